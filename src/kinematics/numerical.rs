//! Numerical inverse kinematics: damped least squares (Levenberg–Marquardt) on the generated
//! geometric Jacobian.
//!
//! Each iteration, with `e` the pose error in the task's directions
//! ([`Task::pose_error`](crate::target::Task::pose_error): position, then the SO(3) logarithm
//! or the yaw difference) and `J_t` the task's rows of the Jacobian:
//!
//! ```text
//! dq = J_t^T (J_t J_t^T + lambda I)^-1 e  +  (I - J_t^+ J_t) k (q_posture - q)   (redundant arms)
//! q  = clamp(q + dq, limits)
//! ```
//!
//! `lambda` adapts (Levenberg–Marquardt): a step that lowers `|e|` is kept and `lambda`
//! shrinks tenfold, towards Gauss–Newton and its quadratic convergence; one that does not is
//! undone and `lambda` grows tenfold. A joint held at a limit by the clamp, with the step
//! pushing it outward, is taken out of the step (its column zeroed) until the step turns.
//! The posture term moves a redundant arm within the task's null space towards the stated
//! posture, so that of the solutions the one nearest it is found. When the seed leads
//! nowhere within the iteration cap, the solve restarts from the posture (or mid-range) and
//! from a fixed sequence of configurations spread over the limits, and returns the solution
//! nearest the seed (or the posture) among the starts that converge, or the closest miss.

use nalgebra::{SMatrix, Vector6};

use super::{IkError, IkSolution, InverseKinematics};
use crate::model::{JointVector, RobotModel};
use crate::target::{orientation, CartesianTarget, Rotations};

/// Settings of [`NumericalIk`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkOptions<const N: usize> {
    /// Position tolerance, m (default 1e-12).
    pub tolerance_m: f64,
    /// Orientation tolerance, rad (default 1e-12).
    pub tolerance_rad: f64,
    /// Iteration cap per start (default 100).
    pub max_iterations: usize,
    /// Starts tried after the seed when it does not converge (default 64).
    pub restarts: usize,
    /// The posture a redundant arm's solution is drawn towards in the task's null space
    /// (`None`: the middle of the joint limits); also the first restart.
    pub posture: Option<JointVector<N>>,
    /// Weight of each joint in the distance to the posture (`None`: all 1): a redundant arm's
    /// solution is the one nearest the posture in `sum_i w_i (q_i - q0_i)^2`, so a joint
    /// with a large weight is held near its posture value first.
    pub posture_weights: Option<JointVector<N>>,
    /// Moves along the null space towards the posture, each followed by Gauss-Newton steps
    /// back onto the task (default 100; a reference tracking a path, warm-started from the
    /// previous sample, needs a few).
    pub posture_moves: usize,
    /// Gain of the posture term per iteration, in `(0, 1]` (default 1: the nearest point of
    /// the linearised null space).
    pub posture_gain: f64,
}

impl<const N: usize> Default for IkOptions<N> {
    fn default() -> Self {
        Self {
            tolerance_m: 1e-12,
            tolerance_rad: 1e-12,
            max_iterations: 100,
            restarts: 64,
            posture_moves: 100,
            posture: None,
            posture_weights: None,
            posture_gain: 1.0,
        }
    }
}

/// Levenberg–Marquardt inverse kinematics of any robot of the registry (see the [module
/// documentation](self)).
///
/// ```
/// use armdyn::kinematics::{InverseKinematics, IkOptions, NumericalIk};
/// use armdyn::model::{RobotModel, Ur5};
/// use armdyn::target::{orientation, CartesianTarget};
/// use nalgebra::SVector;
///
/// let q = SVector::from([0.3, -1.2, 1.4, -1.8, -1.5, 0.2]);
/// let pose = Ur5.end_effector_pose(&q);
/// let target = CartesianTarget::at_rest(
///     pose.fixed_view::<3, 1>(0, 3).into_owned(),
///     orientation::of_pose(&pose),
/// );
/// let ik = NumericalIk::new(Ur5, IkOptions::default());
/// let s = ik.solve(&target, &SVector::from([0.2, -1.0, 1.2, -1.6, -1.4, 0.0])).unwrap();
/// assert!(s.position_error_m < 1e-9 && s.orientation_error_rad < 1e-9);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct NumericalIk<const N: usize, R> {
    robot: R,
    options: IkOptions<N>,
    posture: JointVector<N>,
    /// The posture weights over their largest (so the largest is 1).
    weights: JointVector<N>,
}

