//! The default way a scenario turns a Cartesian reference into joint setpoints: the
//! numerical inverse kinematics ([`NumericalIk`]) at every control sample, warm-started from
//! the previous sample's joints, with the joint rates of [`joint_rates`].
//!
//! Before the run the whole reference is solved at `min(5 ms, control period)` from the
//! first point (solved from the seed, with restarts) onward, each sample from the previous
//! one without restarts, so a reference that leaves the workspace, passes a joint limit or
//! jumps between solution branches is refused with its time and the remaining error. During
//! the run a sample whose solve fails (which the check makes unexpected) holds the previous
//! target and is counted.
//!
//! A redundant arm's joints are planned once, before the run: each planning sample is
//! predicted from the previous one by the task's joint rates plus a pull towards the
//! posture in the task's null space (rate [`POSTURE_RATE`]), then corrected onto the task by
//! Gauss-Newton steps; the run follows the natural cubic spline through them, so the
//! joints' position, velocity and acceleration agree (a joint-space law's feedforward needs
//! that), and the tool stays on the reference to the spline's error between samples.

use nalgebra::Vector3;
use serde_json::json;

use super::error::ScenarioError;
use super::planned::{PlannedReference, ReferenceReport, SharedTrajectory};
use super::spec::Scenario;
use crate::kinematics::{joint_rates, null_space_step, IkOptions, InverseKinematics, NumericalIk};
use crate::model::{JointVector, RobotModel, Wrench};
use crate::sim::{ReferenceSource, Sample, Setpoint};
use crate::target::{CartesianTarget, JointTarget};
use crate::trajectory::{sample, CartesianTrajectory, JointReference};

/// Largest joint step between two planning samples, rad or m: more means the solution
/// jumped to another branch (or passed a singularity) rather than followed the path.
pub const MAX_JOINT_STEP: f64 = 0.25;

/// Posture moves per control sample while tracking (the warm start is already near the
/// posture-optimal solution of the previous sample).
const TRACKING_POSTURE_MOVES: usize = 3;

/// The numerical plan of a reference (see the [module documentation](self)).
pub struct IkPlan<const N: usize, R> {
    robot: R,
    trajectory: SharedTrajectory,
    /// The solver with restarts, for the first point and the contact pose.
    full: NumericalIk<N, R>,
    /// The solver of the samples, warm-started, without restarts.
    tracking: NumericalIk<N, R>,
    start: JointVector<N>,
    /// The previous sample's time and joints.
    last: Option<(f64, JointVector<N>, JointVector<N>)>,
    posture: Option<JointVector<N>>,
    /// A redundant arm's joint reference: the planned solutions, interpolated.
    spline: Option<JointReference<N>>,
    singular_samples: usize,
    failed_samples: usize,
    max_iterations: usize,
}

/// Rate at which a redundant arm's planned joints are drawn towards the posture in the
/// task's null space, 1/s (a time constant of 20 ms).
pub const POSTURE_RATE: f64 = 50.0;

/// The options of a scenario's inverse kinematics, and its posture.
fn options<const N: usize>(scenario: &Scenario) -> (IkOptions<N>, Option<JointVector<N>>) {
    let ik = &scenario.ik;
    let vector = |v: &Option<Vec<f64>>| v.as_ref().map(|v| JointVector::<N>::from_fn(|i, _| v[i]));
    let posture = vector(&ik.posture);
    (
        IkOptions {
            tolerance_m: ik.tolerance_m,
            tolerance_rad: ik.tolerance_rad,
            max_iterations: ik.max_iterations,
            posture,
            posture_weights: vector(&ik.posture_weights),
            ..IkOptions::default()
        },
        posture,
    )
}

/// The seed of the first point's solve: `[reference] seed`, else the posture, else `q0`
/// (when the run starts there), else the middle of the limits.
fn seed<const N: usize, R: RobotModel<N>>(
    scenario: &Scenario,
    ik: &NumericalIk<N, R>,
) -> JointVector<N> {
    let vector = |v: &Vec<f64>| JointVector::<N>::from_fn(|i, _| v[i]);
    if let Some(s) = &scenario.ik.seed {
        return vector(s);
    }
    if scenario.ik.posture.is_some() {
        return *ik.posture();
    }
    match (&scenario.q0, scenario.start_on_reference) {
        (Some(q0), false) => vector(q0),
        _ => *ik.posture(),
    }
}

