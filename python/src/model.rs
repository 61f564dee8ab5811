//! Every generated robot behind one object-safe interface on flat slices, so Python can call
//! any of them by name: [`Arm`], [`Function`], [`arm`].

use armdyn::identification::Identifiable;
use armdyn::model::batch::{Batch, BatchModel, Lanes, LANES};
use armdyn::model::{DynamicsDerivatives, JointKind, ParametricModel, RobotModel};
use armdyn_generated::lanes::Lane;
use nalgebra::SVector;

/// A function of the model, its inputs (each `n` numbers per state) and output shapes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    /// Link frame poses `T_0^i`, `(n, 4, 4)`, from `q`.
    FramePoses,
    /// End-effector pose, `(4, 4)`, from `q`.
    EndEffectorPose,
    /// End-effector Jacobian `[v; w] = J qd`, `(6, n)`, base frame, from `q`.
    Jacobian,
    /// `Jdot qd`, `(6,)`, from `q, qd`.
    JdotQd,
    /// `M(q)`, `(n, n)`.
    MassMatrix,
    /// `C(q, qd)` (Christoffel), `(n, n)`.
    CoriolisMatrix,
    /// `c(q, qd) = C qd`, `(n,)`.
    Coriolis,
    /// `g(q)`, `(n,)`.
    Gravity,
    /// `M(q)` and `c + g`, `(n, n)` and `(n,)`.
    MassMatrixAndBias,
    /// `tau = M qdd + c + g`, `(n,)`, from `q, qd, qdd`.
    InverseDynamics,
    /// `qdd = M^-1 (tau - c - g)`, `(n,)`, from `q, qd, tau`.
    ForwardDynamics,
    /// The regressor `Y` with `tau = Y pi`, `(n, 10 n)`, from `q, qd, qdd`.
    Regressor,
    /// `d tau/d q` and `d tau/d qd` of inverse dynamics, `(n, n)` each, from `q, qd, qdd`.
    InverseDynamicsDerivatives,
    /// `d qdd/d q`, `d qdd/d qd` and `d qdd/d tau = M^-1` of forward dynamics, `(n, n)` each,
    /// from `q, qd, tau`.
    ForwardDynamicsDerivatives,
}

impl Function {
    /// The shape of each output for `n` joints.
    pub fn outputs(self, n: usize) -> Vec<Vec<usize>> {
        match self {
            Self::FramePoses => vec![vec![n, 4, 4]],
            Self::EndEffectorPose => vec![vec![4, 4]],
            Self::Jacobian => vec![vec![6, n]],
            Self::JdotQd => vec![vec![6]],
            Self::MassMatrix | Self::CoriolisMatrix => vec![vec![n, n]],
            Self::Coriolis | Self::Gravity | Self::InverseDynamics | Self::ForwardDynamics => {
                vec![vec![n]]
            }
            Self::MassMatrixAndBias => vec![vec![n, n], vec![n]],
            Self::Regressor => vec![vec![n, 10 * n]],
            Self::InverseDynamicsDerivatives => vec![vec![n, n]; 2],
            Self::ForwardDynamicsDerivatives => vec![vec![n, n]; 3],
        }
    }
}

/// A generated robot on flat slices.
pub trait Arm: Send + Sync {
    /// Its name.
    fn name(&self) -> &'static str;
    /// Degrees of freedom.
    fn dof(&self) -> usize;
    /// Joint names, base to tip.
    fn joint_names(&self) -> Vec<&'static str>;
    /// Joint kinds, `"revolute"` or `"prismatic"`.
    fn joint_kinds(&self) -> Vec<&'static str>;
    /// `[lower, upper]` per joint, rad or m.
    fn joint_limits(&self) -> Vec<[f64; 2]>;
    /// Actuator limits per joint, N m or N.
    fn effort_limits(&self) -> Vec<f64>;
    /// Gravity in the base frame, m/s^2.
    fn gravity(&self) -> [f64; 3];
    /// SHA-256 of the description the model was generated from.
    fn source_sha256(&self) -> &'static str;
    /// The `10 n` standard parameters of the description.
    fn standard_parameters(&self) -> Vec<f64>;
    /// Evaluates `f` at `rows` states: `inputs` holds its joint-vector arguments (`rows n`
    /// numbers each, state after state), `params` the standard parameters to use (`None`: the
    /// description's, through the generated closed-form functions: [`LANES`] states per call
    /// of the generated lane functions where they exist), and each output slice receives
    /// `rows` results, each row-major, one after the other.
    ///
    /// # Errors
    ///
    /// The state and what the model refuses there (a mass matrix that is not positive
    /// definite).
    fn eval_batch(
        &self,
        f: Function,
        inputs: &[&[f64]],
        params: Option<&[f64]>,
        rows: usize,
        out: &mut [&mut [f64]],
    ) -> Result<(), (usize, String)>;
}

