//! `armdyn.Robot`: a generated robot by name, its facts and its functions on one state or a
//! batch of states (loops in Rust with the GIL released, in parallel above
//! [`PARALLEL_MIN_STATES`]).

use numpy::PyArrayDyn;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::inputs::{output, same_rows, states, vector, States};
use crate::model::{arm, Arm, Function};

/// With `parallel=None` (the default), batches of at least this many states run on every core
/// (rayon) and smaller ones on the calling thread, where splitting costs more than it gains
/// (`python/bench.py` measures both sides of it); `parallel=True` or `False` forces either.
pub const PARALLEL_MIN_STATES: usize = 1024;

/// Batches shorter than this run without releasing the GIL (a microsecond or less).
const SERIAL_WITH_THE_GIL: usize = 8;

/// States per parallel task: four tasks per core, 16 to 4096 states each.
fn chunk(count: usize, threads: usize) -> usize {
    count.div_ceil(4 * threads).clamp(16, 4096)
}

/// A numpy `float64` array.
type Array<'py> = Bound<'py, PyArrayDyn<f64>>;

/// A generated robot of the registry.
#[pyclass(module = "armdyn._native", name = "Robot", frozen)]
pub struct Robot {
    arm: &'static dyn Arm,
}

/// Evaluates `f` of `arm` at every state of `args` (read and checked), with `parameters`.
fn evaluate<'py>(
    py: Python<'py>,
    arm: &'static dyn Arm,
    f: Function,
    args: &[(&str, &Bound<'py, PyAny>)],
    parameters: Option<&Bound<'py, PyAny>>,
    parallel: Option<bool>,
) -> PyResult<Vec<Bound<'py, PyArrayDyn<f64>>>> {
    let n = arm.dof();
    let read: Vec<(&str, States)> = args
        .iter()
        .map(|(name, obj)| Ok((*name, states(obj, name, n)?)))
        .collect::<PyResult<_>>()?;
    let pairs: Vec<(&str, &States)> = read.iter().map(|(k, s)| (*k, s)).collect();
    let (count, batched) = same_rows(&pairs)?;
    let params = match parameters {
        Some(p) if !p.is_none() => Some(vector(p, "parameters", 10 * n)?),
        _ => None,
    };
    let shapes = f.outputs(n);
    let sizes: Vec<usize> = shapes.iter().map(|s| s.iter().product()).collect();
    let inputs: Vec<Vec<f64>> = read.into_iter().map(|(_, s)| s.data).collect();
    // States `from..to` into fresh output buffers.
    // States `from..to` into `slots` (each output's part for those states).
    let run = |from: usize, to: usize, slots: &mut [&mut [f64]]| -> Result<(), String> {
        let ins: Vec<&[f64]> = inputs.iter().map(|x| &x[from * n..to * n]).collect();
        arm.eval_batch(f, &ins, params.as_deref(), to - from, slots)
            .map_err(|(k, e)| {
                if batched {
                    format!("state {}: {e}", from + k)
                } else {
                    e
                }
            })
    };
    let mut out: Vec<Vec<f64>> = sizes
        .iter()
        .map(|s| crate::buffer::zeros(s * count))
        .collect();
    let parallel = parallel.unwrap_or(count >= PARALLEL_MIN_STATES) && count > 1;
    let result = if !batched || count < SERIAL_WITH_THE_GIL {
        // Too short to be worth releasing the GIL.
        let mut slots: Vec<&mut [f64]> = out.iter_mut().map(Vec::as_mut_slice).collect();
        run(0, count, &mut slots)
    } else {
        py.detach(|| {
            if parallel {
                let pool = crate::pool::pool()?;
                let size = chunk(count, pool.current_num_threads());
                // Each task writes its states' part of every output in place.
                let mut tasks: Vec<Vec<&mut [f64]>> =
                    (0..count.div_ceil(size)).map(|_| Vec::new()).collect();
                for (o, s) in out.iter_mut().zip(&sizes) {
                    for (task, part) in tasks.iter_mut().zip(o.chunks_mut(size * s)) {
                        task.push(part);
                    }
                }
                pool.install(|| {
                    tasks
                        .into_par_iter()
                        .enumerate()
                        .try_for_each(|(c, mut slots)| {
                            run(c * size, ((c + 1) * size).min(count), &mut slots)
                        })
                })
            } else {
                let mut slots: Vec<&mut [f64]> = out.iter_mut().map(Vec::as_mut_slice).collect();
                run(0, count, &mut slots)
            }
        })
    };
    result.map_err(PyValueError::new_err)?;
    let data = out;
    data.into_iter()
        .zip(&shapes)
        .map(|(d, shape)| output(py, d, count, batched, shape))
        .collect()
}

