//! Tests of `armdyn::control::safety::sensor_health`: the sensor health check: each bad reading
//! trips with its cause, a frozen reading, and the spike filter.

use armdyn::control::safety::limits::defaults;
use armdyn::control::safety::sensor_health::*;
use armdyn::control::safety::{SensorLimits, Trip, TripCause};
use nalgebra::Vector6;

fn limits() -> SensorLimits<f64> {
    SensorLimits {
        range_n: defaults::SENSOR_RANGE_N,
        range_nm: defaults::SENSOR_RANGE_NM,
        frozen_s: Some(0.005),
        stale_s: 0.003,
        spike_n: Some(defaults::SPIKE_N),
    }
}

/// [`SensorHealth::judge`] with [`limits`] at a 1 ms period, as a result: the reading to
/// use, or the trip.
fn check(
    h: &mut SensorHealth<f64>,
    t: f64,
    r: &Vector6<f64>,
    age_s: f64,
) -> Result<Vector6<f64>, Trip<f64>> {
    match h.judge(&limits(), t, r, age_s, 1e-3) {
        Some(trip) => Err(trip),
        None => Ok(h.accepted()),
    }
}

fn fz(f: f64) -> Vector6<f64> {
    Vector6::new(0.0, 0.0, f, 0.0, 0.0, 0.0)
}

#[test]
fn each_bad_reading_trips_with_its_cause() {
    let mut h = SensorHealth::default();
    let cause = |h: &mut SensorHealth<f64>, r: Vector6<f64>, age| {
        check(h, 1.0, &r, age).err().map(|t| t.cause)
    };
    assert_eq!(cause(&mut h, fz(-50.0), 0.0), None);
    assert_eq!(
        cause(&mut h, fz(f64::NAN), 0.0),
        Some(TripCause::SensorNonFinite)
    );
    assert_eq!(
        cause(&mut h, fz(f64::NEG_INFINITY), 0.0),
        Some(TripCause::SensorNonFinite)
    );
    assert_eq!(
        cause(&mut h, fz(-3000.0), 0.0),
        Some(TripCause::SensorRange)
    );
    assert_eq!(cause(&mut h, fz(-50.0), 0.002), None);
    assert_eq!(
        cause(&mut h, fz(-50.0), 0.004),
        Some(TripCause::SensorStale)
    );
}

#[test]
fn a_repeating_reading_is_frozen_after_the_frozen_time() {
    let mut h = SensorHealth::default();
    let r = fz(-50.0);
    // The first reading and four repeats (4 ms) pass; the fifth repeat is 5 ms frozen.
    for k in 0..5 {
        assert!(check(&mut h, k as f64 * 1e-3, &r, 0.0).is_ok(), "{k}");
    }
    let trip = check(&mut h, 5e-3, &r, 0.0).unwrap_err();
    assert_eq!(trip.cause, TripCause::SensorFrozen);
    // A held (not fresh) reading is not a frozen one.
    let mut h = SensorHealth::default();
    for k in 0..10 {
        let _ = check(&mut h, k as f64 * 1e-3, &fz(k as f64), 0.0);
    }
    assert!(check(&mut h, 0.01, &fz(9.0), 0.001).is_ok());
}

#[test]
fn the_spike_filter_holds_one_reading_and_takes_a_real_step_one_period_late() {
    let mut h = SensorHealth::default();
    assert_eq!(check(&mut h, 0.0, &fz(-50.0), 0.0), Ok(fz(-50.0)));
    assert_eq!(check(&mut h, 1e-3, &fz(-2050.0), 0.0), Ok(fz(-50.0)));
    assert_eq!(check(&mut h, 2e-3, &fz(-51.0), 0.0), Ok(fz(-51.0)));
    assert_eq!(h.spikes(), 1);
    // A step that stays: held once, then accepted.
    assert_eq!(check(&mut h, 3e-3, &fz(-600.0), 0.0), Ok(fz(-51.0)));
    assert_eq!(check(&mut h, 4e-3, &fz(-600.0), 0.0), Ok(fz(-600.0)));
}
