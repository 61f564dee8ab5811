//! Tests of `armdyn::metrics` on samples built by hand, whose metrics are known in closed
//! form. A file here tests the file of the same name in `src/metrics/`.

mod alignment;
mod contact;
mod force;
mod pose;
mod rms;
mod settling;
mod tracking;

use armdyn::model::{JointVector, Wrench};
use armdyn::sim::Sample;
use armdyn::target::{CartesianTarget, JointTarget, Setpoint};
use nalgebra::{UnitQuaternion, Vector3};

/// A two-joint sample at `t` s: at rest at the origin, on its reference exactly, no force,
/// position controlled.
pub fn at(t: f64) -> Sample<2> {
    let zero = JointVector::<2>::zeros();
    let pose = CartesianTarget::at_rest(Vector3::zeros(), UnitQuaternion::identity());
    Sample {
        t,
        q: zero,
        qd: zero,
        tau_command: zero,
        tau: zero,
        setpoint: Setpoint {
            joint: JointTarget::at_rest(zero),
            cartesian: pose,
            wrench: Wrench::zeros(),
        },
        position: pose.position,
        orientation: pose.orientation,
        wrench: Wrench::zeros(),
        measured_wrench: Wrench::zeros(),
        force_controlled: false,
    }
}

/// The times `0, dt, 2 dt, ...` below `end` s (`k dt`, not a running sum).
pub fn times(dt: f64, end: f64) -> impl Iterator<Item = f64> {
    (0..)
        .map(move |k| k as f64 * dt)
        .take_while(move |t| *t < end - 1e-12)
}