fn one(mut v: Vec<Bound<'_, PyArrayDyn<f64>>>) -> Bound<'_, PyArrayDyn<f64>> {
    v.swap_remove(0)
}

#[pymethods]
impl Robot {
    /// The robot called `name` (one of `armdyn.robots()`).
    #[new]
    fn new(name: &str) -> PyResult<Self> {
        arm(name).map(|arm| Self { arm }).ok_or_else(|| {
            PyValueError::new_err(format!(
                "name: no robot called {name:?} (one of {})",
                crate::model::names().join(", ")
            ))
        })
    }

    fn __repr__(&self) -> String {
        format!("Robot({:?})", self.arm.name())
    }

    /// The robot's name, as in its description `robots/<name>.toml`.
    #[getter]
    fn name(&self) -> &'static str {
        self.arm.name()
    }

    /// Degrees of freedom `n`.
    #[getter]
    fn dof(&self) -> usize {
        self.arm.dof()
    }

    /// Joint names, base to tip.
    #[getter]
    fn joint_names(&self) -> Vec<&'static str> {
        self.arm.joint_names()
    }

    /// Joint kinds, base to tip: `"revolute"` (rad, N m) or `"prismatic"` (m, N).
    #[getter]
    fn joint_kinds(&self) -> Vec<&'static str> {
        self.arm.joint_kinds()
    }

    /// Joint position limits, `(n, 2)`: `[lower, upper]` per joint, rad or m.
    #[getter]
    fn joint_limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let l = self.arm.joint_limits();
        let n = l.len();
        output(py, l.into_iter().flatten().collect(), 1, false, &[n, 2])
    }

    /// Actuator limits, `(n,)`, N m or N (symmetric: `|tau_i| <= effort_limits[i]`).
    #[getter]
    fn effort_limits<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let e = self.arm.effort_limits();
        let n = e.len();
        output(py, e, 1, false, &[n])
    }

    /// Gravity acceleration in the base frame, `(3,)`, m/s^2 (as Pinocchio's `model.gravity`;
    /// the joint torques it causes are [`generalized_gravity`](Self::generalized_gravity)).
    #[getter]
    fn gravity<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        output(py, self.arm.gravity().to_vec(), 1, false, &[3])
    }

    /// SHA-256 (hex) of the description the model was generated from.
    #[getter]
    fn source_sha256(&self) -> &'static str {
        self.arm.source_sha256()
    }

    /// The description's `10 n` standard inertial parameters: per link `[m, m cx, m cy, m cz,
    /// Ixx, Ixy, Ixz, Iyy, Iyz, Izz]` (kg, kg m, kg m^2 about the link frame's origin).
    fn standard_parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let p = self.arm.standard_parameters();
        let len = p.len();
        output(py, p, 1, false, &[len])
    }

    /// Link frame poses `T_0^i`, i = 1..n: `(n, 4, 4)` (or `(N, n, 4, 4)`), m.
    #[pyo3(signature = (q, *, parallel = None))]
    fn frame_poses<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::FramePoses,
            &[("q", q)],
            None,
            parallel,
        )
        .map(one)
    }

    /// End-effector pose `T_0^tool`: `(4, 4)` (or `(N, 4, 4)`), m.
    #[pyo3(signature = (q, *, parallel = None))]
    fn end_effector_pose<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::EndEffectorPose,
            &[("q", q)],
            None,
            parallel,
        )
        .map(one)
    }

    /// End-effector Jacobian, base frame, at the tool point: `[v; w] = J(q) qd`, `(6, n)`.
    #[pyo3(signature = (q, *, parallel = None))]
    fn jacobian<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::Jacobian,
            &[("q", q)],
            None,
            parallel,
        )
        .map(one)
    }

    /// `Jdot(q, qd) qd`, `(6,)`: the tool's acceleration at `qdd = 0` (m/s^2, rad/s^2).
    #[pyo3(signature = (q, qd, *, parallel = None))]
    fn jdot_qd<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::JdotQd,
            &[("q", q), ("qd", qd)],
            None,
            parallel,
        )
        .map(one)
    }

    /// Joint-space mass matrix `M(q)`, `(n, n)`, kg m^2 / kg.
    #[pyo3(signature = (q, *, parameters = None, parallel = None))]
    fn mass_matrix<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::MassMatrix,
            &[("q", q)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// Coriolis/centrifugal matrix `C(q, qd)` (Christoffel form, `c = C qd`), `(n, n)`.
    #[pyo3(signature = (q, qd, *, parameters = None, parallel = None))]
    fn coriolis_matrix<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::CoriolisMatrix,
            &[("q", q), ("qd", qd)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// Coriolis and centrifugal torques `c(q, qd) = C(q, qd) qd`, `(n,)`, N m or N.
    #[pyo3(signature = (q, qd, *, parameters = None, parallel = None))]
    fn coriolis<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::Coriolis,
            &[("q", q), ("qd", qd)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// Gravity torques `g(q)`, `(n,)`, N m or N (Pinocchio's `computeGeneralizedGravity`).
    #[pyo3(signature = (q, *, parameters = None, parallel = None))]
    fn generalized_gravity<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::Gravity,
            &[("q", q)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// `(M(q), c(q, qd) + g(q))` in one call: `(n, n)` and `(n,)` (Pinocchio's `crba` and
    /// `nonLinearEffects`).
    #[pyo3(signature = (q, qd, *, parameters = None, parallel = None))]
    fn mass_matrix_and_bias<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<(Array<'py>, Array<'py>)> {
        let mut v = evaluate(
            q.py(),
            self.arm,
            Function::MassMatrixAndBias,
            &[("q", q), ("qd", qd)],
            parameters,
            parallel,
        )?;
        let b = v.swap_remove(1);
        Ok((v.swap_remove(0), b))
    }

    /// Inverse dynamics `tau = M(q) qdd + c(q, qd) + g(q)`, `(n,)`, N m or N.
    #[pyo3(signature = (q, qd, qdd, *, parameters = None, parallel = None))]
    fn inverse_dynamics<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        qdd: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::InverseDynamics,
            &[("q", q), ("qd", qd), ("qdd", qdd)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// Forward dynamics `qdd = M(q)^-1 (tau - c(q, qd) - g(q))`, `(n,)`, rad/s^2 or m/s^2.
    #[pyo3(signature = (q, qd, tau, *, parameters = None, parallel = None))]
    fn forward_dynamics<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
        parameters: Option<&Bound<'py, PyAny>>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::ForwardDynamics,
            &[("q", q), ("qd", qd), ("tau", tau)],
            parameters,
            parallel,
        )
        .map(one)
    }

    /// Derivatives of inverse dynamics at `(q, qd, qdd)`: `(d tau/d q, d tau/d qd)`, `(n, n)`
    /// each (or `(N, n, n)`), as Pinocchio's `computeRNEADerivatives` (`d tau/d qdd` is
    /// [`mass_matrix`](Self::mass_matrix)).
    #[pyo3(signature = (q, qd, qdd, *, parallel = None))]
    fn inverse_dynamics_derivatives<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        qdd: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<(Array<'py>, Array<'py>)> {
        let mut v = evaluate(
            q.py(),
            self.arm,
            Function::InverseDynamicsDerivatives,
            &[("q", q), ("qd", qd), ("qdd", qdd)],
            None,
            parallel,
        )?;
        let d_dqd = v.swap_remove(1);
        Ok((v.swap_remove(0), d_dqd))
    }

    /// Derivatives of forward dynamics at `(q, qd, tau)`: `(d qdd/d q, d qdd/d qd, M^-1)`,
    /// `(n, n)` each (or `(N, n, n)`), as Pinocchio's `computeABADerivatives` (`d qdd/d tau`
    /// is `M(q)^-1`).
    #[pyo3(signature = (q, qd, tau, *, parallel = None))]
    fn forward_dynamics_derivatives<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<(Array<'py>, Array<'py>, Array<'py>)> {
        let mut v = evaluate(
            q.py(),
            self.arm,
            Function::ForwardDynamicsDerivatives,
            &[("q", q), ("qd", qd), ("tau", tau)],
            None,
            parallel,
        )?;
        let m_inv = v.swap_remove(2);
        let d_dqd = v.swap_remove(1);
        Ok((v.swap_remove(0), d_dqd, m_inv))
    }

    /// The regressor `Y(q, qd, qdd)`, `(n, 10 n)`: `tau = Y @ standard_parameters()`.
    #[pyo3(signature = (q, qd, qdd, *, parallel = None))]
    fn regressor<'py>(
        &self,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        qdd: &Bound<'py, PyAny>,
        parallel: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        evaluate(
            q.py(),
            self.arm,
            Function::Regressor,
            &[("q", q), ("qd", qd), ("qdd", qdd)],
            None,
            parallel,
        )
        .map(one)
    }
}

/// The name of every robot: the registry's, then the package's own
/// (`ARMDYN_PYTHON_MODELS` at build time), each in name order.
#[pyfunction]
pub fn robots() -> Vec<&'static str> {
    crate::model::names()
}
