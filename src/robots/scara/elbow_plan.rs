//! Elbow planning for a whole reference (thesis Section 4.4): which configuration to run in,
//! and where to switch when neither works throughout (see [`workspace`](super::workspace) for
//! the zones each sample falls in).
//!
//! If one configuration works for every sample, it is kept for the whole run: elbow up when
//! both do (the thesis's choice, Section 4.4), otherwise the one that does. Otherwise the run
//! starts in the configuration that works longest from the start and switches only when it
//! must: each [`ElbowSwitch`] says when, and the window of samples over which the switch could
//! be made; [`SwitchPolicy`] picks the time within the window. Every policy gives the fewest
//! switches.

use core::cmp::Ordering;

use nalgebra::Vector3;

use super::geometry::{Elbow, ScaraGeometry};
use super::workspace::{Reachability, Reason};
use crate::model::JointVector;
use crate::target::PoseSample;
use crate::trajectory::{sample, CartesianTrajectory};

/// How many unreachable samples a [`WorkspaceError::Unreachable`] lists.
pub const MAX_REPORTED: usize = 5;

/// Where within its window an elbow switch is placed (see the [module
/// documentation](self)).
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::SwitchPolicy;
/// assert_eq!(SwitchPolicy::default(), SwitchPolicy::Latest);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SwitchPolicy {
    /// At the first sample where the current configuration is no longer feasible.
    #[default]
    Latest,
    /// At the first sample of the window where the new configuration is feasible through to
    /// the end of the current one's (the thesis's code: it switches on entering the zone
    /// both configurations reach).
    Earliest,
    /// At the sample of the window where the two solutions are closest: the smallest
    /// largest-joint jump `max(|dq1|, |dq2|, |dq4|)` (rad; `d3` is the same for both).
    SmallestJump,
}

/// One change of elbow configuration during a run.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, ScaraGeometry, SwitchPolicy};
/// use armdyn::robots::scara::thesis::ThreeZone;
///
/// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
/// let plan = ik.plan_trajectory(&ThreeZone::new(), 0.005, SwitchPolicy::Latest).unwrap();
/// let switch = &plan.switches()[0];
/// assert_eq!(switch.to, Elbow::Up);
/// assert!(switch.earliest < switch.t && switch.t == switch.latest);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElbowSwitch {
    /// Time of the switch, s: the new configuration is used from this sample on.
    pub t: f64,
    /// Index of that sample in the planned samples.
    pub index: usize,
    /// The configuration switched to.
    pub to: Elbow,
    /// Earliest time at which this switch could be made (s): from then on the new
    /// configuration is feasible through to `latest`.
    pub earliest: f64,
    /// Latest time at which the switch can be made (s): the first sample where the previous
    /// configuration is not feasible.
    pub latest: f64,
    /// Joint-space jump of the reference at the switch, `max(|dq1|, |dq2|, |dq4|)`, rad.
    pub jump: f64,
}

/// The elbow configuration to use over a run: one throughout, or a start and a list of
/// switches.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, ScaraGeometry};
/// use armdyn::trajectory::sample;
/// use armdyn::robots::scara::thesis::PositionTest;
///
/// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
/// let plan = ik.plan_elbows(&sample(&PositionTest::new(), 0.005)).unwrap();
/// assert_eq!(plan.single(), Some(Elbow::Up)); // both work throughout: elbow up
/// assert_eq!(plan.elbow_at(7.0), Elbow::Up);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ElbowPlan {
    initial: Elbow,
    switches: Vec<ElbowSwitch>,
}

impl ElbowPlan {
    /// One configuration for the whole run.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ElbowPlan};
    /// assert_eq!(ElbowPlan::single_elbow(Elbow::Down).elbow_at(3.0), Elbow::Down);
    /// ```
    pub fn single_elbow(elbow: Elbow) -> Self {
        ElbowPlan {
            initial: elbow,
            switches: Vec::new(),
        }
    }