/// What a generated robot implements (every robot of the registry and of `robot_type!`).
pub trait GeneratedRobot<const N: usize>:
    RobotModel<N>
    + ParametricModel<N>
    + Identifiable<N>
    + DynamicsDerivatives<N>
    + BatchModel<N>
    + Send
    + Sync
{
}

impl<const N: usize, R> GeneratedRobot<N> for R where
    R: RobotModel<N>
        + ParametricModel<N>
        + Identifiable<N>
        + DynamicsDerivatives<N>
        + BatchModel<N>
        + Send
        + Sync
{
}

/// The robot `R` as an [`Arm`].
pub struct Generated<R, const N: usize>(pub R);

#[inline(always)]
fn vector<const N: usize>(x: &[f64]) -> SVector<f64, N> {
    SVector::<f64, N>::from_column_slice(x)
}

/// Lanes `start .. start + LANES` of the joint vectors `x` (`rows` states of `N` numbers, the
/// last one repeated past the end).
#[inline(always)]
fn pack<const N: usize>(x: &[f64], rows: usize, start: usize) -> Lanes<N> {
    core::array::from_fn(|i| Batch::from_fn(|k| x[(start + k).min(rows - 1) * N + i]))
}

/// Writes lane `l` of `values` (one state's result, flattened row-major) into state
/// `start + l` of `out`, for the states below `end`.
#[inline(always)]
fn unpack(values: &[Batch], out: &mut [f64], start: usize, end: usize) {
    let size = values.len();
    let block = &mut out[start * size..end * size];
    for (i, value) in values.iter().enumerate() {
        for (l, state) in block.chunks_exact_mut(size).enumerate() {
            state[i] = value.lane(l);
        }
    }
}

/// Copies the `rows x cols` matrix `m` into `out` row-major.
#[inline(always)]
fn rows<const R: usize, const C: usize>(m: &nalgebra::SMatrix<f64, R, C>, out: &mut [f64]) {
    for i in 0..R {
        for j in 0..C {
            out[i * C + j] = m[(i, j)];
        }
    }
}

impl<const N: usize, R> Arm for Generated<R, N>
where
    R: GeneratedRobot<N>,
{
    fn name(&self) -> &'static str {
        R::NAME
    }
    fn dof(&self) -> usize {
        N
    }
    fn joint_names(&self) -> Vec<&'static str> {
        R::JOINT_NAMES.to_vec()
    }
    fn joint_kinds(&self) -> Vec<&'static str> {
        R::JOINT_KINDS
            .iter()
            .map(|k| match k {
                JointKind::Revolute => "revolute",
                JointKind::Prismatic => "prismatic",
            })
            .collect()
    }
    fn joint_limits(&self) -> Vec<[f64; 2]> {
        R::JOINT_LIMITS.to_vec()
    }
    fn effort_limits(&self) -> Vec<f64> {
        R::EFFORT_LIMITS.to_vec()
    }
    fn gravity(&self) -> [f64; 3] {
        R::GRAVITY
    }
    fn source_sha256(&self) -> &'static str {
        R::SOURCE_SHA256
    }
    fn standard_parameters(&self) -> Vec<f64> {
        <R as ParametricModel<N>>::standard_parameters()
            .as_ref()
            .to_vec()
    }

    fn eval_batch(
        &self,
        f: Function,
        inputs: &[&[f64]],
        params: Option<&[f64]>,
        rows: usize,
        out: &mut [&mut [f64]],
    ) -> Result<(), (usize, String)> {
        // Parameters were checked for their length by the caller.
        let p = params.and_then(R::parameters_from);
        let sizes: Vec<usize> = f.outputs(N).iter().map(|s| s.iter().product()).collect();
        if p.is_none() && self.lanes(f, inputs, rows, &sizes, out)? {
            return Ok(());
        }
        for k in 0..rows {
            self.one(f, k, inputs, p.as_ref(), &sizes, out)
                .map_err(|e| (k, e))?;
        }
        Ok(())
    }
}

