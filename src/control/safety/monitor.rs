//! The supervisor's checks and its output stage, independent of any controller and of the
//! scalar (`f64` on the host, `f32` on a microcontroller): [`SafetyMonitor`].

// `!(x <= limit)` on purpose: a NaN fails the check and trips.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::force_watch::ForceWatch;
use super::limits::SafetyLimits;
use super::period_bounds::{finite, larger, smaller, PeriodBounds};
use super::precision::cast;
use super::reaction::{ModelAt, ReactionState};
use super::sensor_health::SensorHealth;
use super::trip::{Trip, TripCause, TripLog};
use nalgebra::{RealField, SVector, Vector3, Vector6};

/// The robot's state at one period, as the checks see it.
#[derive(Clone, Copy, Debug)]
pub struct Observation<'a, T: RealField + Copy, const N: usize> {
    /// Time, s.
    pub t: T,
    /// Joint positions, rad or m.
    pub q: &'a SVector<T, N>,
    /// Joint velocities, rad/s or m/s.
    pub qd: &'a SVector<T, N>,
    /// Tool position, m, base frame.
    pub position: &'a Vector3<T>,
    /// Tool velocity, m/s, base frame.
    pub velocity: &'a Vector3<T>,
    /// Norm of the desired force, N.
    pub force_ref_n: T,
    /// Whether the controller controls a contact force.
    pub force_controlled: bool,
}

/// The largest value of each checked quantity over a run (how close it came to each limit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peaks<T: RealField + Copy, const N: usize> {
    /// Largest accepted force norm, N.
    pub force_n: T,
    /// Largest tool speed, m/s.
    pub tool_speed_m_s: T,
    /// Largest distance outside the workspace box, m (negative: the closest approach to
    /// its walls from inside).
    pub outside_workspace_m: T,
    /// Per joint, the closest approach to a limit, rad or m (negative: beyond it).
    pub joint_limit_distance: SVector<T, N>,
    /// Per joint, the largest speed.
    pub joint_speed: SVector<T, N>,
    /// Per joint, the largest commanded torque step in one period (before slewing).
    pub torque_step: SVector<T, N>,
}

impl<T: RealField + Copy, const N: usize> Peaks<T, N> {
    /// The same peaks in the scalar `U`.
    #[must_use]
    pub fn cast<U: RealField + Copy>(&self) -> Peaks<U, N> {
        Peaks {
            force_n: cast(self.force_n),
            tool_speed_m_s: cast(self.tool_speed_m_s),
            outside_workspace_m: cast(self.outside_workspace_m),
            joint_limit_distance: self.joint_limit_distance.map(cast),
            joint_speed: self.joint_speed.map(cast),
            torque_step: self.torque_step.map(cast),
        }
    }
}

/// What a run's supervisor saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SafetyReport<const N: usize> {
    /// The limits it checked.
    pub limits: SafetyLimits<f64, N>,
    /// Its trips; the first latched the reaction.
    pub trips: TripLog<f64>,
    /// Periods whose commanded torque was slewed.
    pub rate_limited_samples: u32,
    /// Periods whose torque was non-finite and replaced.
    pub replaced_samples: u32,
    /// Readings the spike filter held back.
    pub spikes_filtered: u32,
    /// How close the run came to each limit.
    pub peaks: Peaks<f64, N>,
    /// Largest force rate, N/s.
    pub peak_force_rate_n_s: f64,
    /// Largest oscillation RMS, N.
    pub peak_oscillation_rms_n: f64,
}

/// The checks of [`SafetyLimits`], the trips they latch, and the output stage (non-finite
/// guard, torque slew). No allocation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SafetyMonitor<T: RealField + Copy, const N: usize> {
    limits: SafetyLimits<T, N>,
    sensor: SensorHealth<T>,
    force: ForceWatch<T>,
    trips: TripLog<T>,
    reaction: Option<ReactionState<T, N>>,
    /// The last output, once `has_prev`.
    prev_tau: SVector<T, N>,
    has_prev: bool,
    bounds: PeriodBounds<T, N>,
    rate_limited: u32,
    replaced: u32,
    peaks: Peaks<T, N>,
}

