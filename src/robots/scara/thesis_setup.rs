//! The thesis's trial settings besides its references: when its hybrid controller switches
//! to force control, the surface it presses on, and the window its force is judged over
//! (Chapter 5).

use crate::contact::ReactionSurface;
use crate::control::force::ForcePi;
use crate::control::gains::MassRounding;
use crate::control::mass_split::SplitKind;
use crate::control::pid_fl::PidFeedbackLinearization;
use crate::control::selection::SelectionPolicy;
use crate::metrics::ForceMetrics;
use crate::model::Scara;

/// The thesis's PID poles (eq. 4.13), rad/s: `Kp = 242 m`, `Ki = 720 m`, `Kd = 27 m` for a
/// joint of effective mass `m` (eq. 4.15).
pub const THESIS_PID_POLES: [f64; 3] = [-8.0, -9.0, -10.0];

/// The thesis's requested closed-loop poles for full-state feedback, rad/s (Section 4.3):
/// `control::fsf::fsf_poles(4)`.
pub const THESIS_FSF_POLES: [f64; 8] = [-8.0, -8.1, -8.2, -8.3, -8.4, -8.5, -8.6, -8.7];

/// The thesis's force law (Section 5.3): PI + feedforward, `Kfp = 20`, `Kfi = 5` 1/s, and with
/// `damped` the velocity damping `Kvd = 2000` N s/m (eq. 5.10-5.11).
#[must_use]
pub fn thesis_force_law(damped: bool) -> ForcePi {
    ForcePi::new(20.0, 5.0, if damped { 2000.0 } else { 0.0 })
}

/// The thesis's position loop (Section 4.2): PID with feedback linearization, `M_linear` the
/// mass matrix's constant part (`kind`: the whole of it, or its diagonal), each joint's poles
/// at -8, -9, -10 rad/s with the masses rounded as the thesis rounds them. `None` only if
/// `M_linear` is singular (not for the committed robot).
#[must_use]
pub fn thesis_position_loop(kind: SplitKind) -> Option<PidFeedbackLinearization<4, Scara>> {
    PidFeedbackLinearization::with_poles(Scara, kind, MassRounding::Thesis, THESIS_PID_POLES)
}

/// The thesis's selection: force control from 2 s on (eq. 5.5-5.6).
pub const THESIS_SELECTION: SelectionPolicy = SelectionPolicy::Time { switch_s: 2.0 };

/// The thesis's reaction surface: `z = 0.13` m, `x in [0.2, 0.6]`, `y in [-0.4, 0.4]` m,
/// `k = 10 kN/m` (Section 5.1, eq. 5.1).
#[must_use]
pub fn thesis_surface() -> ReactionSurface {
    ReactionSurface::new(0.13, [0.2, 0.6], [-0.4, 0.4], 10_000.0)
        .expect("the thesis's surface is valid")
}

/// The thesis's force metrics: force control from 2 s, a 10 s trial judged over its last
/// 5 s, 200 N asked, settling within a 5 % band.
#[must_use]
pub fn thesis_force_metrics() -> ForceMetrics {
    ForceMetrics::new(2.0, 10.0, 5.0, 200.0, 0.05)
}