/// One start's result: the configuration and its errors.
#[derive(Clone, Copy, Debug)]
struct Attempt<const N: usize> {
    q: JointVector<N>,
    position_error_m: f64,
    orientation_error_rad: f64,
    iterations: usize,
    converged: bool,
}

impl<const N: usize, R: RobotModel<N>> NumericalIk<N, R> {
    /// The solver for `robot` with `options`.
    #[must_use]
    pub fn new(robot: R, options: IkOptions<N>) -> Self {
        let mid = robot.middle_of_limits();
        let weights = options
            .posture_weights
            .map_or(JointVector::<N>::repeat(1.0), |w| {
                let largest = w.amax();
                if largest > 0.0 && largest.is_finite() {
                    w / largest
                } else {
                    JointVector::<N>::repeat(1.0)
                }
            });
        Self {
            robot,
            posture: options.posture.unwrap_or(mid),
            weights,
            options,
        }
    }

    /// The settings.
    #[must_use]
    pub fn options(&self) -> &IkOptions<N> {
        &self.options
    }

    /// The weighted distance of `q` from the posture, `sqrt(sum_i w_i (q_i - q0_i)^2)`.
    #[must_use]
    pub fn posture_distance(&self, q: &JointVector<N>) -> f64 {
        let d = q - self.posture;
        libm::sqrt(d.component_mul(&d).dot(&self.weights))
    }

    /// The posture a redundant arm is drawn towards (the option's, or mid-range).
    #[must_use]
    pub fn posture(&self) -> &JointVector<N> {
        &self.posture
    }

