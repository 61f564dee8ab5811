//! The thesis's trials, assembled from the library's pieces (std only): reference sources
//! for the SCARA, the controller line-up of Chapters 4 and 5, and a runner that records
//! every sample.

mod controllers;
mod reference;
mod runner;

pub use controllers::{
    ForceController, ForceReference, GainReport, HybridSetup, PositionController, UnknownName,
};
pub use reference::ScaraReference;
pub use runner::{run, RunOutput};
