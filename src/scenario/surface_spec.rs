//! `[[surfaces]]` checked: the kind and its shape's settings (read through
//! [`SettingsReader`], so a new shape needs nothing here), the stiffness, damping and
//! friction every surface has. Any other key is refused, naming the kind's keys.

use toml::Table;

use super::check::Checker;
use super::error::ScenarioError;
use super::toml_table::TomlTable;
use crate::contact::{ContactSurface, SurfaceGeometry};
use crate::surface::SettingsReader;

/// The keys every surface has besides its `kind` and its shape's.
const COMMON_KEYS: [&str; 3] = ["stiffness", "damping", "friction"];

/// Surface `key` (`surfaces[i]`) of the file, its table `s`.
pub(super) fn surface(
    c: &Checker<'_>,
    key: &str,
    s: &Table,
) -> Result<ContactSurface, ScenarioError> {
    let mut r = TomlSettings(TomlTable {
        c,
        at: key,
        table: s,
    });
    let kinds = SurfaceGeometry::KINDS.join(", ");
    let kind = r.0.tag("kind", &format!("the shape, one of {kinds}"))?;
    let unknown = || {
        c.err(
            &format!("{key}.kind"),
            format!("unknown surface kind `{kind}`; known: {kinds}"),
        )
    };
    let Some(shape_keys) = SurfaceGeometry::keys_of(kind) else {
        return Err(unknown());
    };
    let allowed = [&COMMON_KEYS[..], shape_keys].concat();
    if let Some(k) = r.0.other_key("kind", &allowed) {
        let keys = shape_keys
            .iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>();
        let own = format!("a {kind} has {}", keys.join(", "));
        let another_kind = SurfaceGeometry::KINDS
            .iter()
            .any(|other| SurfaceGeometry::keys_of(other).is_some_and(|ks| ks.contains(&k)));
        return Err(r.0.err(
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
    let r = r.0;
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

/// A surface's table, read as the shapes read their settings.
struct TomlSettings<'a>(TomlTable<'a>);

impl SettingsReader for TomlSettings<'_> {
    type Error = ScenarioError;

    fn number(&mut self, key: &'static str, what: &'static str) -> Result<f64, ScenarioError> {
        let x = self
            .0
            .optional_number(key)?
            .ok_or_else(|| self.0.err(key, format!("is missing: {what}")))?;
        self.0.c.finite(&self.0.path(key), x)
    }

    fn numbers<const N: usize>(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<[f64; N], ScenarioError> {
        let v = self.0.numbers(key, what)?;
        let Ok(v) = <[f64; N]>::try_from(v.as_slice()) else {
            return Err(self
                .0
                .err(key, format!("needs {N} numbers ({what}), got {}", v.len())));
        };
        for x in v {
            self.0.c.finite(&self.0.path(key), x)?;
        }
        Ok(v)
    }

    fn refuse(&mut self, key: &'static str, why: core::fmt::Arguments<'_>) -> ScenarioError {
        self.0.err(key, why.to_string())
    }
}
