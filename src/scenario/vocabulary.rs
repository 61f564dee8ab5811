//! What a scenario file can say about a robot beyond its model: the references it knows by
//! name (`[reference] kind = "thesis"`) and its own keys of `[reference]` (a SCARA's elbow
//! switch), which the reader refuses for every other robot. Reading a file
//! needs only this ([`RobotVocabulary`], found by name with
//! [`with_robot_named!`](crate::with_robot_named): the
//! reader does not depend on the runner, whose default planning reads scenarios); running it
//! needs the rest of [`ScenarioRobot`](super::ScenarioRobot). A robot without a module of
//! its own in `crate::robots` gets the defaults (`crate::robots` says which).

use crate::model::ParametricModel;

use super::planned::SharedTrajectory;

/// What a scenario file can name of a robot (see the [module documentation](self)).
pub trait RobotVocabulary<const N: usize>: ParametricModel<N> + Send + Sync {
    /// The named references (`[reference] kind = "thesis"`) of this robot.
    fn named_references() -> &'static [&'static str] {
        &[]
    }

    /// The named reference `name`, with `surface_z_m` (m) where it takes one; `None` if there
    /// is no such reference for this robot.
    fn named_reference(_name: &str, _surface_z_m: Option<f64>) -> Option<SharedTrajectory> {
        None
    }

    /// The robot's own keys of a scenario's `[reference]` table, beyond the generic ones (the
    /// SCARA's elbow switch and its settings).
    fn reference_keys() -> &'static [&'static str] {
        &[]
    }

    /// Checks the robot's own `[reference]` keys of a scenario, `keys` (those of
    /// [`Self::reference_keys`] the file gives).
    ///
    /// # Errors
    ///
    /// [`KeyError`] naming the key at fault and the rule it breaks.
    fn check_reference_keys(_keys: &toml::Table) -> Result<(), KeyError> {
        Ok(())
    }
}

/// A robot's own key of a scenario file that is wrong: the key (in its table) and the rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KeyError {
    /// The key, as written in its table (`elbow_switch`).
    pub key: String,
    /// What is wrong with it.
    pub rule: String,
}

impl KeyError {
    /// The error on `key`: `rule`.
    pub fn new(key: &str, rule: impl Into<String>) -> Self {
        Self {
            key: key.to_owned(),
            rule: rule.into(),
        }
    }
}

/// The string at `key` of `keys`, `None` if absent.
///
/// # Errors
///
/// [`KeyError`] if the value is not a string.
pub fn string<'a>(keys: &'a toml::Table, key: &str) -> Result<Option<&'a str>, KeyError> {
    keys.get(key)
        .map(|v| {
            v.as_str()
                .ok_or_else(|| KeyError::new(key, format!("{v} is not a string")))
        })
        .transpose()
}

/// The number at `key` of `keys` (an integer reads as one) within `[lo, hi]` (`lo` excluded
/// if `open_lo`), else the rule `what`; `None` if absent.
///
/// # Errors
///
/// [`KeyError`] if the value is not a number or out of range.
pub fn number_in(
    keys: &toml::Table,
    key: &str,
    (lo, hi, open_lo): (f64, f64, bool),
    what: &str,
) -> Result<Option<f64>, KeyError> {
    let Some(v) = keys.get(key) else {
        return Ok(None);
    };
    let x = (v.as_float().or_else(|| v.as_integer().map(|i| i as f64)))
        .ok_or_else(|| format!("{v} is not a number"))
        .and_then(|x| super::check::in_range(x, lo, hi, open_lo, what));
    x.map(Some).map_err(|rule| KeyError::new(key, rule))
}
