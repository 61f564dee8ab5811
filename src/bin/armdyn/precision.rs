//! `--precision`: which arithmetic runs a scenario's controller.

use armdyn::scenario::{
    prepare, prepare_deployed, prepare_deployed_for, prepare_for, Prepared, PreparedRun, Scenario,
    ScenarioError, ScenarioRobot,
};
use clap::ValueEnum;

/// The controller a scenario runs with.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// The library's controllers (`f64`), as the scenario names them.
    #[default]
    Reference,
    /// The robot's deployable hybrid step (the SCARA's `armdyn::robots::scara::deploy`) in
    /// `f64`.
    F64,
    /// The deployable hybrid step in `f32`, as a Cortex-M4F's FPU would run it.
    F32,
}

impl Precision {
    /// [`prepare`], or [`prepare_deployed`] in the chosen precision.
    pub fn prepare(self, s: &Scenario) -> Result<Prepared, ScenarioError> {
        match self {
            Self::Reference => prepare(s),
            Self::F64 => prepare_deployed(s, armdyn::scenario::Precision::F64),
            Self::F32 => prepare_deployed(s, armdyn::scenario::Precision::F32),
        }
    }

    /// [`Self::prepare`] on the scenario's robot `robot`, typed: the run keeps its samples.
    pub fn prepare_for<const N: usize, R: ScenarioRobot<N>>(
        self,
        s: &Scenario,
        robot: R,
    ) -> Result<PreparedRun<N, R>, ScenarioError> {
        match self {
            Self::Reference => prepare_for(s, robot),
            Self::F64 => prepare_deployed_for(s, robot, armdyn::scenario::Precision::F64),
            Self::F32 => prepare_deployed_for(s, robot, armdyn::scenario::Precision::F32),
        }
    }
}