    fn clamp(q: &JointVector<N>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| {
            let [lo, hi] = R::JOINT_LIMITS[i];
            q[i].clamp(lo, hi)
        })
    }

    /// The task error at `q` and the task rows of the Jacobian there.
    fn error(
        &self,
        target: &CartesianTarget,
        q: &JointVector<N>,
    ) -> (Vector6<f64>, SMatrix<f64, 6, N>) {
        let pose = self.robot.end_effector_pose(q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let e = R::TASK.pose_error(
            &target.position,
            &target.orientation,
            &p,
            &orientation::of_pose(&pose),
        );
        let mask = R::TASK.mask();
        let mut j = self.robot.jacobian(q);
        if R::TASK.rotations() == Rotations::Full {
            // The log map's own Jacobian: e_o moves by -J_r^-1(e_o) J_w dq.
            let rows = orientation::right_jacobian_inverse(&e.fixed_rows::<3>(3).into_owned())
                * j.fixed_rows::<3>(3);
            j.fixed_rows_mut::<3>(3).copy_from(&rows);
        }
        (e, SMatrix::<f64, 6, N>::from_fn(|r, c| j[(r, c)] * mask[r]))
    }

    /// `(position error, orientation error)` norms of `e`.
    fn norms(e: &Vector6<f64>) -> (f64, f64) {
        (e.fixed_rows::<3>(0).norm(), e.fixed_rows::<3>(3).norm())
    }

    /// One Levenberg–Marquardt run from `start`: steps with the posture term (a redundant
    /// arm) until the task error is small and the posture step has died out, then steps
    /// without it until the tolerance is met.
    fn run(&self, target: &CartesianTarget, start: &JointVector<N>) -> Attempt<N> {
        let o = &self.options;
        let done = |e: &Vector6<f64>| {
            let (ep, eo) = Self::norms(e);
            ep <= o.tolerance_m && eo <= o.tolerance_rad
        };
        let attempt = |state: &Descent<N>, iterations: usize| {
            let (position_error_m, orientation_error_rad) = Self::norms(&state.e);
            Attempt {
                q: state.q,
                position_error_m,
                orientation_error_rad,
                iterations,
                converged: done(&state.e),
            }
        };
        // Levenberg-Marquardt on the task alone.
        let mut state = Descent::new(self, target, start);
        let mut iterations = 0;
        while iterations < o.max_iterations && !done(&state.e) && state.lambda <= 1e12 {
            iterations += 1;
            state.step(self, target, 0.0);
        }
        let plain = attempt(&state, iterations);
        if !plain.converged || R::TASK.redundancy(N) == 0 {
            return plain;
        }
        // A redundant arm: along the task's null space towards the posture, then a polish
        // back onto the tolerance; the plain solution stands if that fails.
        // Each move: a step along the null space (and onto the task), then Gauss-Newton back
        // onto the task; kept if it ends on the task nearer the posture, else undone with half
        // the gain.
        let mut gain = o.posture_gain;
        let mut moved = 0;
        let mut distance = self.posture_distance(&state.q);
        while moved < o.posture_moves && gain > 1e-6 {
            moved += 1;
            let saved = state.clone();
            state.lambda = 1e-9;
            let (posture_step, _) = state.step(self, target, gain);
            for _ in 0..4 {
                state.step(self, target, 0.0);
            }
            let d = self.posture_distance(&state.q);
            if Self::norms(&state.e).0 <= 1e-9 && Self::norms(&state.e).1 <= 1e-9 && d <= distance {
                distance = d;
                gain = (gain * 2.0).min(o.posture_gain);
                if posture_step <= 1e-9 {
                    break;
                }
            } else {
                state = saved;
                gain *= 0.5;
            }
        }
        state.lambda = 1e-6;
        let mut polish = 0;
        while polish < 20 && !done(&state.e) && state.lambda <= 1e12 {
            polish += 1;
            state.step(self, target, 0.0);
        }
        let drawn = attempt(&state, iterations + moved + polish);
        if drawn.converged {
            drawn
        } else {
            Attempt {
                iterations: drawn.iterations,
                ..plain
            }
        }
    }

    /// The `k`-th restart configuration: the posture, then a fixed low-discrepancy sequence
    /// over the limits (infinite ones as +-pi rad or +-1 m).
    fn restart(&self, k: usize) -> JointVector<N> {
        if k == 0 {
            return self.posture;
        }
        // Additive recurrence with the golden-ratio family of irrationals, one per joint.
        JointVector::<N>::from_fn(|i, _| {
            let alpha = libm::fmod(
                0.618_033_988_749_894_9 * (i as f64 + 1.0)
                    + 0.324_919_696_232_906_3 * (i * i) as f64,
                1.0,
            );
            let u = libm::fmod(0.5 + alpha * k as f64, 1.0);
            let [lo, hi] = R::JOINT_LIMITS[i];
            let (lo, hi) = if lo.is_finite() && hi.is_finite() {
                (lo, hi)
            } else {
                let span = if R::JOINT_KINDS[i] == crate::model::JointKind::Prismatic {
                    1.0
                } else {
                    core::f64::consts::PI
                };
                (-span, span)
            };
            lo + (hi - lo) * u
        })
    }
}

/// The state of one descent: the configuration, its error and Jacobian, the damping and the
/// joints held at a limit.
#[derive(Clone)]
struct Descent<const N: usize> {
    q: JointVector<N>,
    e: Vector6<f64>,
    j: SMatrix<f64, 6, N>,
    cost: f64,
    lambda: f64,
    free: [bool; N],
}

impl<const N: usize> Descent<N> {
    fn new<R: RobotModel<N>>(
        ik: &NumericalIk<N, R>,
        target: &CartesianTarget,
        start: &JointVector<N>,
    ) -> Self {
        let q = NumericalIk::<N, R>::clamp(start);
        let (e, j) = ik.error(target, &q);
        Self {
            q,
            cost: e.norm_squared(),
            e,
            j,
            lambda: 1e-3,
            free: [true; N],
        }
    }

