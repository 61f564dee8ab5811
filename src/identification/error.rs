//! What can go wrong in an identification.

/// An identification that cannot be done as asked.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum IdentificationError {
    /// The two rank tests of the stacked regressor disagree: the tolerance does not separate
    /// the identifiable combinations from rounding (more or other states are needed).
    #[error("base parameters: the column-by-column rank ({greedy}) and the SVD rank ({svd}) of the stacked regressor disagree at tolerance {tolerance:e}")]
    RankMismatch {
        /// Independent columns found one by one.
        greedy: usize,
        /// Singular values above the tolerance.
        svd: usize,
        /// Relative tolerance.
        tolerance: f64,
    },
    /// A setting is out of range.
    #[error("{0}")]
    Setting(String),
    /// The measurement run failed.
    #[error("measurement run: {0}")]
    Simulation(String),
    /// Least squares had too few rows or a rank-deficient base regressor.
    #[error("estimation: {0}")]
    Estimation(String),
}
