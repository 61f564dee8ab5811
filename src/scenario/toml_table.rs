//! One table of a scenario file whose keys depend on one of them, its tag (a surface's or a
//! fault's `kind`, `[selection]`'s `mode`, `[position]`'s `law`), read key by key: the tag,
//! every other key against the tag's list, and each value by its type, an error naming the
//! key's path (`faults[2].force_n`) and its line.

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

    /// The string at `tag` (`kind`, `mode`: what the table's other keys depend on), which must
    /// be there (`what` says what it names, for the message if not).
    pub(super) fn tag(&self, tag: &str, what: &str) -> Result<&'a str, ScenarioError> {
        match self.table.get(tag) {
            Some(Value::String(value)) => Ok(value.as_str()),
            Some(other) => Err(self.err(
                tag,
                format!("invalid type: {}, expected a string", other.type_str()),
            )),
            None => Err(self.err(tag, format!("is missing: {what}"))),
        }
    }

    /// The first key of the table that is neither `tag` nor in `allowed`, if any.
    pub(super) fn other_key(&self, tag: &str, allowed: &[&str]) -> Option<&'a str> {
        self.table
            .keys()
            .map(String::as_str)
            .find(|k| *k != tag && !allowed.contains(k))
    }

    /// The number at `name`, if there (an integer is taken as a number).
    pub(super) fn optional_number(&self, name: &str) -> Result<Option<f64>, ScenarioError> {
        self.optional(name, "a number", as_number)
    }

    /// The boolean at `name`, if there.
    pub(super) fn optional_bool(&self, name: &str) -> Result<Option<bool>, ScenarioError> {
        self.optional(name, "true or false", Value::as_bool)
    }

    /// The whole number (>= 0) at `name`, if there.
    pub(super) fn optional_count(&self, name: &str) -> Result<Option<u64>, ScenarioError> {
        match self.table.get(name) {
            Some(Value::Integer(i)) if *i < 0 => Err(self.err(
                name,
                format!("invalid value: {i}, expected a whole number >= 0"),
            )),
            _ => self.optional(name, "a whole number >= 0", as_count),
        }
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
                self.err(
                    name,
                    format!("invalid type: {}, expected {expected}", v.type_str()),
                )
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

/// `keys` as a file writes them (`` `a`, `b` ``), or "no other key".
pub(super) fn key_list(keys: &[&str]) -> String {
    if keys.is_empty() {
        "no other key".into()
    } else {
        let quoted: Vec<String> = keys.iter().map(|k| format!("`{k}`")).collect();
        quoted.join(", ")
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
