//! The stages of an identification from a log, for progress while they run and their times
//! afterwards: [`Stage`], the [`Event`]s an observer receives, and [`StageTimer`], which sends
//! them and keeps the times.

use std::time::Instant;

/// A stage of the work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// Reading the log file (timed by the caller that reads it).
    Reading,
    /// Resampling, filtering and differentiating the estimation and validation parts.
    Filtering,
    /// Base parameters, the stacked regressor, the friction slopes and the weighted least
    /// squares.
    LinearFit,
    /// The physically consistent fit (and the unconstrained one it is compared with).
    ConsistentFit,
    /// Predictions and errors on the held-out samples.
    Validation,
    /// Drawing the figures (timed by the caller that draws them).
    Figures,
}

impl Stage {
    /// `reading`, `filtering`, `linear fit`, `consistent fit`, `validation`, `figures`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Reading => "reading",
            Self::Filtering => "filtering",
            Self::LinearFit => "linear fit",
            Self::ConsistentFit => "consistent fit",
            Self::Validation => "validation",
            Self::Figures => "figures",
        }
    }

    /// The name as a JSON key: `reading`, `filtering`, `linear_fit`, ...
    #[must_use]
    pub fn key(self) -> String {
        self.name().replace(' ', "_")
    }
}

/// What an observer of the stages is told.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event<'a> {
    /// A stage starts.
    Start(Stage),
    /// Progress within the stage: `done` of `of` (when known) `unit`.
    Progress {
        /// Done so far.
        done: u64,
        /// Out of (a budget, a size), when known.
        of: Option<u64>,
        /// What is counted (`evaluations`, `bytes`, ...).
        unit: &'a str,
    },
    /// The stage ended after `seconds`.
    Finish(Stage, f64),
}

/// Times stages and tells `observer` about them.
pub struct StageTimer<'o> {
    observer: &'o mut dyn FnMut(Event<'_>),
    current: Option<(Stage, Instant)>,
    times: Vec<(Stage, f64)>,
}

impl<'o> StageTimer<'o> {
    /// A timer reporting to `observer`.
    pub fn new(observer: &'o mut dyn FnMut(Event<'_>)) -> Self {
        Self {
            observer,
            current: None,
            times: Vec::new(),
        }
    }

    /// Ends the current stage (if any) and starts `stage`.
    pub fn start(&mut self, stage: Stage) {
        self.finish();
        (self.observer)(Event::Start(stage));
        self.current = Some((stage, Instant::now()));
    }

    /// Progress within the current stage.
    pub fn progress(&mut self, done: u64, of: Option<u64>, unit: &str) {
        (self.observer)(Event::Progress { done, of, unit });
    }

    /// Ends the current stage, if any.
    pub fn finish(&mut self) {
        if let Some((stage, at)) = self.current.take() {
            let s = at.elapsed().as_secs_f64();
            self.times.push((stage, s));
            (self.observer)(Event::Finish(stage, s));
        }
    }

    /// Ends the current stage and gives the times, in order.
    #[must_use]
    pub fn times(mut self) -> Vec<(Stage, f64)> {
        self.finish();
        self.times
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stages_are_told_and_timed_in_order() {
        let mut seen = Vec::new();
        let mut observer = |e: Event<'_>| {
            seen.push(match e {
                Event::Start(s) => format!("start {}", s.name()),
                Event::Progress { done, of, unit } => format!("{done}/{of:?} {unit}"),
                Event::Finish(s, t) => {
                    assert!(t >= 0.0);
                    format!("end {}", s.key())
                }
            });
        };
        let mut timer = StageTimer::new(&mut observer);
        timer.start(Stage::Filtering);
        timer.progress(1, Some(2), "parts");
        timer.start(Stage::ConsistentFit);
        let times = timer.times();
        assert_eq!(
            times.iter().map(|(s, _)| *s).collect::<Vec<_>>(),
            [Stage::Filtering, Stage::ConsistentFit]
        );
        assert_eq!(
            seen,
            [
                "start filtering",
                "1/Some(2) parts",
                "end filtering",
                "start consistent fit",
                "end consistent_fit"
            ]
        );
    }
}
