//! `[[surfaces]]` checked: the kind and its shape's settings (read through
//! [`SettingsReader`], so a new shape needs nothing here), the stiffness, damping and
//! friction every surface has. Any other key is refused, naming the kind's keys.

use toml::{Table, Value};

use super::check::Checker;
use super::error::ScenarioError;
use crate::contact::{ContactSurface, SurfaceGeometry};
use crate::surface::SettingsReader;

/// The keys every surface has besides its shape's.
const COMMON_KEYS: [&str; 4] = ["kind", "stiffness", "damping", "friction"];

/// Surface `key` (`surfaces[i]`) of the file, its table `s`.
pub(super) fn surface(
    c: &Checker<'_>,
    key: &str,
    s: &Table,
) -> Result<ContactSurface, ScenarioError> {
    let mut r = TomlSettings { c, key, s };
    let kinds = SurfaceGeometry::KINDS.join(", ");
    let kind = match s.get("kind") {
        Some(Value::String(kind)) => kind.as_str(),
        Some(other) => {
            return Err(r.err(
                "kind",
                format!("invalid type: {}, expected a string", other.type_str()),
            ))
        }
        None => return Err(r.err("kind", format!("is missing: the shape, one of {kinds}"))),
    };
    let unknown = || {
        c.err(
            &format!("{key}.kind"),
            format!("unknown surface kind `{kind}`; known: {kinds}"),
        )
    };
    let Some(shape_keys) = SurfaceGeometry::keys_of(kind) else {
        return Err(unknown());
    };
    for k in s.keys() {
        if COMMON_KEYS.contains(&k.as_str()) || shape_keys.contains(&k.as_str()) {
            continue;
        }
        let keys = shape_keys
            .iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>();
        let own = format!("a {kind} has {}", keys.join(", "));
        let another_kind = SurfaceGeometry::KINDS.iter().any(|other| {
            SurfaceGeometry::keys_of(other).is_some_and(|ks| ks.contains(&k.as_str()))
        });
        return Err(r.err(
            k,
            if another_kind {
                format!("does not belong here: {own}")
            } else {
                format!("unknown field `{k}`: {own}; every surface has `kind`, `stiffness`, `damping` and `friction`")
            },
        ));
    }
    let geometry = SurfaceGeometry::read(kind, &mut r).ok_or_else(unknown)??;
    let stiffness = r.number("stiffness", "a stiffness in N/m")?;
    Ok(ContactSurface {
        geometry,
        stiffness: c.range(
            &r.path("stiffness"),
            stiffness,
            0.0,
            1e9,
            true,
            "a stiffness in N/m, > 0",
        )?,
        damping: c.range(
            &r.path("damping"),
            r.optional_number("damping")?.unwrap_or(0.0),
            0.0,
            1e7,
            false,
            "a damping in N s/m, >= 0",
        )?,
        friction: c.coulomb(
            &r.path("friction"),
            r.optional_number("friction")?.unwrap_or(0.0),
        )?,
    })
}

/// The table `s` of surface `key` in the file `c` checks.
struct TomlSettings<'a> {
    c: &'a Checker<'a>,
    key: &'a str,
    s: &'a Table,
}

impl TomlSettings<'_> {
    fn path(&self, name: &str) -> String {
        format!("{}.{name}", self.key)
    }

    fn err(&self, name: &str, rule: impl Into<String>) -> ScenarioError {
        self.c.err(&self.path(name), rule)
    }

    /// The number at `name`, if there (an integer is taken as a number).
    fn optional_number(&self, name: &str) -> Result<Option<f64>, ScenarioError> {
        match self.s.get(name) {
            None => Ok(None),
            Some(v) => as_number(v).map(Some).ok_or_else(|| {
                self.err(
                    name,
                    format!("invalid type: {}, expected a number", v.type_str()),
                )
            }),
        }
    }

    /// The numbers at `name`, which must be there (`what` for the message if not).
    fn array(&self, name: &str, what: &str) -> Result<Vec<f64>, ScenarioError> {
        match self.s.get(name) {
            None => Err(self.err(name, format!("is missing: {what}"))),
            Some(Value::Array(items)) => items
                .iter()
                .map(as_number)
                .collect::<Option<Vec<f64>>>()
                .ok_or_else(|| self.err(name, "invalid type: an entry is not a number")),
            Some(v) => Err(self.err(
                name,
                format!(
                    "invalid type: {}, expected an array of numbers",
                    v.type_str()
                ),
            )),
        }
    }
}

/// A TOML number (integer or float) as `f64`.
fn as_number(v: &Value) -> Option<f64> {
    match v {
        Value::Float(x) => Some(*x),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

impl SettingsReader for TomlSettings<'_> {
    type Error = ScenarioError;

    fn number(&mut self, key: &'static str, what: &'static str) -> Result<f64, ScenarioError> {
        let x = self
            .optional_number(key)?
            .ok_or_else(|| self.err(key, format!("is missing: {what}")))?;
        self.c.finite(&self.path(key), x)
    }

    fn numbers<const N: usize>(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<[f64; N], ScenarioError> {
        let v = self.array(key, what)?;
        let Ok(v) = <[f64; N]>::try_from(v.as_slice()) else {
            return Err(self.err(key, format!("needs {N} numbers ({what}), got {}", v.len())));
        };
        for x in v {
            self.c.finite(&self.path(key), x)?;
        }
        Ok(v)
    }

    fn refuse(&mut self, key: &'static str, why: core::fmt::Arguments<'_>) -> ScenarioError {
        self.err(key, why.to_string())
    }
}
