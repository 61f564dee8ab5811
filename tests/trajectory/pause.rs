//! Tests of `armdyn::trajectory::pause`: a paused reference stops, holds and resumes shifted,
//! continuous; bad pauses are refused.

use armdyn::robots::scara::thesis::ThreeZone;
use armdyn::trajectory::pause::*;
use armdyn::trajectory::CartesianTrajectory;

fn paused() -> Paused<ThreeZone> {
    Paused::new(
        ThreeZone::new(),
        vec![Pause {
            at_s: 5.0,
            ramp_s: 0.5,
            hold_s: 1.2,
        }],
    )
    .unwrap()
}

#[test]
fn continuous_stops_holds_and_resumes_shifted() {
    let p = paused();
    let inner = ThreeZone::new();
    assert_eq!(p.at(4.0), inner.at(4.0));
    assert!((p.duration() - 11.7).abs() < 1e-12);
    let (h0, h1) = p.hold_interval(0);
    assert!((h0 - 5.25).abs() < 1e-12 && (h1 - 6.45).abs() < 1e-12);
    let still = p.at(5.8);
    assert_eq!(still.position, inner.at(5.0).position);
    assert_eq!(still.velocity, nalgebra::Vector3::zeros());
    assert_eq!(still.acceleration, nalgebra::Vector3::zeros());
    let later = p.at(9.0);
    assert!((later.position - inner.at(9.0 - 1.7).position).norm() < 1e-12);
    // Position, velocity and acceleration are continuous at every phase boundary, and
    // velocity and acceleration are the derivatives of position and velocity.
    for t in [4.75, 5.25, 6.45, 6.95, 5.0, 6.7] {
        let (a, b) = (p.at(t - 1e-7), p.at(t + 1e-7));
        assert!((a.position - b.position).norm() < 1e-7, "{t}");
        assert!((a.velocity - b.velocity).norm() < 1e-6, "{t}");
        assert!((a.acceleration - b.acceleration).norm() < 1e-4, "{t}");
        let h = 1e-5;
        let (m, c, n) = (p.at(t - h), p.at(t), p.at(t + h));
        assert!(
            ((n.position - m.position) / (2.0 * h) - c.velocity).norm() < 1e-7,
            "{t}"
        );
        assert!(
            ((n.velocity - m.velocity) / (2.0 * h) - c.acceleration).norm() < 1e-5,
            "{t}"
        );
    }
}

#[test]
fn bad_pauses_are_refused() {
    let p = |at_s, ramp_s, hold_s| Pause {
        at_s,
        ramp_s,
        hold_s,
    };
    assert!(Paused::new(ThreeZone::new(), vec![p(5.0, 0.0, 1.0)]).is_err());
    assert!(Paused::new(ThreeZone::new(), vec![p(5.0, 0.5, -1.0)]).is_err());
    assert!(Paused::new(ThreeZone::new(), vec![p(5.0, 0.5, 1.0), p(5.2, 0.5, 1.0)]).is_err());
}
