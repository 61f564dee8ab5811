//! Tests of `armdyn::report::decimate`: min-max decimation: short series pass, extremes and order
//! kept within the bound, the ends kept.

use armdyn::report::decimate::*;

#[test]
fn short_series_pass_through() {
    let s = [(0.0, 1.0), (1.0, 2.0), (2.0, f64::NAN), (3.0, 0.0)];
    assert_eq!(
        decimate_min_max(&s, 10),
        [(0.0, 1.0), (1.0, 2.0), (3.0, 0.0)]
    );
    assert!(decimate_min_max(&[], 10).is_empty());
}

#[test]
fn keeps_extremes_order_and_bound() {
    let s: Vec<(f64, f64)> = (0..10_001)
        .map(|i| {
            let t = i as f64 * 1e-3;
            (t, (40.0 * t).sin() + if i == 7777 { -5.0 } else { 0.0 })
        })
        .collect();
    let d = decimate_min_max(&s, 2000);
    assert!(d.len() <= 2002, "{}", d.len());
    assert!(d.windows(2).all(|w| w[0].0 < w[1].0), "time order kept");
    assert_eq!(d[0], s[0]);
    assert_eq!(*d.last().unwrap(), *s.last().unwrap());
    assert!(d.contains(&s[7777]));
    let max = s.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    assert_eq!(d.iter().map(|p| p.1).fold(f64::MIN, f64::max), max);
}

#[test]
fn stride_keeps_ends() {
    let s: Vec<usize> = (0..10_001).collect();
    let d = decimate_stride(&s, 2000);
    assert!(d.len() <= 2001, "{}", d.len());
    assert_eq!(d[0], 0);
    assert_eq!(*d.last().unwrap(), 10_000);
    assert_eq!(decimate_stride(&s[..3], 2000), [0, 1, 2]);
}
