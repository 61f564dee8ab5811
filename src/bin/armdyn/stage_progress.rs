//! Progress of a command made of stages (`armdyn identify --log`: reading, filtering, the
//! linear fit, the consistent fit, ...) on stderr: on a terminal, a spinner per stage with
//! what it has done so far, drawn once the stage has run for a second (a short stage draws
//! nothing); hidden when stderr is not a terminal (a log, a pipe, CI), as `armdyn sweep`'s
//! bar. The stages' times are printed by the command itself.

use std::io::{IsTerminal, Read};
use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use armdyn::identification::stages::{Event, Stage};

/// A stage's spinner appears once it has run this long.
const SHOW_AFTER: Duration = Duration::from_secs(1);
/// Spinner tick.
const TICK: Duration = Duration::from_millis(120);

/// The spinner of the running stage, and the thread that shows it after [`SHOW_AFTER`].
struct Running {
    bar: ProgressBar,
    /// Dropped or sent to when the stage ends before the spinner is shown.
    done: Sender<()>,
    shower: JoinHandle<()>,
}

/// Progress of stages, fed [`Event`]s.
pub struct StageProgress {
    terminal: bool,
    running: Option<Running>,
}

impl StageProgress {
    /// Progress on stderr if it is a terminal, else nothing.
    pub fn stderr() -> Self {
        Self {
            terminal: std::io::stderr().is_terminal(),
            running: None,
        }
    }

    /// Shows `event`.
    pub fn event(&mut self, event: Event<'_>) {
        if !self.terminal {
            return;
        }
        match event {
            Event::Start(stage) => {
                self.end();
                self.running = Some(start(stage));
            }
            Event::Progress { done, of, unit } => {
                if let Some(r) = &self.running {
                    r.bar.set_message(match of {
                        Some(of) => format!("{done} of {of} {unit}"),
                        None => format!("{done} {unit}"),
                    });
                }
            }
            Event::Finish(..) => self.end(),
        }
    }

    fn end(&mut self) {
        if let Some(r) = self.running.take() {
            let _ = r.done.send(());
            let _ = r.shower.join();
            r.bar.finish_and_clear();
        }
    }
}

impl Drop for StageProgress {
    fn drop(&mut self) {
        self.end();
    }
}

fn start(stage: Stage) -> Running {
    let style = ProgressStyle::with_template("{spinner} {prefix} ({elapsed}) {msg}")
        .unwrap_or_else(|_| ProgressStyle::default_spinner());
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden())
        .with_style(style)
        .with_prefix(stage.name());
    let (done, wait) = channel::<()>();
    let shown = bar.clone();
    let shower = std::thread::spawn(move || {
        if wait.recv_timeout(SHOW_AFTER) == Err(RecvTimeoutError::Timeout) {
            shown.set_draw_target(ProgressDrawTarget::stderr());
            shown.enable_steady_tick(TICK);
        }
    });
    Running { bar, done, shower }
}

/// A reader that reports the bytes read so far to `report` (for the reading stage's
/// progress).
pub struct CountingReader<R, F> {
    inner: R,
    count: u64,
    report: F,
}

impl<R, F: FnMut(u64)> CountingReader<R, F> {
    /// `inner`, counted.
    pub fn new(inner: R, report: F) -> Self {
        Self {
            inner,
            count: 0,
            report,
        }
    }
}

impl<R: Read, F: FnMut(u64)> Read for CountingReader<R, F> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.count += n as u64;
        (self.report)(self.count);
        Ok(n)
    }
}

/// `reading 0.05 s, filtering 1.20 s, ...; total 3.40 s`.
pub fn times_line(times: &[(Stage, f64)]) -> String {
    let parts: Vec<String> = times
        .iter()
        .map(|(s, t)| format!("{} {t:.2} s", s.name()))
        .collect();
    let total: f64 = times.iter().map(|(_, t)| t).sum();
    format!("{}; total {total:.2} s", parts.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_are_counted_as_they_are_read() {
        let mut seen = Vec::new();
        let mut r = CountingReader::new(&b"t,q1,tau1\n0,1,2\n"[..], |n| seen.push(n));
        let mut buf = [0u8; 10];
        assert_eq!(r.read(&mut buf).unwrap(), 10);
        let mut rest = Vec::new();
        r.read_to_end(&mut rest).unwrap();
        assert_eq!(rest, b"0,1,2\n");
        assert_eq!(seen.first(), Some(&10));
        assert_eq!(seen.last(), Some(&16));
    }

    #[test]
    fn without_a_terminal_nothing_is_drawn_and_the_times_read_well() {
        let mut p = StageProgress {
            terminal: false,
            running: None,
        };
        p.event(Event::Start(Stage::Filtering));
        assert!(p.running.is_none());
        assert_eq!(
            times_line(&[(Stage::Reading, 0.126), (Stage::ConsistentFit, 2.0)]),
            "reading 0.13 s, consistent fit 2.00 s; total 2.13 s"
        );
    }

    #[test]
    fn a_short_stage_draws_nothing_and_ends_cleanly() {
        let mut p = StageProgress {
            terminal: true,
            running: None,
        };
        p.event(Event::Start(Stage::LinearFit));
        p.event(Event::Progress {
            done: 3,
            of: Some(10),
            unit: "evaluations",
        });
        assert!(p.running.as_ref().unwrap().bar.is_hidden());
        p.event(Event::Finish(Stage::LinearFit, 0.0));
        assert!(p.running.is_none());
    }
}