/// Plans `trajectory` for `robot` with `scenario`'s inverse-kinematics settings.
///
/// # Errors
///
/// [`ScenarioError`] on `reference` naming the time (and position) where the reference
/// leaves what the robot reaches within its limits, or jumps.
pub fn plan<const N: usize, R: RobotModel<N> + Copy + 'static>(
    robot: R,
    scenario: &Scenario,
    trajectory: SharedTrajectory,
) -> Result<Box<dyn PlannedReference<N>>, ScenarioError> {
    let (full_options, posture) = options::<N>(scenario);
    let full = NumericalIk::new(robot, full_options);
    let tracking = NumericalIk::new(
        robot,
        IkOptions {
            restarts: 0,
            posture_moves: TRACKING_POSTURE_MOVES,
            ..full_options
        },
    );
    let first = trajectory.at(0.0);
    let start = full
        .solve(&first, &seed(scenario, &full))
        .map_err(|e| {
            scenario.error(
                "reference",
                format!(
                    "the reference's first point ({:.4}, {:.4}, {:.4}) m has no solution: {e}",
                    first.position.x, first.position.y, first.position.z
                ),
            )
        })?
        .q;
    // The whole reference, as the run will follow it.
    let dt = 0.005_f64.min(scenario.control_dt_s);
    let duration = scenario.duration_s.unwrap_or_else(|| trajectory.duration());
    let redundant = R::TASK.redundancy(N) > 0;
    // A redundant arm: each sample predicted from the previous one by the task's rates and
    // a pull towards the posture in the null space, then corrected onto the task by
    // Gauss-Newton steps: a smooth joint path, interpolated for the run.
    let corrector = NumericalIk::new(
        robot,
        IkOptions {
            restarts: 0,
            posture_moves: 0,
            ..full_options
        },
    );
    let weights = full_options
        .posture_weights
        .map_or(JointVector::<N>::repeat(1.0), |w| w / w.amax());
    // A redundant arm starts where the planner's own pull towards the posture is at rest:
    // the first point's solution carried along the null space to the posture's nearest
    // point (by the same predictor-corrector steps, at t = 0), so the joints do not jump
    // at the start and an arm started on the reference is already where the plan begins.
    let start = if redundant {
        settle_on_first_point(
            &robot,
            &corrector,
            &first,
            start,
            &weights,
            *full.posture(),
            dt,
        )
    } else {
        start
    };
    let mut q = start;
    let mut previous_t = 0.0;
    let mut knots: (Vec<f64>, Vec<JointVector<N>>) = (Vec::new(), Vec::new());
    let mut max_iterations = 0;
    for s in sample(trajectory.as_ref(), dt)
        .into_iter()
        .filter(|s| s.t <= duration)
    {
        let target = CartesianTarget::at_rest(s.position, s.orientation);
        let p = s.position;
        let solver = if redundant { &corrector } else { &tracking };
        let guess = if redundant && s.t > 0.0 {
            let h = s.t - previous_t;
            let rates = joint_rates(&robot, &q, &trajectory.at(s.t));
            let pull = null_space_step(&robot, &q, &(*full.posture() - q), &weights);
            q + (rates.qd + pull * POSTURE_RATE) * h
        } else {
            q
        };
        let solution = solver.solve(&target, &guess).map_err(|e| {
            scenario.error(
                "reference",
                format!(
                    "the reference leaves the workspace at t = {:.3} s ({:.4}, {:.4}, {:.4}) m: {e}",
                    s.t, p.x, p.y, p.z
                ),
            )
        })?;
        let step = (solution.q - q).amax();
        if step > MAX_JOINT_STEP {
            return Err(scenario.error(
                "reference",
                format!(
                    "the inverse kinematics jumps by {step:.3} rad (or m) between two samples at t = {:.3} s ({:.4}, {:.4}, {:.4}) m: the reference passes a singularity or needs another solution branch",
                    s.t, p.x, p.y, p.z
                ),
            ));
        }
        max_iterations = max_iterations.max(solution.iterations);
        q = solution.q;
        previous_t = s.t;
        knots.0.push(s.t);
        knots.1.push(q);
    }
    let spline = if redundant {
        Some(
            JointReference::new(knots.0, knots.1)
                .map_err(|e| scenario.error("reference", format!("the planned joint path: {e}")))?,
        )
    } else {
        None
    };
    Ok(Box::new(IkPlan {
        robot,
        trajectory,
        full,
        tracking,
        start,
        last: None,
        posture,
        spline,
        singular_samples: 0,
        failed_samples: 0,
        max_iterations,
    }))
}

