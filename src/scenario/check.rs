//! The checks every key of a scenario goes through: finite, in range, of the right length,
//! present where needed and absent where it does not belong; each failure an error naming
//! the file, the key (and line) and the rule.

use nalgebra::Vector3;

/// Largest normal force accepted, N (a larger one is most likely in the wrong unit).
pub const MAX_FORCE_N: f64 = 1e5;
/// Largest Coulomb coefficient accepted.
pub const MAX_FRICTION: f64 = 2.0;

use super::error::ScenarioError;

/// The file being checked, for messages.
pub(super) struct Checker<'a> {
    pub(super) file: &'a str,
    pub(super) source: &'a str,
}

impl Checker<'_> {
    pub(super) fn err(&self, key: &str, rule: impl Into<String>) -> ScenarioError {
        ScenarioError::at(self.file, self.source, key, rule)
    }

    pub(super) fn finite(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        in_range(v, f64::NEG_INFINITY, f64::INFINITY, false, "").map_err(|rule| self.err(key, rule))
    }

    /// `v` within `[lo, hi]` (bounds inclusive unless `open_lo`), else the rule `what`.
    pub(super) fn range(
        &self,
        key: &str,
        v: f64,
        lo: f64,
        hi: f64,
        open_lo: bool,
        what: &str,
    ) -> Result<f64, ScenarioError> {
        in_range(v, lo, hi, open_lo, what).map_err(|rule| self.err(key, rule))
    }

    /// A Coulomb friction coefficient at `key`: `v`, in `[0, MAX_FRICTION]`.
    pub(super) fn coulomb(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        let what = format!("a Coulomb coefficient, >= 0 and <= {MAX_FRICTION}");
        self.range(key, v, 0.0, MAX_FRICTION, false, &what)
    }

    pub(super) fn vec3(&self, key: &str, v: &[f64]) -> Result<Vector3<f64>, ScenarioError> {
        if v.len() != 3 {
            return Err(self.err(key, format!("needs 3 numbers [x, y, z], got {}", v.len())));
        }
        for x in v {
            self.finite(key, *x)?;
        }
        Ok(Vector3::new(v[0], v[1], v[2]))
    }

    pub(super) fn unit(&self, key: &str, v: &[f64]) -> Result<Vector3<f64>, ScenarioError> {
        let v = self.vec3(key, v)?;
        let n = v.norm();
        if n.is_nan() || n <= 1e-9 {
            return Err(self.err(
                key,
                "is zero; a direction needs a non-zero vector (it is normalised if not unit)",
            ));
        }
        Ok(v / n)
    }

    pub(super) fn forbid(&self, key: &str, present: bool, why: &str) -> Result<(), ScenarioError> {
        if present {
            Err(self.err(key, format!("does not belong here: {why}")))
        } else {
            Ok(())
        }
    }

    pub(super) fn need<T: Clone>(
        &self,
        key: &str,
        v: &Option<T>,
        why: &str,
    ) -> Result<T, ScenarioError> {
        v.clone()
            .ok_or_else(|| self.err(key, format!("is missing: {why}")))
    }

    /// Joint values at `key`: exactly `dof` finite numbers (`what` says which, e.g. "the
    /// robot's joints").
    pub(super) fn joints(
        &self,
        key: &str,
        v: &[f64],
        dof: usize,
        robot: &str,
        what: &str,
    ) -> Result<Vec<f64>, ScenarioError> {
        if v.len() != dof {
            return Err(self.err(
                key,
                format!(
                    "needs {dof} values ({what}, one per joint of `{robot}`, rad or m), got {}",
                    v.len()
                ),
            ));
        }
        for x in v {
            self.finite(key, *x)?;
        }
        Ok(v.to_vec())
    }
}

/// `n` numbers at `key`, each checked by `ok` (rule `what`), or `default` repeated when
/// absent.
pub(super) fn numbers(
    c: &Checker<'_>,
    key: &str,
    v: Option<&Vec<f64>>,
    n: usize,
    default: f64,
    ok: impl Fn(f64) -> bool,
    what: &str,
) -> Result<Vec<f64>, ScenarioError> {
    let Some(v) = v else {
        return Ok(vec![default; n]);
    };
    if v.len() != n {
        return Err(c.err(key, format!("needs {n} numbers ({what}), got {}", v.len())));
    }
    for (i, x) in v.iter().enumerate() {
        if !(x.is_finite() && ok(*x)) {
            return Err(c.err(key, format!("entry {i} = {x} is out of range: {what}")));
        }
    }
    Ok(v.clone())
}

/// `v` within `[lo, hi]` (bounds inclusive unless `open_lo`), else the rule it breaks (`what`).
/// Every finite `v` is within `(-inf, inf)`.
pub(super) fn in_range(v: f64, lo: f64, hi: f64, open_lo: bool, what: &str) -> Result<f64, String> {
    if !v.is_finite() {
        return Err(format!("{v} is not a finite number"));
    }
    let above = if open_lo { v > lo } else { v >= lo };
    if above && v <= hi {
        Ok(v)
    } else {
        Err(format!("{v} is out of range: {what}"))
    }
}
