//! Errors of the model layer.

/// What can go wrong when solving the equation of motion.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// An input held NaN or an infinity.
    #[error("{what}[{index}] is not finite ({value})")]
    NonFinite {
        /// Which input: `"q"`, `"qd"`, `"qdd"`, `"tau"` or `"tau_ext"`.
        what: &'static str,
        /// The joint index, from 0.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The matrix to factorise is not (numerically) symmetric positive definite: the
    /// pivot of row `index` was `pivot <= 0` or not finite.
    #[error("matrix is not positive definite: pivot {index} is {pivot}")]
    NotPositiveDefinite {
        /// The row, from 0, where the factorisation broke down.
        index: usize,
        /// The value under the square root at that row.
        pivot: f64,
    },
}
