//! The events a run's viewer marks, from its `metrics.json`: the first touch, the switch to
//! force control, the contact detection, each fault and each trip.

use serde_json::Value;

/// One event: its time, s, and what the page shows.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewEvent {
    /// Time, s.
    pub t_s: f64,
    /// The text shown.
    pub text: String,
}

/// The events of a run's metrics (the object `metrics.json` holds), by time. Keys a run did
/// not write, or of another type, give no event.
#[must_use]
pub fn events_from_metrics(metrics: &Value) -> Vec<ViewEvent> {
    let mut out = Vec::new();
    let mut at = |t: Option<f64>, text: String| {
        if let Some(t_s) = t.filter(|t| t.is_finite()) {
            out.push(ViewEvent { t_s, text });
        }
    };
    at(metrics["first_touch_s"].as_f64(), "first touch".into());
    at(
        metrics["contact_detected_s"].as_f64(),
        "contact detected".into(),
    );
    at(
        metrics["force_control_start_s"].as_f64(),
        "switch to force control".into(),
    );
    for f in metrics["faults"].as_array().into_iter().flatten() {
        let kind = f["kind"].as_str().unwrap_or("fault");
        at(f["start_s"].as_f64(), format!("fault: {kind}"));
    }
    for t in metrics["safety_trips"].as_array().into_iter().flatten() {
        let cause = t["cause"].as_str().unwrap_or("trip");
        let reaction = t["reaction"].as_str().unwrap_or("-");
        at(t["t_s"].as_f64(), format!("trip: {cause}, {reaction}"));
    }
    out.sort_by(|a, b| a.t_s.total_cmp(&b.t_s));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn the_events_of_a_run_by_time_and_nothing_from_missing_keys() {
        let m = json!({
            "first_touch_s": 2.0,
            "contact_detected_s": null,
            "force_control_start_s": 2.0,
            "faults": [{"kind": "dropout", "start_s": 5.0}],
            "safety_trips": [{"cause": "sensor-stale", "t_s": 5.02, "reaction": "hold"}],
        });
        let e = events_from_metrics(&m);
        let texts: Vec<&str> = e.iter().map(|e| e.text.as_str()).collect();
        assert_eq!(
            texts,
            [
                "first touch",
                "switch to force control",
                "fault: dropout",
                "trip: sensor-stale, hold"
            ]
        );
        assert!(events_from_metrics(&json!([1, 2])).is_empty());
    }
}
