//! The thesis's trial settings besides its references: when its hybrid controller switches
//! to force control, the surface it presses on, and the window its force is judged over
//! (Chapter 5).

use crate::contact::ReactionSurface;
use crate::control::selection::SelectionPolicy;
use crate::metrics::ForceMetrics;

/// The thesis's requested closed-loop poles for full-state feedback, rad/s (Section 4.3):
/// `control::fsf::fsf_poles(4)`.
pub const THESIS_FSF_POLES: [f64; 8] = [-8.0, -8.1, -8.2, -8.3, -8.4, -8.5, -8.6, -8.7];

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_generic_pole_pattern_is_the_thesis_poles_for_four_joints() {
        assert_eq!(crate::control::fsf::fsf_poles(4), THESIS_FSF_POLES.to_vec());
    }
}