impl<T: RealField + Copy, const N: usize> SafetyMonitor<T, N> {
    /// A monitor of `limits`, nothing tripped.
    #[must_use]
    pub fn new(limits: SafetyLimits<T, N>) -> Self {
        let big: T = nalgebra::convert(f64::MAX);
        Self {
            limits,
            sensor: SensorHealth::default(),
            force: ForceWatch::default(),
            trips: TripLog::default(),
            reaction: None,
            prev_tau: SVector::zeros(),
            has_prev: false,
            bounds: PeriodBounds::new(&limits, T::zero()),
            rate_limited: 0,
            replaced: 0,
            peaks: Peaks {
                force_n: T::zero(),
                tool_speed_m_s: T::zero(),
                outside_workspace_m: -big,
                joint_limit_distance: SVector::repeat(big),
                joint_speed: SVector::zeros(),
                torque_step: SVector::zeros(),
            },
        }
    }

    /// Back to the start of a run.
    pub fn reset(&mut self) {
        *self = Self::new(self.limits);
    }

    /// The limits.
    #[must_use]
    pub fn limits(&self) -> &SafetyLimits<T, N> {
        &self.limits
    }

    /// The trips so far; the first latched the reaction.
    #[must_use]
    pub fn trips(&self) -> &TripLog<T> {
        &self.trips
    }

    /// Whether a trip is latched.
    #[must_use]
    pub fn tripped(&self) -> bool {
        !self.trips.is_empty()
    }

    /// Periods whose commanded torque the slew limited.
    #[must_use]
    pub fn rate_limited_samples(&self) -> u32 {
        self.rate_limited
    }

    /// Periods whose torque was non-finite and replaced (by gravity compensation, or zero).
    #[must_use]
    pub fn replaced_samples(&self) -> u32 {
        self.replaced
    }

    /// Readings the spike filter held back.
    #[must_use]
    pub fn spikes_filtered(&self) -> u32 {
        self.sensor.spikes()
    }

    /// The peaks of the run so far.
    #[must_use]
    pub fn peaks(&self) -> Peaks<T, N> {
        let mut p = self.peaks;
        p.force_n = p.force_n.max(T::zero());
        p.tool_speed_m_s = p.tool_speed_m_s.sqrt();
        p
    }

    /// Largest force rate seen, N/s, and largest oscillation RMS, N.
    #[must_use]
    pub fn force_peaks(&self) -> (T, T) {
        (self.force.peak_rate(), self.force.peak_rms())
    }

    /// What it saw so far, widened to `f64`.
    #[must_use]
    pub fn report(&self) -> SafetyReport<N> {
        let (rate, rms) = self.force_peaks();
        SafetyReport {
            limits: self.limits.cast(),
            trips: self.trips.cast(),
            rate_limited_samples: self.rate_limited,
            replaced_samples: self.replaced,
            spikes_filtered: self.spikes_filtered(),
            peaks: self.peaks().cast(),
            peak_force_rate_n_s: cast(rate),
            peak_oscillation_rms_n: cast(rms),
        }
    }

    /// The per-period bounds for the period `dt` (s), recomputed only when it changes.
    #[inline(always)]
    fn refresh_bounds(&mut self, dt: T) {
        if !(dt == self.bounds.dt) {
            self.bounds = PeriodBounds::new(&self.limits, dt);
        }
    }

    /// Records `trip` (each cause once).
    #[cold]
    #[inline(never)]
    pub fn record(&mut self, trip: Trip<T>) {
        self.trips.record(trip);
    }

    /// Checks a sensor reading `age_s` seconds old: the reading the controller may use (the
    /// last accepted one if this one is bad or held by the spike filter).
    #[inline(always)]
    pub fn sensor(&mut self, t: T, reading: &Vector6<T>, age_s: T, dt: T) -> Vector6<T> {
        if let Some(trip) = self
            .sensor
            .judge(&self.limits.sensor, t, reading, age_s, dt)
        {
            self.record(trip);
        }
        self.sensor.accepted()
    }