    /// A plan that starts with `initial` and switches to each `(t, elbow)` at time `t` (s,
    /// increasing): the plan of a reference whose switches were placed by other means (a
    /// planned flip, [`crate::robots::scara::elbow_flip`]). Window and jump are set to the
    /// switch itself.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ElbowPlan};
    /// let p = ElbowPlan::from_switch_times(Elbow::Down, &[(6.0, Elbow::Up)]);
    /// assert_eq!((p.elbow_at(5.9), p.elbow_at(6.0)), (Elbow::Down, Elbow::Up));
    /// ```
    pub fn from_switch_times(initial: Elbow, switches: &[(f64, Elbow)]) -> Self {
        ElbowPlan {
            initial,
            switches: switches
                .iter()
                .enumerate()
                .map(|(index, &(t, to))| ElbowSwitch {
                    t,
                    index,
                    to,
                    earliest: t,
                    latest: t,
                    jump: 0.0,
                })
                .collect(),
        }
    }

    /// The configuration at the start of the run.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ElbowPlan};
    /// assert_eq!(ElbowPlan::single_elbow(Elbow::Up).initial(), Elbow::Up);
    /// ```
    pub fn initial(&self) -> Elbow {
        self.initial
    }

    /// The switches, in time order (empty when one configuration serves the whole run).
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ElbowPlan};
    /// assert!(ElbowPlan::single_elbow(Elbow::Up).switches().is_empty());
    /// ```
    pub fn switches(&self) -> &[ElbowSwitch] {
        &self.switches
    }

    /// `Some(elbow)` if one configuration serves the whole run.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ElbowPlan};
    /// assert_eq!(ElbowPlan::single_elbow(Elbow::Up).single(), Some(Elbow::Up));
    /// ```
    pub fn single(&self) -> Option<Elbow> {
        self.switches.is_empty().then_some(self.initial)
    }

    /// The configuration to use at time `t` (s): the one switched to by the last switch at
    /// or before `t`, or the initial one.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ScaraGeometry, SwitchPolicy};
    /// use armdyn::robots::scara::thesis::ThreeZone;
    ///
    /// let ik = ScaraGeometry::thesis();
    /// let plan = ik.plan_trajectory(&ThreeZone::new(), 0.005, SwitchPolicy::Latest).unwrap();
    /// assert_eq!(plan.elbow_at(0.0), Elbow::Down);
    /// assert_eq!(plan.elbow_at(10.0), Elbow::Up);
    /// ```
    pub fn elbow_at(&self, t: f64) -> Elbow {
        self.switches
            .iter()
            .take_while(|s| s.t <= t)
            .last()
            .map_or(self.initial, |s| s.to)
    }
}

/// An unreachable sample of a reference.
///
/// ```
/// use armdyn::robots::scara::{ScaraGeometry, WorkspaceError};
/// use armdyn::target::PoseSample;
/// use nalgebra::Vector3;
///
/// let samples = [PoseSample::with_yaw(0.0, Vector3::new(0.9, 0.0, 0.1), 0.0),
///                PoseSample::with_yaw(1.0, Vector3::new(0.5, 0.0, 0.1), 0.0)];
/// let Err(WorkspaceError::Unreachable { first, .. }) = ScaraGeometry::thesis().plan_elbows(&samples)
/// else { panic!() };
/// assert_eq!(first.0[0].t, 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnreachableSample {
    /// Index of the sample.
    pub index: usize,
    /// Its time, s.
    pub t: f64,
    /// Its position, m.
    pub position: Vector3<f64>,
    /// Why neither configuration reaches it.
    pub reason: Reason,
}

/// The first few unreachable samples of a reference (at most [`MAX_REPORTED`]); displayed one
/// per line.
///
/// ```
/// use armdyn::robots::scara::UnreachableSamples;
/// assert_eq!(UnreachableSamples(Vec::new()).to_string(), "");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct UnreachableSamples(pub Vec<UnreachableSample>);

impl core::fmt::Display for UnreachableSamples {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        for s in &self.0 {
            write!(
                f,
                "\n  sample {} at t = {} s, position ({}, {}, {}) m: {}",
                s.index, s.t, s.position.x, s.position.y, s.position.z, s.reason
            )?;
        }
        Ok(())
    }
}

