//! Settling time: how long after a start a signal's error last left a band around zero
//! (the force metrics' 5 % band), accumulated without allocation.

/// The last time the error was outside `±band`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settling {
    band: f64,
    last_outside_s: Option<f64>,
}

impl Settling {
    /// A band of half-width `band` (the error's unit, for instance N).
    #[must_use]
    pub fn new(band: f64) -> Self {
        Self {
            band,
            last_outside_s: None,
        }
    }

    /// Adds the error `error` at time `t` (s).
    pub fn push(&mut self, t: f64, error: f64) {
        if error.abs() > self.band {
            self.last_outside_s = Some(t);
        }
    }

    /// The settling time from `start_s` of a run ending at `end_s` (s): zero if the error
    /// never left the band, `None` if it was still outside at the end (within 1e-9 s), else
    /// the last time outside less `start_s`.
    #[must_use]
    pub fn time_after(&self, start_s: f64, end_s: f64) -> Option<f64> {
        match self.last_outside_s {
            None => Some(0.0),
            Some(t) if t >= end_s - 1e-9 => None,
            Some(t) => Some(t - start_s),
        }
    }
}