    /// One damped step, with the posture term of gain `posture_gain` (0: none); returns the
    /// size of the posture part of the step and whether the step was kept.
    fn step<R: RobotModel<N>>(
        &mut self,
        ik: &NumericalIk<N, R>,
        target: &CartesianTarget,
        posture_gain: f64,
    ) -> (f64, bool) {
        let posture = posture_gain > 0.0;
        let free = self.free;
        // The columns of joints held at a limit (and pushed outward) are left out.
        let jf = SMatrix::<f64, 6, N>::from_fn(|r, c| if free[c] { self.j[(r, c)] } else { 0.0 });
        let jjt = jf * jf.transpose();
        // Rows outside the task are zero in jf: an identity there keeps the system regular.
        let mask = R::TASK.mask();
        let scale = jjt.trace().max(1e-12) / 6.0;
        let mut a = jjt;
        for k in 0..6 {
            a[(k, k)] += self.lambda * scale + (1.0 - mask[k]);
        }
        let Some(chol) = a.cholesky() else {
            self.lambda *= 10.0;
            return (0.0, false);
        };
        let mut dq = jf.transpose() * chol.solve(&self.e);
        let mut posture_step = 0.0;
        if posture {
            // Null-space pull towards the posture, with the (barely damped) pseudo-inverse.
            let mut g = jjt;
            for k in 0..6 {
                g[(k, k)] += 1e-12 * scale + (1.0 - mask[k]);
            }
            if let Some(gc) = g.cholesky() {
                let pull = (ik.posture - self.q).component_mul(&ik.weights) * posture_gain;
                let pull = JointVector::<N>::from_fn(|i, _| if free[i] { pull[i] } else { 0.0 });
                let null = pull - jf.transpose() * gc.solve(&(jf * pull));
                posture_step = null.amax() / posture_gain;
                dq += null;
            }
        }
        let candidate = NumericalIk::<N, R>::clamp(&(self.q + dq));
        let (e_new, j_new) = ik.error(target, &candidate);
        let cost_new = e_new.norm_squared();
        // A step with the posture term is always taken: the task error it adds (to second
        // order) is corrected by the steps after it, and the caller judges the result.
        let accept = cost_new <= self.cost || posture;
        if accept {
            // Joints the clamp stopped at a limit while the step pushed them out are held.
            for i in 0..N {
                let [lo, hi] = R::JOINT_LIMITS[i];
                self.free[i] =
                    !((candidate[i] <= lo && dq[i] < 0.0) || (candidate[i] >= hi && dq[i] > 0.0));
            }
            self.q = candidate;
            self.e = e_new;
            self.j = j_new;
            self.cost = cost_new;
            self.lambda = (self.lambda * 0.1).max(1e-15);
        } else {
            self.lambda *= 10.0;
            // A joint held at its limit may have to come back: release them all.
            self.free = [true; N];
        }
        (posture_step, accept)
    }
}

impl<const N: usize, R: RobotModel<N>> InverseKinematics<N> for NumericalIk<N, R> {
    fn solve(
        &self,
        target: &CartesianTarget,
        seed: &JointVector<N>,
    ) -> Result<IkSolution<N>, IkError> {
        let q = target.orientation.quaternion();
        let finite = target
            .position
            .iter()
            .chain(q.coords.iter())
            .chain(seed.iter())
            .all(|x| x.is_finite());
        if !finite {
            return Err(IkError::NonFinite);
        }
        let first = self.run(target, seed);
        let mut total = first.iterations;
        let solution = |a: &Attempt<N>, total: usize| IkSolution {
            q: a.q,
            position_error_m: a.position_error_m,
            orientation_error_rad: a.orientation_error_rad,
            iterations: total,
        };
        if first.converged {
            return Ok(solution(&first, total));
        }
        // Restarts, from the posture and then spread over the limits: the first that
        // converges.
        let mut best: Option<Attempt<N>> = None;
        let mut closest = first;
        for k in 0..self.options.restarts {
            let a = self.run(target, &self.restart(k));
            total += a.iterations;
            if a.converged {
                best = Some(a);
                break;
            }
            if a.position_error_m + a.orientation_error_rad
                < closest.position_error_m + closest.orientation_error_rad
            {
                closest = a;
            }
        }
        match best {
            Some(a) => Ok(solution(&a, total)),
            None => Err(IkError::NotReached {
                position_error_m: closest.position_error_m,
                orientation_error_rad: closest.orientation_error_rad,
                iterations: total,
            }),
        }
    }
}
