//! `[[surfaces]]` checked: planes, spheres and cylinders with their stiffness, damping and
//! friction.

use super::check::Checker;
use super::error::ScenarioError;
use super::file::SurfaceTable;
use crate::contact::{ContactSurface, SurfaceGeometry};

pub(super) fn surface(
    c: &Checker<'_>,
    key: &str,
    s: &SurfaceTable,
) -> Result<ContactSurface, ScenarioError> {
    let k = |name: &str| format!("{key}.{name}");
    let point = c.vec3(&k("point"), &c.need(&k("point"), &s.point, "a point in m")?)?;
    let radius = |c: &Checker<'_>| -> Result<f64, ScenarioError> {
        let r = c.need(&k("radius"), &s.radius, "a radius in m")?;
        c.range(
            &k("radius"),
            r,
            0.0,
            100.0,
            true,
            "a radius in m, > 0 and <= 100",
        )
    };
    let geometry = match s.kind.as_str() {
        "plane" => {
            c.forbid(
                &k("axis"),
                s.axis.is_some(),
                "a plane has a normal, not an axis",
            )?;
            c.forbid(&k("radius"), s.radius.is_some(), "a plane has no radius")?;
            let normal = c.unit(
                &k("normal"),
                &c.need(&k("normal"), &s.normal, "the outward normal")?,
            )?;
            let he = c.need(
                &k("half_extent"),
                &s.half_extent,
                "the patch's half sizes [a, b] in m",
            )?;
            if he.len() != 2 {
                return Err(c.err(
                    &k("half_extent"),
                    format!("needs 2 half sizes [a, b] in m, got {}", he.len()),
                ));
            }
            for v in &he {
                c.range(
                    &k("half_extent"),
                    *v,
                    0.0,
                    100.0,
                    true,
                    "half sizes in m, > 0",
                )?;
            }
            SurfaceGeometry::plane(point, normal, [he[0], he[1]])
        }
        "sphere" => {
            for (name, present) in [
                ("normal", s.normal.is_some()),
                ("axis", s.axis.is_some()),
                ("half_extent", s.half_extent.is_some()),
            ] {
                c.forbid(
                    &k(name),
                    present,
                    "a sphere has a centre (`point`) and a radius only",
                )?;
            }
            SurfaceGeometry::Sphere {
                centre: point,
                radius: radius(c)?,
            }
        }
        "cylinder" => {
            c.forbid(
                &k("normal"),
                s.normal.is_some(),
                "a cylinder has an axis, not a normal",
            )?;
            c.forbid(
                &k("half_extent"),
                s.half_extent.is_some(),
                "a cylinder is infinitely long",
            )?;
            let axis = c.unit(
                &k("axis"),
                &c.need(&k("axis"), &s.axis, "the axis direction")?,
            )?;
            SurfaceGeometry::Cylinder {
                point,
                axis,
                radius: radius(c)?,
            }
        }
        other => {
            return Err(c.err(
                &k("kind"),
                format!("unknown surface kind `{other}`; known: plane, sphere, cylinder"),
            ))
        }
    };
    Ok(ContactSurface {
        geometry,
        stiffness: c.range(
            &k("stiffness"),
            s.stiffness,
            0.0,
            1e9,
            true,
            "a stiffness in N/m, > 0",
        )?,
        damping: c.range(
            &k("damping"),
            s.damping.unwrap_or(0.0),
            0.0,
            1e7,
            false,
            "a damping in N s/m, >= 0",
        )?,
        friction: c.coulomb(&k("friction"), s.friction.unwrap_or(0.0))?,
    })
}