/// Why no elbow plan exists for a reference.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{ScaraGeometry, WorkspaceError};
/// assert_eq!(ScaraGeometry::thesis().plan_elbows(&[]), Err(WorkspaceError::NoSamples));
/// ```
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum WorkspaceError {
    /// The reference has no samples.
    #[error("the reference has no samples")]
    NoSamples,
    /// The sample times do not increase strictly.
    #[error("sample {index}: time {t} s is not after the previous sample's {previous} s")]
    NotIncreasing {
        /// Index of the sample.
        index: usize,
        /// Its time, s.
        t: f64,
        /// The previous sample's time, s.
        previous: f64,
    },
    /// Some samples are reachable by neither configuration.
    #[error("{count} of {total} reference samples are outside the workspace (first {}):{first}", first.0.len())]
    Unreachable {
        /// Number of unreachable samples.
        count: usize,
        /// Number of samples.
        total: usize,
        /// The first [`MAX_REPORTED`] of them.
        first: UnreachableSamples,
    },
}

impl ScaraGeometry {
    /// Plans the elbow configuration over a sampled reference with the default
    /// [`SwitchPolicy::Latest`] (see [`ScaraGeometry::plan_elbows_with`]).
    ///
    /// # Errors
    ///
    /// As [`ScaraGeometry::plan_elbows_with`].
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ScaraGeometry};
    /// use armdyn::trajectory::sample;
    /// use armdyn::robots::scara::thesis::ThreeZone;
    ///
    /// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
    /// let plan = ik.plan_elbows(&sample(&ThreeZone::new(), 0.005)).unwrap();
    /// assert_eq!((plan.initial(), plan.switches().len()), (Elbow::Down, 1));
    /// ```
    pub fn plan_elbows(&self, samples: &[PoseSample]) -> Result<ElbowPlan, WorkspaceError> {
        self.plan_elbows_with(samples, SwitchPolicy::Latest)
    }

    /// Plans the elbow configuration over a sampled reference (times in s, strictly
    /// increasing; positions in m; yaw in rad): one configuration for the whole run when one
    /// works for every sample (elbow up if both do), otherwise the fewest switches, placed
    /// within their windows by `policy` (see the [module documentation](self)).
    ///
    /// # Errors
    ///
    /// [`WorkspaceError::NoSamples`] for an empty slice, [`WorkspaceError::NotIncreasing`]
    /// for times out of order, [`WorkspaceError::Unreachable`] if any sample is reachable by
    /// neither configuration (with the count and the first [`MAX_REPORTED`] such samples:
    /// time, position and reason).
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{ScaraGeometry, SwitchPolicy};
    /// use armdyn::trajectory::sample;
    /// use armdyn::robots::scara::thesis::ThreeZone;
    ///
    /// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
    /// let samples = sample(&ThreeZone::new(), 0.005);
    /// let late = ik.plan_elbows_with(&samples, SwitchPolicy::Latest).unwrap();
    /// let early = ik.plan_elbows_with(&samples, SwitchPolicy::Earliest).unwrap();
    /// let gentle = ik.plan_elbows_with(&samples, SwitchPolicy::SmallestJump).unwrap();
    /// assert!(early.switches()[0].t < late.switches()[0].t);
    /// assert!(gentle.switches()[0].jump <= late.switches()[0].jump);
    /// ```
    pub fn plan_elbows_with(
        &self,
        samples: &[PoseSample],
        policy: SwitchPolicy,
    ) -> Result<ElbowPlan, WorkspaceError> {
        if samples.is_empty() {
            return Err(WorkspaceError::NoSamples);
        }
        let increasing =
            |i: usize| samples[i].t.partial_cmp(&samples[i - 1].t) == Some(Ordering::Greater);
        if let Some(index) = (1..samples.len()).find(|&i| !increasing(i)) {
            return Err(WorkspaceError::NotIncreasing {
                index,
                t: samples[index].t,
                previous: samples[index - 1].t,
            });
        }

        let classes: Vec<Reachability> = samples
            .iter()
            .map(|s| self.classify(&s.position, s.yaw()))
            .collect();
        let unreachable: Vec<UnreachableSample> = classes
            .iter()
            .enumerate()
            .filter_map(|(index, class)| match class {
                Reachability::Unreachable(reason) => Some(UnreachableSample {
                    index,
                    t: samples[index].t,
                    position: samples[index].position,
                    reason: *reason,
                }),
                _ => None,
            })
            .collect();
        if !unreachable.is_empty() {
            return Err(WorkspaceError::Unreachable {
                count: unreachable.len(),
                total: samples.len(),
                first: UnreachableSamples(unreachable.into_iter().take(MAX_REPORTED).collect()),
            });
        }

        let n = samples.len();
        let feasible = |i: usize, elbow: Elbow| classes[i].allows(elbow);
        // First index at or after `from` where `elbow` is not feasible (n if none).
        let run_end =
            |elbow: Elbow, from: usize| (from..n).find(|&i| !feasible(i, elbow)).unwrap_or(n);

        if run_end(Elbow::Up, 0) == n {
            return Ok(ElbowPlan::single_elbow(Elbow::Up));
        }
        if run_end(Elbow::Down, 0) == n {
            return Ok(ElbowPlan::single_elbow(Elbow::Down));
        }
        // Start with the configuration that lasts longer (every sample is reachable, so at
        // least one is feasible at 0, and they cannot end at the same sample).
        let initial = if run_end(Elbow::Up, 0) >= run_end(Elbow::Down, 0) {
            Elbow::Up
        } else {
            Elbow::Down
        };
        let mut switches = Vec::new();
        let (mut current, mut from) = (initial, 0);
        loop {
            let latest = run_end(current, from);
            if latest == n {
                break;
            }
            let next = current.other();
            // `next` is feasible at `latest` (the sample is reachable); go back while it
            // stays feasible. It was not feasible where `current` started (or it would have
            // run longer), so the window stays after `from`.
            let mut earliest = latest;
            while earliest > from + 1 && feasible(earliest - 1, next) {
                earliest -= 1;
            }
            let jump_at = |i: usize| self.switch_jump(&samples[i], current);
            let index = match policy {
                SwitchPolicy::Latest => latest,
                SwitchPolicy::Earliest => earliest,
                SwitchPolicy::SmallestJump => (earliest..=latest)
                    .min_by(|&a, &b| jump_at(a).total_cmp(&jump_at(b)))
                    .unwrap_or(latest),
            };
            switches.push(ElbowSwitch {
                t: samples[index].t,
                index,
                to: next,
                earliest: samples[earliest].t,
                latest: samples[latest].t,
                jump: jump_at(index),
            });
            current = next;
            from = index;
        }
        Ok(ElbowPlan { initial, switches })
    }

    /// Samples `reference` every `dt` seconds ([`sample`]) and
    /// plans its elbows ([`ScaraGeometry::plan_elbows_with`]).
    ///
    /// # Errors
    ///
    /// As [`ScaraGeometry::plan_elbows_with`].
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{ScaraGeometry, SwitchPolicy};
    /// use armdyn::robots::scara::thesis::ContactTest;
    ///
    /// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
    /// let plan = ik.plan_trajectory(&ContactTest::thesis(), 0.005, SwitchPolicy::Latest).unwrap();
    /// assert!(plan.single().is_some());
    /// ```
    pub fn plan_trajectory<R: CartesianTrajectory + ?Sized>(
        &self,
        reference: &R,
        dt: f64,
        policy: SwitchPolicy,
    ) -> Result<ElbowPlan, WorkspaceError> {
        self.plan_elbows_with(&sample(reference, dt), policy)
    }

    /// `max(|dq1|, |dq2|, |dq4|)` between the two solutions at a reachable sample (rad).
    fn switch_jump(&self, s: &PoseSample, from: Elbow) -> f64 {
        let solve = |elbow| self.inverse(&s.position, s.yaw(), elbow).ok();
        match (solve(from), solve(from.other())) {
            (Some(a), Some(b)) => {
                let d: JointVector<4> = a - b;
                libm::fmax(
                    libm::fmax(libm::fabs(d[0]), libm::fabs(d[1])),
                    libm::fabs(d[3]),
                )
            }
            _ => f64::NAN,
        }
    }
}
