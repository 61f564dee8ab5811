//! Tests of `armdyn::sim::friction`: joint friction: the Stribeck and asymmetry terms shape the
//! Coulomb level.

use armdyn::sim::friction::*;
use nalgebra::Vector2;

#[test]
fn stribeck_and_asymmetry_shape_the_coulomb_level() {
    let base = JointFriction::new(Vector2::new(0.0, 1.0), Vector2::new(2.0, 2.0), 1e-4).unwrap();
    let f = base
        .with_stribeck(Vector2::new(1.0, 0.0), 0.1)
        .unwrap()
        .with_asymmetry(Vector2::new(0.0, 0.25))
        .unwrap();
    // Joint 1: 2 + 1 near rest (past the smoothing), fading to 2 well past vs.
    let slow = f.torque(&Vector2::new(0.01, 0.0))[0];
    approx::assert_relative_eq!(slow, 2.0 + libm::exp(-0.01), epsilon = 1e-9);
    approx::assert_relative_eq!(f.torque(&Vector2::new(1.0, 0.0))[0], 2.0, epsilon = 1e-9);
    approx::assert_relative_eq!(f.torque(&Vector2::new(-1.0, 0.0))[0], -2.0, epsilon = 1e-9);
    // Joint 2: Coulomb 2 (1 + 0.25) forward, 2 (1 - 0.25) backward, viscous 1.
    approx::assert_relative_eq!(f.torque(&Vector2::new(0.0, 1.0))[1], 3.5, epsilon = 1e-9);
    approx::assert_relative_eq!(f.torque(&Vector2::new(0.0, -1.0))[1], -2.5, epsilon = 1e-9);
    // Without them, as before; bad values named.
    assert_eq!(base.torque(&Vector2::new(1.0, 1.0)), Vector2::new(2.0, 3.0));
    assert_eq!(
        base.with_stribeck(Vector2::new(1.0, -1.0), 0.1),
        Err(FrictionError::Stribeck(1))
    );
    assert_eq!(
        base.with_stribeck(Vector2::new(1.0, 1.0), 0.0),
        Err(FrictionError::Stribeck(0))
    );
    assert_eq!(
        base.with_asymmetry(Vector2::new(1.5, 0.0)),
        Err(FrictionError::Asymmetry(0))
    );
}
