//! Long runs: a limit on their length, checked before they start (`--max-steps`), and
//! progress while they run: a bar with an ETA on a terminal (after the first second), a
//! plain line every few seconds otherwise (a log, a pipe, CI).

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use anyhow::{bail, Context};
use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use armdyn::model::JointVector;
use armdyn::scenario::{run_duration, Scenario};
use armdyn::sim::{Sample, SimConfig};

/// Default of `--max-steps`.
pub const DEFAULT_MAX_STEPS: u64 = 100_000_000;

/// `--max-steps`, for every command that simulates.
#[derive(Debug, Clone, Copy, Args)]
pub struct StepLimit {
    /// Refuse, before it starts, a run of more RK4 plant steps than this (a typo in a time
    /// or a step can otherwise ask for hours of simulation).
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_STEPS)]
    pub max_steps: u64,
}

impl Default for StepLimit {
    fn default() -> Self {
        Self {
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

impl StepLimit {
    /// Refuses a run of `steps` plant steps beyond the limit, naming the run (`what`), where
    /// the count comes from (`how`) and the option that allows it.
    pub fn check(&self, what: &str, steps: u64, how: &str) -> anyhow::Result<()> {
        if steps <= self.max_steps {
            return Ok(());
        }
        bail!(
            "{what}: the run would take {steps} plant steps ({how}), more than the limit of {} \
             (--max-steps); nothing was simulated. To run it anyway, pass --max-steps {steps}",
            self.max_steps
        )
    }

    /// [`Self::check_run`] for a scenario, before its reference is planned.
    pub fn check_scenario(&self, what: &str, scenario: &Scenario) -> anyhow::Result<()> {
        self.check_run(
            what,
            &scenario.robot,
            run_duration(scenario),
            scenario.control_dt_s,
            scenario.plant_dt_s,
        )
    }

    /// [`Self::check`] for a closed-loop run of `robot`: `duration` s of control periods
    /// `control_dt` of plant steps `plant_dt`, counted as the simulator counts them.
    pub fn check_run(
        &self,
        what: &str,
        robot: &str,
        duration: f64,
        control_dt: f64,
        plant_dt: f64,
    ) -> anyhow::Result<()> {
        armdyn::with_robot_named!(robot, |model: R, N, _module| {
            let config = SimConfig {
                duration,
                control_dt,
                plant_dt,
                q0: JointVector::<N>::zeros(),
                ..SimConfig::new(&model)
            };
            self.check_config(what, &config)
        })
        .unwrap_or_else(|| bail!("{what}: unknown robot `{robot}`"))
    }

    /// [`Self::check`] for a closed-loop run with `config`; then, since the run keeps every
    /// control sample, whether they fit in memory.
    pub fn check_config<const N: usize>(
        &self,
        what: &str,
        config: &SimConfig<N>,
    ) -> anyhow::Result<()> {
        let steps = config
            .plant_steps()
            .with_context(|| format!("{what}: nothing was simulated"))?;
        self.check(
            what,
            steps,
            &format!(
                "{} s at a plant step of {} s",
                num(config.duration),
                num(config.plant_dt)
            ),
        )?;
        let samples = ((config.duration / config.control_dt).round() as usize).saturating_add(1);
        let mut probe: Vec<Sample<N>> = Vec::new();
        if probe.try_reserve_exact(samples).is_err() {
            bail!(
                "{what}: the run would keep {samples} control samples of {} bytes each, more \
                 than this machine can hold; nothing was simulated. Use a longer --control-dt \
                 or a shorter run",
                std::mem::size_of::<Sample<N>>()
            );
        }
        Ok(())
    }
}

/// A number for a message: `0.001`, `2.5`, `10.776435` (at most 6 decimals), `1e-10`, `1e9`.
pub fn num(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        let fixed = format!("{x:.6}");
        fixed.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

/// Where a bar is drawn (a terminal), or a line written every [`LINE_EVERY`].
enum Mode {
    Bar { bar: ProgressBar, shown: bool },
    Lines { sink: Box<dyn Write>, next: Instant },
}

/// A bar appears once a run has taken this long (shorter runs stay quiet).
const BAR_AFTER: Duration = Duration::from_secs(1);
/// Without a terminal, a line this often (the first after this long).
const LINE_EVERY: Duration = Duration::from_secs(5);
/// Positions of the bar.
const BAR_LENGTH: u64 = 10_000;
/// [`Progress::step`] looks at the clock once per this many calls.
const STEP_STRIDE: u32 = 1024;

/// Progress of one run over simulated time `[t0, t_end]`.
pub struct Progress {
    name: String,
    t0: f64,
    t_end: f64,
    started: Instant,
    calls: u32,
    mode: Mode,
}

impl Progress {
    /// Starts reporting on stderr: a bar if it is a terminal, else lines.
    pub fn start(name: &str, t0: f64, t_end: f64) -> Self {
        let now = Instant::now();
        if std::io::stderr().is_terminal() {
            let style = ProgressStyle::with_template(
                "{prefix}: [{bar:30}] {percent:>3}% {msg}, {elapsed} elapsed, ETA {eta}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> ");
            // Hidden until BAR_AFTER: a short run draws nothing.
            let bar = ProgressBar::with_draw_target(Some(BAR_LENGTH), ProgressDrawTarget::hidden())
                .with_style(style)
                .with_prefix(name.to_owned());
            Self::new(name, t0, t_end, now, Mode::Bar { bar, shown: false })
        } else {
            Self::lines(name, t0, t_end, Box::new(std::io::stderr()), now)
        }
    }

    /// Lines into `sink`, the first one [`LINE_EVERY`] after `now`.
    fn lines(name: &str, t0: f64, t_end: f64, sink: Box<dyn Write>, now: Instant) -> Self {
        let next = now + LINE_EVERY;
        Self::new(name, t0, t_end, now, Mode::Lines { sink, next })
    }

    fn new(name: &str, t0: f64, t_end: f64, started: Instant, mode: Mode) -> Self {
        Self {
            name: name.to_owned(),
            t0,
            t_end,
            started,
            calls: 0,
            mode,
        }
    }

    /// The run has reached simulated time `t`.
    pub fn update(&mut self, t: f64) {
        self.update_at(t, Instant::now());
    }

    /// [`Self::update`] for a caller that reports after every plant step: only one call in
    /// [`STEP_STRIDE`] looks at the clock.
    pub fn step(&mut self, t: f64) {
        self.calls = self.calls.wrapping_add(1);
        if self.calls.is_multiple_of(STEP_STRIDE) {
            self.update(t);
        }
    }

    /// Fraction of the run done at `t`, in `[0, 1]`.
    fn fraction(&self, t: f64) -> f64 {
        let span = self.t_end - self.t0;
        if span > 0.0 {
            ((t - self.t0) / span).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    fn update_at(&mut self, t: f64, now: Instant) {
        let fraction = self.fraction(t);
        let elapsed = now.saturating_duration_since(self.started);
        let message = format!("t = {t:.2} of {:.2} s", self.t_end);
        let line = match &mut self.mode {
            Mode::Bar { bar, shown } => {
                bar.set_position((fraction * BAR_LENGTH as f64) as u64);
                bar.set_message(message);
                if !*shown && elapsed >= BAR_AFTER {
                    bar.set_draw_target(ProgressDrawTarget::stderr());
                    *shown = true;
                }
                return;
            }
            Mode::Lines { next, .. } if now < *next => return,
            Mode::Lines { .. } => {
                let left = remaining(fraction, elapsed)
                    .map_or("time left unknown".to_owned(), |d| {
                        format!("about {} left", human(d))
                    });
                format!(
                    "{}: {message} ({:.1} %), {} elapsed, {left}",
                    self.name,
                    100.0 * fraction,
                    human(elapsed)
                )
            }
        };
        if let Mode::Lines { sink, next } = &mut self.mode {
            // Progress is a courtesy: a closed stderr does not stop the run.
            let _ = writeln!(sink, "{line}");
            let _ = sink.flush();
            *next = now + LINE_EVERY;
        }
    }

    /// Ends the report (clears the bar).
    pub fn finish(self) {}
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Mode::Bar { bar, .. } = &self.mode {
            bar.finish_and_clear();
        }
    }
}

/// Time left at a constant rate, `None` before any progress.
fn remaining(fraction: f64, elapsed: Duration) -> Option<Duration> {
    if fraction <= 0.0 {
        return None;
    }
    Duration::try_from_secs_f64(elapsed.as_secs_f64() * (1.0 - fraction) / fraction).ok()
}

/// `45 s`, `3 min 20 s`, `2 h 05 min`, `12 d 3 h`.
fn human(d: Duration) -> String {
    let s = d.as_secs();
    match s {
        0..60 => format!("{s} s"),
        60..3600 => format!("{} min {} s", s / 60, s % 60),
        3600..86_400 => format!("{} h {:02} min", s / 3600, s % 3600 / 60),
        _ => format!("{} d {} h", s / 86_400, s % 86_400 / 3600),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::RefCell;
    use std::rc::Rc;

    #[derive(Clone, Default)]
    struct Shared(Rc<RefCell<Vec<u8>>>);

    impl Write for Shared {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.0.borrow_mut().extend_from_slice(buf);
            Ok(buf.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl Shared {
        fn text(&self) -> String {
            String::from_utf8(self.0.borrow().clone()).unwrap()
        }
    }

    #[test]
    fn without_a_terminal_a_line_every_few_seconds_with_the_time_left() {
        let sink = Shared::default();
        let t0 = Instant::now();
        let mut p = Progress::lines("run", 0.0, 10.0, Box::new(sink.clone()), t0);
        p.update_at(1.0, t0 + Duration::from_secs(2));
        assert_eq!(sink.text(), "", "nothing in the first seconds");
        p.update_at(2.5, t0 + Duration::from_secs(5));
        assert_eq!(
            sink.text(),
            "run: t = 2.50 of 10.00 s (25.0 %), 5 s elapsed, about 15 s left\n"
        );
        p.update_at(3.0, t0 + Duration::from_secs(9));
        assert_eq!(sink.text().lines().count(), 1, "not again before 5 s more");
        p.update_at(5.0, t0 + Duration::from_secs(600));
        assert!(
            sink.text().ends_with(
                "run: t = 5.00 of 10.00 s (50.0 %), 10 min 0 s elapsed, about 10 min 0 s left\n"
            ),
            "{}",
            sink.text()
        );
    }

    #[test]
    fn per_step_reports_look_at_the_clock_once_per_stride() {
        let sink = Shared::default();
        let long_ago = Instant::now() - Duration::from_secs(60);
        let mut p = Progress::lines("run", 0.0, 1.0, Box::new(sink.clone()), long_ago);
        for _ in 0..STEP_STRIDE - 1 {
            p.step(0.5);
        }
        assert_eq!(sink.text(), "");
        p.step(0.5);
        assert!(
            sink.text().starts_with("run: t = 0.50 of 1.00 s (50.0 %)"),
            "{}",
            sink.text()
        );
    }

    #[test]
    fn no_progress_yet_means_no_estimate() {
        let sink = Shared::default();
        let t0 = Instant::now();
        let mut p = Progress::lines("run", 0.0, 10.0, Box::new(sink.clone()), t0);
        p.update_at(0.0, t0 + Duration::from_secs(7));
        assert!(
            sink.text().ends_with("7 s elapsed, time left unknown\n"),
            "{}",
            sink.text()
        );
    }

    #[test]
    fn durations_read_well() {
        assert_eq!(human(Duration::from_secs(45)), "45 s");
        assert_eq!(human(Duration::from_secs(200)), "3 min 20 s");
        assert_eq!(human(Duration::from_secs(7500)), "2 h 05 min");
        assert_eq!(
            human(Duration::from_secs(12 * 86_400 + 3 * 3600 + 59)),
            "12 d 3 h"
        );
        assert_eq!(
            remaining(0.5, Duration::from_secs(3)),
            Some(Duration::from_secs(3))
        );
        assert_eq!(remaining(0.0, Duration::from_secs(3)), None);
    }

    #[test]
    fn numbers_read_well() {
        assert_eq!(num(0.001), "0.001");
        assert_eq!(num(2.5), "2.5");
        assert_eq!(num(0.0), "0");
        assert_eq!(num(1e-10), "1e-10");
        assert_eq!(num(1e9), "1e9");
        assert_eq!(num(-123456.0), "-123456");
        assert_eq!(num(10.776435003280639), "10.776435");
        assert_eq!(num(100.0), "100");
    }

    #[test]
    fn the_limit_names_the_steps_and_the_option() {
        let limit = StepLimit::default();
        assert!(limit.check("x", DEFAULT_MAX_STEPS, "").is_ok());
        let err = limit
            .check("tau.csv", 1_000_000_000_000, "t from 0 to 1000000000 s")
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "tau.csv: the run would take 1000000000000 plant steps (t from 0 to 1000000000 s), \
             more than the limit of 100000000 (--max-steps); nothing was simulated. To run it \
             anyway, pass --max-steps 1000000000000"
        );
        let err = limit
            .check_run("hybrid", "scara", 10.0, 1e-3, 1e-10)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("would take 100000000000 plant steps (10 s at a plant step of 1e-10 s)"),
            "{err}"
        );
        assert!(limit.check_run("hybrid", "scara", 10.0, 1e-3, 1e-3).is_ok());
        let err = limit
            .check_run("hybrid", "scara", 10.0, 1e-3, 0.0)
            .unwrap_err();
        assert!(
            format!("{err:#}").contains("plant step must be finite"),
            "{err:#}"
        );
    }
}
