//! Tests of `armdyn::report::data_plots`: the data plots draw, and refuse empty data.

use armdyn::report::data_plots::*;
use armdyn::report::plots::PlotError;

#[test]
fn draws_and_refuses_empty() {
    let svg = histogram("h", "x (N)", &[1.0, 2.0, 2.5, f64::NAN], 5).unwrap();
    assert!(svg.starts_with("<svg"));
    assert_eq!(histogram("h", "x", &[f64::NAN], 5), Err(PlotError::Empty));
    let p = Panel {
        title: "joint 1".into(),
        y_label: "tau (N m)".into(),
        series: vec![("measured".into(), vec![(0.0, 1.0), (1.0, 2.0)])],
    };
    assert!(time_panels("t", &[p]).unwrap().contains("measured"));
}