impl<const N: usize, R> Generated<R, N>
where
    R: GeneratedRobot<N>,
{
    /// `f` at the `rows` states of `inputs` by the generated lane functions, [`LANES`] states
    /// per call, if `f` has them (`Ok(false)`, nothing written, if not). A state whose forward
    /// dynamics is not finite is evaluated again by the scalar function, whose error names it.
    fn lanes(
        &self,
        f: Function,
        inputs: &[&[f64]],
        rows: usize,
        sizes: &[usize],
        out: &mut [&mut [f64]],
    ) -> Result<bool, (usize, String)> {
        let robot = &self.0;
        let checked = matches!(
            f,
            Function::ForwardDynamics | Function::ForwardDynamicsDerivatives
        );
        for start in (0..rows).step_by(LANES) {
            let end = (start + LANES).min(rows);
            let arg = |j: usize| pack::<N>(inputs[j], rows, start);
            match f {
                Function::MassMatrixAndBias => {
                    let (m, b) = robot.mass_matrix_and_bias_lanes(&arg(0), &arg(1));
                    unpack(m.as_flattened(), out[0], start, end);
                    unpack(&b, out[1], start, end);
                }
                Function::InverseDynamics => {
                    let tau = robot.inverse_dynamics_lanes(&arg(0), &arg(1), &arg(2));
                    unpack(&tau, out[0], start, end);
                }
                Function::ForwardDynamics => {
                    let qdd = robot.forward_dynamics_lanes(&arg(0), &arg(1), &arg(2));
                    unpack(&qdd, out[0], start, end);
                }
                Function::InverseDynamicsDerivatives => {
                    let d = robot.inverse_dynamics_derivatives_lanes(&arg(0), &arg(1), &arg(2));
                    unpack(d[0].as_flattened(), out[0], start, end);
                    unpack(d[1].as_flattened(), out[1], start, end);
                }
                Function::ForwardDynamicsDerivatives => {
                    let d = robot.forward_dynamics_derivatives_lanes(&arg(0), &arg(1), &arg(2));
                    for (block, o) in d.iter().zip(out.iter_mut()) {
                        unpack(block.as_flattened(), o, start, end);
                    }
                }
                _ => return Ok(false),
            }
            if checked {
                for k in start..end {
                    let finite = out
                        .iter()
                        .zip(sizes)
                        .all(|(o, s)| o[k * s..(k + 1) * s].iter().all(|x| x.is_finite()));
                    if !finite {
                        self.one(f, k, inputs, None, sizes, out)
                            .map_err(|e| (k, e))?;
                    }
                }
            }
        }
        Ok(true)
    }

    /// `f` at state `k` of the batch `inputs` into slot `k` of `out` (`sizes`: each
    /// output's numbers per state).
    #[inline(always)]
    fn one(
        &self,
        f: Function,
        k: usize,
        inputs: &[&[f64]],
        p: Option<&R::Parameters>,
        sizes: &[usize],
        out: &mut [&mut [f64]],
    ) -> Result<(), String> {
        let robot = &self.0;
        let at = |j: usize| vector::<N>(&inputs[j][k * N..(k + 1) * N]);
        let q = at(0);
        let s0 = sizes[0];
        let (first, rest) = out.split_at_mut(1);
        let o = &mut first[0][k * s0..(k + 1) * s0];
        match f {
            Function::FramePoses => {
                for (i, pose) in robot.frame_poses(&q).iter().enumerate() {
                    rows(pose, &mut o[16 * i..16 * (i + 1)]);
                }
            }
            Function::EndEffectorPose => rows(&robot.end_effector_pose(&q), o),
            Function::Jacobian => rows(&robot.jacobian(&q), o),
            Function::JdotQd => o.copy_from_slice(robot.jdot_qd(&q, &at(1)).as_slice()),
            Function::MassMatrix => rows(
                &p.map_or_else(|| robot.mass_matrix(&q), |p| R::mass_matrix_with(&q, p)),
                o,
            ),
            Function::CoriolisMatrix => {
                let qd = at(1);
                rows(
                    &p.map_or_else(
                        || robot.coriolis_matrix(&q, &qd),
                        |p| R::coriolis_matrix_with(&q, &qd, p),
                    ),
                    o,
                );
            }
            Function::Coriolis => {
                let qd = at(1);
                let c = p.map_or_else(|| robot.coriolis(&q, &qd), |p| R::coriolis_with(&q, &qd, p));
                o.copy_from_slice(c.as_slice());
            }
            Function::Gravity => {
                let g = p.map_or_else(|| robot.gravity(&q), |p| R::gravity_with(&q, p));
                o.copy_from_slice(g.as_slice());
            }
            Function::MassMatrixAndBias => {
                let qd = at(1);
                let (m, b) = match p {
                    None => robot.mass_matrix_and_bias(&q, &qd),
                    Some(p) => (
                        R::mass_matrix_with(&q, p),
                        R::coriolis_with(&q, &qd, p) + R::gravity_with(&q, p),
                    ),
                };
                rows(&m, o);
                rest[0][k * N..(k + 1) * N].copy_from_slice(b.as_slice());
            }
            Function::InverseDynamics => {
                let (qd, qdd) = (at(1), at(2));
                let tau = p.map_or_else(
                    || robot.inverse_dynamics(&q, &qd, &qdd),
                    |p| R::inverse_dynamics_with(&q, &qd, &qdd, p),
                );
                o.copy_from_slice(tau.as_slice());
            }
            Function::ForwardDynamics => {
                let (qd, tau) = (at(1), at(2));
                let qdd = match p {
                    None => robot
                        .forward_dynamics(&q, &qd, &tau)
                        .map_err(|e| e.to_string())?,
                    Some(p) => {
                        let qdd = R::forward_dynamics_with(&q, &qd, &tau, p);
                        if !qdd.iter().all(|x| x.is_finite()) {
                            return Err("forward dynamics with these parameters is not finite \
                                        (their mass matrix is singular here)"
                                .to_string());
                        }
                        qdd
                    }
                };
                o.copy_from_slice(qdd.as_slice());
            }
            Function::Regressor => {
                let y = robot.regressor(&q, &at(1), &at(2));
                for i in 0..N {
                    for j in 0..10 * N {
                        o[i * 10 * N + j] = y[(i, j)];
                    }
                }
            }
            Function::InverseDynamicsDerivatives => {
                let d = robot.inverse_dynamics_derivatives(&q, &at(1), &at(2));
                rows(&d.dtau_dq, o);
                rows(&d.dtau_dqd, &mut rest[0][k * s0..(k + 1) * s0]);
            }
            Function::ForwardDynamicsDerivatives => {
                let d = robot
                    .forward_dynamics_derivatives(&q, &at(1), &at(2))
                    .map_err(|e| e.to_string())?;
                rows(&d.dqdd_dq, o);
                rows(&d.dqdd_dqd, &mut rest[0][k * s0..(k + 1) * s0]);
                rows(&d.mass_matrix_inverse, &mut rest[1][k * s0..(k + 1) * s0]);
            }
        }
        Ok(())
    }
}

