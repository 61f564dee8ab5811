//! Why a deployable controller cannot be built from a design.

/// A design the deployable hybrid controller does not implement, or cannot invert.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DeployError {
    /// The task frame follows a surface; the deployable step has a fixed normal only.
    #[error("the deployable hybrid step needs a fixed task normal (TaskFrame::Fixed)")]
    SurfaceFrame,
    /// The fixed normal is not a finite unit vector.
    #[error("the task normal must be a finite unit vector")]
    Normal,
    /// The selection switches on contact; the deployable step switches at a time only.
    #[error("the deployable hybrid step switches at a time only (SelectionPolicy::Time)")]
    ContactSelection,
    /// `M_linear` of the position loop is singular.
    #[error("M_linear of the position loop is singular")]
    SingularLinearPart,
}