/// Steps of the null-space flow at the first point at most, and the joint step below which
/// it is at rest, rad or m.
const SETTLE_STEPS: usize = 10_000;
const SETTLED: f64 = 1e-12;

/// `q` on the first point `first` carried by the planner's predictor-corrector (a pull
/// towards `posture` in the null space at [`POSTURE_RATE`], then back onto the task) until a
/// step moves it by less than [`SETTLED`]: the joints at which the plan's pull vanishes.
fn settle_on_first_point<const N: usize, R: RobotModel<N>>(
    robot: &R,
    corrector: &NumericalIk<N, R>,
    first: &CartesianTarget,
    mut q: JointVector<N>,
    weights: &JointVector<N>,
    posture: JointVector<N>,
    h: f64,
) -> JointVector<N> {
    let target = CartesianTarget::at_rest(first.position, first.orientation);
    for _ in 0..SETTLE_STEPS {
        let pull = null_space_step(robot, &q, &(posture - q), weights);
        let Ok(next) = corrector.solve(&target, &(q + pull * (POSTURE_RATE * h))) else {
            break;
        };
        let moved = (next.q - q).amax();
        q = next.q;
        if moved < SETTLED {
            break;
        }
    }
    q
}

impl<const N: usize, R: RobotModel<N>> ReferenceSource<N> for IkPlan<N, R> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        let cartesian = self.trajectory.at(t);
        if let Some(spline) = &self.spline {
            return Setpoint {
                joint: spline.at(t),
                cartesian,
                wrench: Wrench::zeros(),
            };
        }
        let seed = self.last.map_or(self.start, |(_, q, _)| q);
        let q = match self.tracking.solve(&cartesian, &seed) {
            Ok(s) => s.q,
            Err(_) => {
                self.failed_samples += 1;
                seed
            }
        };
        let rates = joint_rates(&self.robot, &q, &cartesian);
        if rates.damping > 0.0 {
            self.singular_samples += 1;
        }
        let (qd, qdd) = (rates.qd, rates.qdd);
        self.last = Some((t, q, JointVector::zeros()));
        Setpoint {
            joint: JointTarget { q, qd, qdd },
            cartesian,
            wrench: Wrench::zeros(),
        }
    }
}

impl<const N: usize, R: RobotModel<N>> PlannedReference<N> for IkPlan<N, R> {
    fn trajectory(&self) -> &dyn CartesianTrajectory {
        self.trajectory.as_ref()
    }

    fn start(&self) -> JointVector<N> {
        self.start
    }

    fn joints_at(&self, t: f64, position: &Vector3<f64>) -> Result<JointVector<N>, String> {
        let mut target = self.trajectory.at(t);
        target.position = *position;
        self.full
            .solve(&target, &self.start)
            .map(|s| s.q)
            .map_err(|e| e.to_string())
    }

    fn report(&self, samples: &[Sample<N>], _effort_limits: &JointVector<N>) -> ReferenceReport {
        let o = self.full.options();
        let mut metrics = serde_json::Map::new();
        metrics.insert(
            "inverse_kinematics".into(),
            json!({
                "solver": "numerical (Levenberg-Marquardt, warm-started at every sample)",
                "tolerance_m": o.tolerance_m,
                "tolerance_rad": o.tolerance_rad,
                "max_iterations": o.max_iterations,
                "most_iterations_of_a_planning_sample": self.max_iterations,
                "failed_samples": self.failed_samples,
            }),
        );
        if let Some(posture) = &self.posture {
            let deviation: Vec<f64> = (0..N)
                .map(|i| {
                    samples
                        .iter()
                        .map(|s| (s.q[i] - posture[i]).abs())
                        .fold(0.0, f64::max)
                })
                .collect();
            metrics.insert("posture".into(), json!(posture.as_slice()));
            metrics.insert("posture_max_deviation_rad".into(), json!(deviation));
        }
        let mut notes = Vec::new();
        if self.failed_samples > 0 {
            notes.push(format!(
                "the inverse kinematics failed at {} samples (the previous target was held)",
                self.failed_samples
            ));
        }
        ReferenceReport {
            singular_samples: self.singular_samples,
            failed_samples: self.failed_samples,
            metrics,
            notes,
        }
    }
}