macro_rules! registry {
    ([$function:ident $($path:ident)::+] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        /// The robot called `name` (`-` read as `_`) among these, or `None`.
        fn $function(name: &str) -> Option<&'static dyn Arm> {
            #[allow(unused_imports)]
            use $($path)::+ as types;
            match name.replace('-', "_").as_str() {
                $(stringify!($module) => Some(&Generated::<_, $n>(types::$ty)),)*
                _ => None,
            }
        }
    };
}

armdyn_generated::for_each_robot!(registry, registry_arm armdyn::model);
for_each_own_robot!(registry, own_arm crate::own);

/// The robot called `name` (`-` read as `_`): the registry's, or the package's own
/// (`ARMDYN_PYTHON_MODELS` at build time); `None` if neither has it.
pub fn arm(name: &str) -> Option<&'static dyn Arm> {
    registry_arm(name).or_else(|| own_arm(name))
}

/// Every robot's name: the registry's, then the package's own, each in name order.
pub fn names() -> Vec<&'static str> {
    armdyn::model::ROBOTS
        .iter()
        .chain(crate::own::OWN_ROBOTS.iter())
        .copied()
        .collect()
}

/// The URDF the generator wrote for the registry's robot `name`, or `None` (a robot of the
/// package's own: its URDF is beside its graphs).
pub fn urdf(name: &str) -> Option<&'static str> {
    armdyn::with_robot_named!(name, |_robot: R, N, module| module::URDF)
}
