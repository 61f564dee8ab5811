//! Physical consistency of an estimate, where base parameters allow a check.
//!
//! A base parameter is a combination; most mix first moments (of either sign) into inertias
//! and say nothing about one body. Two things can be checked: a base parameter whose every
//! term is a mass, a diagonal moment of inertia about a frame origin (never negative for a
//! real body) or a friction coefficient, with positive coefficients, must be positive; and
//! where a link's `Ixx`, `Iyy`, `Izz` are each a base parameter on their own, they must
//! satisfy the triangle inequality.

use super::base::BaseParameters;

/// One check and its outcome.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// What is checked, e.g. `m3 + m4 > 0`.
    pub rule: String,
    /// Whether the estimate meets it.
    pub ok: bool,
}

/// The checks that can be made on an estimate.
#[derive(Clone, Debug, PartialEq)]
pub struct Consistency {
    /// Every check made.
    pub checks: Vec<Check>,
    /// Base parameters that no check covers.
    pub not_checkable: usize,
}

impl Consistency {
    /// Whether every check passed.
    #[must_use]
    pub fn all_ok(&self) -> bool {
        self.checks.iter().all(|c| c.ok)
    }

    /// One sentence for reports.
    #[must_use]
    pub fn summary(&self) -> String {
        let failed: Vec<&str> = self
            .checks
            .iter()
            .filter(|c| !c.ok)
            .map(|c| c.rule.as_str())
            .collect();
        let head = if failed.is_empty() {
            format!(
                "{} of {} checks passed",
                self.checks.len(),
                self.checks.len()
            )
        } else {
            format!(
                "{} of {} checks failed: {}",
                failed.len(),
                self.checks.len(),
                failed.join("; ")
            )
        };
        format!(
            "{head}; {} base parameters mix first moments or products of inertia and cannot be checked on their own",
            self.not_checkable
        )
    }
}

fn sign_definite(term: &str) -> bool {
    let t = term.trim();
    let is = |p: &str| {
        t.strip_prefix(p)
            .is_some_and(|rest| !rest.is_empty() && rest.chars().all(|c| c.is_ascii_digit()))
    };
    is("m") || is("Ixx") || is("Iyy") || is("Izz") || is("fv") || is("fc")
}

/// Checks `estimate` (base parameters in the order of `base`).
#[must_use]
pub fn check(base: &BaseParameters, estimate: &[f64]) -> Consistency {
    let names = base.names();
    let mut checks = Vec::new();
    let mut not_checkable = 0;
    for (name, value) in names.iter().zip(estimate) {
        // "a + 0.16 b - c": terms with their signs.
        let mut positive = true;
        let mut definite = true;
        for part in name.replace(" - ", " + -").split(" + ") {
            positive &= !part.starts_with('-');
            let term = part
                .trim_start_matches('-')
                .split_whitespace()
                .filter(|w| w.parse::<f64>().is_err())
                .collect::<Vec<_>>()
                .join(" ");
            definite &= sign_definite(&term);
        }
        if definite && positive {
            checks.push(Check {
                rule: format!("{name} > 0 (estimated {value:.6e})"),
                ok: *value > 0.0,
            });
        } else {
            not_checkable += 1;
        }
    }
    let bare = |n: &str| names.iter().position(|x| x == n).map(|i| estimate[i]);
    let links = base
        .parameter_names()
        .iter()
        .filter_map(|n| n.strip_prefix("Ixx"))
        .filter_map(|j| j.parse::<usize>().ok())
        .collect::<Vec<_>>();
    for j in links {
        if let (Some(a), Some(b), Some(c)) = (
            bare(&format!("Ixx{j}")),
            bare(&format!("Iyy{j}")),
            bare(&format!("Izz{j}")),
        ) {
            checks.push(Check {
                rule: format!("triangle inequality of link {j}'s Ixx, Iyy, Izz"),
                ok: a + b >= c && b + c >= a && a + c >= b,
            });
        }
    }
    Consistency {
        checks,
        not_checkable,
    }
}
