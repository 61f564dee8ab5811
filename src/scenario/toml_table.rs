//! One table of a scenario file whose keys depend on its `kind` (a surface, a fault), read key
//! by key: its `kind`, every other key against the kind's list, and each value by its type,
//! an error naming the key's path (`faults[2].force_n`) and its line.

use toml::{Table, Value};

use super::check::Checker;
use super::error::ScenarioError;

/// The table `table` at `at` (`surfaces[0]`, `faults[2]`) of the file `c` checks.
pub(super) struct TomlTable<'a> {
    pub(super) c: &'a Checker<'a>,
    pub(super) at: &'a str,
    pub(super) table: &'a Table,
}

impl<'a> TomlTable<'a> {
    /// The path of key `name`: `at.name`.
    pub(super) fn path(&self, name: &str) -> String {
        format!("{}.{name}", self.at)
    }

    /// An error at key `name` breaking `rule`.
    pub(super) fn err(&self, name: &str, rule: impl Into<String>) -> ScenarioError {
        self.c.err(&self.path(name), rule)
    }

    /// The string at `kind`, which must be there (`what` says what it names, for the message
    /// if not).
    pub(super) fn kind(&self, what: &str) -> Result<&'a str, ScenarioError> {
        match self.table.get("kind") {
            Some(Value::String(kind)) => Ok(kind.as_str()),
            Some(other) => Err(self.err(
                "kind",
                format!("invalid type: {}, expected a string", other.type_str()),
            )),
            None => Err(self.err("kind", format!("is missing: {what}"))),
        }
    }

    /// The first key of the table that is neither `kind` nor in `allowed`, if any.
    pub(super) fn other_key(&self, allowed: &[&str]) -> Option<&'a str> {
        self.table
            .keys()
            .map(String::as_str)
            .find(|k| *k != "kind" && !allowed.contains(k))
    }

    /// The number at `name`, if there (an integer is taken as a number).
    pub(super) fn optional_number(&self, name: &str) -> Result<Option<f64>, ScenarioError> {
        self.optional(name, "a number", as_number)
    }

    /// The whole number (>= 0) at `name`, if there.
    pub(super) fn optional_count(&self, name: &str) -> Result<Option<u64>, ScenarioError> {
        self.optional(name, "a whole number >= 0", as_count)
    }

    /// The numbers at `name`, if there.
    pub(super) fn optional_numbers(&self, name: &str) -> Result<Option<Vec<f64>>, ScenarioError> {
        self.optional_array(name, ("a number", "numbers"), as_number)
    }

    /// The whole numbers (>= 0) at `name`, if there.
    pub(super) fn optional_counts(&self, name: &str) -> Result<Option<Vec<u64>>, ScenarioError> {
        self.optional_array(
            name,
            ("a whole number >= 0", "whole numbers >= 0"),
            as_count,
        )
    }

    /// The numbers at `name`, which must be there (`what` for the message if not).
    pub(super) fn numbers(&self, name: &str, what: &str) -> Result<Vec<f64>, ScenarioError> {
        self.optional_numbers(name)?
            .ok_or_else(|| self.err(name, format!("is missing: {what}")))
    }

    fn optional<T>(
        &self,
        name: &str,
        expected: &str,
        read: fn(&Value) -> Option<T>,
    ) -> Result<Option<T>, ScenarioError> {
        match self.table.get(name) {
            None => Ok(None),
            Some(v) => read(v).map(Some).ok_or_else(|| {
                let found = match v {
                    Value::Integer(i) => format!("invalid value: {i}"),
                    _ => format!("invalid type: {}", v.type_str()),
                };
                self.err(name, format!("{found}, expected {expected}"))
            }),
        }
    }

    /// `expected`: what one entry is, and what they are.
    fn optional_array<T>(
        &self,
        name: &str,
        (one, many): (&str, &str),
        read: fn(&Value) -> Option<T>,
    ) -> Result<Option<Vec<T>>, ScenarioError> {
        match self.table.get(name) {
            None => Ok(None),
            Some(Value::Array(items)) => items
                .iter()
                .map(read)
                .collect::<Option<Vec<T>>>()
                .map(Some)
                .ok_or_else(|| self.err(name, format!("invalid type: an entry is not {one}"))),
            Some(v) => Err(self.err(
                name,
                format!(
                    "invalid type: {}, expected an array of {many}",
                    v.type_str()
                ),
            )),
        }
    }
}

/// A TOML number (integer or float) as `f64`.
pub(crate) fn as_number(v: &Value) -> Option<f64> {
    match v {
        Value::Float(x) => Some(*x),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// A TOML integer >= 0.
fn as_count(v: &Value) -> Option<u64> {
    match v {
        Value::Integer(i) => u64::try_from(*i).ok(),
        _ => None,
    }
}