    /// The state checks at one period, with the contact wrench as the law read it (`wrench`,
    /// the accepted reading with a tool's weight and bias taken out): force, its rate,
    /// oscillation and loss, tool speed and workspace, joint limits and speeds.
    // Joint `i` of several vectors at once: indexed loops.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub fn state(&mut self, x: &Observation<'_, T, N>, wrench: &Vector6<T>, dt: T) {
        let f = wrench.fixed_rows::<3>(0).norm();
        self.peaks.force_n = larger(self.peaks.force_n, f);
        if f > self.limits.force.max_n {
            self.record(Trip {
                cause: TripCause::Force,
                t: x.t,
                value: f,
                limit: self.limits.force.max_n,
            });
        }
        let controlled = x.force_controlled && self.trips.is_empty();
        if let Err(t) = self
            .force
            .step(&self.limits.force, x.t, f, x.force_ref_n, controlled, dt)
        {
            self.record(t);
        }
        self.refresh_bounds(dt);
        // One pass that only reads: every value inside its bounds (a NaN fails a comparison)
        // updates the peaks; anything else goes through the checks that name the trip.
        let b = &self.bounds;
        let speed2 = x.velocity.norm_squared();
        let mut inside = speed2 <= b.tool_speed2;
        let mut outside = -T::one() / T::zero();
        for k in 0..3 {
            let p = x.position[k];
            outside = larger(
                outside,
                larger(b.workspace_lo[k] - p, p - b.workspace_hi[k]),
            );
            inside &= finite(p);
        }
        inside &= outside <= T::zero();
        let mut distance = [T::zero(); N];
        for i in 0..N {
            let d = smaller(
                x.q[i] - self.limits.joint_lower[i],
                self.limits.joint_upper[i] - x.q[i],
            );
            distance[i] = d;
            inside &= (d >= b.joint_margin[i]) & (x.qd[i].abs() <= b.joint_speed[i]);
        }
        if !inside {
            self.kinematic_checks(x);
            return;
        }
        let peaks = &mut self.peaks;
        peaks.tool_speed_m_s = larger(peaks.tool_speed_m_s, speed2);
        if self.limits.workspace.is_some() {
            peaks.outside_workspace_m = larger(peaks.outside_workspace_m, outside);
        }
        // One pass per quantity (the compiler may run two or four joints at once).
        for i in 0..N {
            let p = &mut peaks.joint_limit_distance[i];
            *p = smaller(*p, distance[i]);
        }
        for i in 0..N {
            let p = &mut peaks.joint_speed[i];
            *p = larger(*p, x.qd[i].abs());
        }
    }

    /// The tool's speed and box, the joints' limits and speeds, each trip named with its
    /// value, and their peaks (the path of a period where something is outside its bounds).
    #[cold]
    #[inline(never)]
    fn kinematic_checks(&mut self, x: &Observation<'_, T, N>) {
        // Disjoint borrows: the limits are read in place, not copied.
        let Self {
            limits: l,
            trips,
            peaks,
            ..
        } = self;
        let trip = |cause, value, limit| Trip {
            cause,
            t: x.t,
            value,
            limit,
        };
        // Squared, as the peak is kept until read.
        let speed2 = x.velocity.norm_squared();
        peaks.tool_speed_m_s = peaks.tool_speed_m_s.max(speed2);
        if let Some(max) = l.max_tool_speed_m_s {
            if !(speed2 <= max * max) {
                trips.record(trip(TripCause::ToolSpeed, speed2.sqrt(), max));
            }
        }
        if let Some((lo, hi)) = l.workspace {
            let outside = (lo - x.position).max().max((x.position - hi).max());
            peaks.outside_workspace_m = peaks.outside_workspace_m.max(outside);
            if !(outside <= T::zero()) {
                trips.record(trip(TripCause::Workspace, outside, T::zero()));
            }
        }
        for i in 0..N {
            let d = (x.q[i] - l.joint_lower[i]).min(l.joint_upper[i] - x.q[i]);
            let p = &mut peaks.joint_limit_distance[i];
            *p = p.min(d);
            if let Some(margin) = l.joint_margin {
                if !(d >= margin[i]) {
                    trips.record(trip(TripCause::JointLimit(i as u8), d, margin[i]));
                }
            }
            let v = x.qd[i].abs();
            let p = &mut peaks.joint_speed[i];
            *p = p.max(v);
            if let Some(max) = l.max_joint_speed {
                if !(v <= max[i]) {
                    trips.record(trip(TripCause::JointSpeed(i as u8), v, max[i]));
                }
            }
        }
    }

    /// Trips if the controller's torque `tau` at time `t` is not finite; whether it is.
    #[inline(always)]
    pub fn torque(&mut self, t: T, tau: &SVector<T, N>) -> bool {
        if all_finite(tau) {
            return true;
        }
        if let Some(i) = tau.iter().position(|x| !x.is_finite()) {
            self.record(Trip {
                cause: TripCause::TorqueNonFinite(i as u8),
                t,
                value: tau[i],
                limit: T::zero(),
            });
        }
        false
    }

    /// The latched reaction's torque at `(q, qd)` (`None` if nothing tripped); the reaction
    /// starts at the tool's position `position`, retreating along `away`.
    pub fn reaction_torque(
        &mut self,
        t: T,
        dt: T,
        q: &SVector<T, N>,
        qd: &SVector<T, N>,
        away: &Vector3<T>,
        model: &ModelAt<'_, T, N>,
    ) -> Option<SVector<T, N>> {
        let first = self.trips.first()?;
        let state = self
            .reaction
            .get_or_insert_with(|| ReactionState::new(first.t, *q, *model.position, *away));
        let limits = (&self.limits.joint_lower, &self.limits.joint_upper);
        Some(state.torque(&self.limits.reaction, t, dt, q, qd, model, limits))
    }

    /// The output stage: a non-finite `tau` is replaced by `fallback` (gravity compensation),
    /// or zero if that is not finite either; then a step of the applied torque (the command
    /// clamped to the actuators' limits) larger than the torque rate limit allows in one
    /// period is slewed to it.
    #[inline(always)]
    pub fn output(
        &mut self,
        tau: &SVector<T, N>,
        fallback: impl FnOnce() -> SVector<T, N>,
        dt: T,
    ) -> SVector<T, N> {
        let mut out = *tau;
        if !all_finite(&out) {
            self.replaced += 1;
            let fallback = fallback();
            out = if all_finite(&fallback) {
                fallback
            } else {
                SVector::zeros()
            };
        }
        self.slew(out, dt)
    }

    /// [`output`](Self::output) of a torque [`torque`](Self::torque) found finite (the
    /// check is not repeated).
    #[inline(always)]
    pub fn output_of_finite(&mut self, tau: &SVector<T, N>, dt: T) -> SVector<T, N> {
        debug_assert!(all_finite(tau));
        self.slew(*tau, dt)
    }

    /// The torque-rate stage of [`output`](Self::output) on a finite `out`: per joint,
    /// `from = clamp(prev, e)`, `to = clamp(out, e)`; if `|to - from| > rate dt` the output
    /// is `from + clamp(to - from, rate dt)`, else `out` unchanged.
    #[inline(always)]
    fn slew(&mut self, mut out: SVector<T, N>, dt: T) -> SVector<T, N> {
        self.refresh_bounds(dt);
        if self.has_prev {
            // Branch-free per joint, each quantity one pass over the joints (the compiler
            // may run two or four joints at once).
            let (e, max) = (&self.limits.effort, &self.bounds.torque_step);
            let mut change = [T::zero(); N];
            let mut from = [T::zero(); N];
            for i in 0..N {
                from[i] = clamped(self.prev_tau[i], e[i]);
                change[i] = clamped(out[i], e[i]) - from[i];
            }
            let mut limited = 0u32;
            for i in 0..N {
                let step = change[i].abs();
                let p = &mut self.peaks.torque_step[i];
                *p = larger(*p, step);
                // `+inf` when the rate is not limited: never slewed.
                let slew = step > max[i];
                let slewed = from[i] + clamped(change[i], max[i]);
                out[i] = if slew { slewed } else { out[i] };
                limited |= u32::from(slew);
            }
            self.rate_limited += limited;
        }
        self.has_prev = true;
        self.prev_tau = out;
        out
    }
}

/// `x` clamped to `[-e, e]` for `e >= 0` (`f64::clamp` without its check that `-e <= e`;
/// a NaN stays).
#[inline(always)]
fn clamped<T: RealField + Copy>(x: T, e: T) -> T {
    smaller(larger(x, -e), e)
}

/// Whether every component of `v` is finite, without an early exit.
#[inline(always)]
fn all_finite<T: RealField + Copy, const N: usize>(v: &SVector<T, N>) -> bool {
    v.iter().fold(true, |ok, &x| ok & finite(x))
}
