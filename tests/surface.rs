//! The surface shapes through their public traits, as a shape of one's own would be: every
//! shape of [`SurfaceGeometry::KINDS`] on shapes drawn at random from its own settings (so a
//! new shape is checked without a line here): its drawing lies on it, its normal is the unit
//! gradient of its signed distance, a shift moves the distance by exactly its amount, it
//! writes every setting it reads, and scenario files and `scene.json` read back what it
//! writes; a key of another kind or of none is refused by name and line.

use std::path::Path;

use armdyn::report::view::{scene_from_json, scene_json};
use armdyn::scenario::Scenario;
use armdyn::surface::{
    plane_axes, Cylinder, Plane, Setting, SettingsReader, Shape, Sphere, SurfaceGeometry, Torus,
};
use nalgebra::Vector3;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// Settings drawn at random: a number 0.05 to 1, several numbers -1 to 1 each (a shape whose
/// settings break a rule, such as a negative half size, is drawn again).
struct RandomSettings(Xoshiro256PlusPlus);

impl SettingsReader for RandomSettings {
    type Error = ();
    fn number(&mut self, _: &'static str, _: &'static str) -> Result<f64, ()> {
        Ok(self.0.random_range(0.05..1.0))
    }
    fn numbers<const N: usize>(
        &mut self,
        _: &'static str,
        _: &'static str,
    ) -> Result<[f64; N], ()> {
        Ok(core::array::from_fn(|_| self.0.random_range(-1.0..1.0)))
    }
    fn refuse(&mut self, _: &'static str, _: core::fmt::Arguments<'_>) {}
}

/// `count` shapes of every kind, drawn from `seed`.
fn random_shapes(seed: u64, count: usize) -> Vec<SurfaceGeometry> {
    let mut r = RandomSettings(Xoshiro256PlusPlus::seed_from_u64(seed));
    SurfaceGeometry::KINDS
        .iter()
        .flat_map(|kind| core::iter::repeat_n(*kind, count))
        .map(|kind| loop {
            // Settings that break a rule between them are drawn again.
            if let Some(Ok(s)) = SurfaceGeometry::read(kind, &mut r) {
                return s;
            }
        })
        .collect()
}

/// Whether `a` and `b` are the same surface: of one kind, and to 1e-12 m at points about them.
fn same_surface(a: &SurfaceGeometry, b: &SurfaceGeometry) -> bool {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(1);
    a.kind() == b.kind()
        && (0..20).all(|_| {
            let p = Vector3::from_fn(|_, _| rng.random_range(-2.0..2.0));
            let (x, y) = (a.closest(&p), b.closest(&p));
            (x.signed_distance - y.signed_distance).abs() < 1e-12
                && (x.normal - y.normal).norm() < 1e-12
                && x.covered == y.covered
        })
}

#[test]
fn every_kind_is_drawn_on_itself_and_shifts_along_its_normal() {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(5);
    let mut point = || Vector3::from_fn(|_, _| rng.random_range(-2.0..2.0));
    for s in random_shapes(3, 50) {
        let path: Vec<Vector3<f64>> = (0..5).map(|_| point()).collect();
        let d = s.drawing(&path, 48);
        let drawn: Vec<&Vector3<f64>> = d
            .fills
            .iter()
            .chain(&d.lines)
            .chain(&d.grid)
            .flatten()
            .collect();
        assert!(!drawn.is_empty(), "{s:?} draws nothing");
        for p in drawn {
            let off = s.closest(p).signed_distance;
            assert!(off.abs() < 1e-9, "{s:?}: drawn point {p} is {off} m off");
        }
        for _ in 0..20 {
            let (p, shift) = (point(), 0.3 * (point().x));
            let (c, moved) = (s.closest(&p), s.shifted(shift).closest(&p));
            assert!((c.normal.norm() - 1.0).abs() < 1e-12, "{s:?}");
            assert!(
                (moved.signed_distance - (c.signed_distance - shift)).abs() < 1e-12,
                "{s:?}"
            );
            assert!((moved.normal - c.normal).norm() < 1e-12, "{s:?}");
            let h = 1e-6;
            let ahead = s.closest(&(p + c.normal * h)).signed_distance - c.signed_distance;
            assert!(
                (ahead - h).abs() < 1e-9,
                "{s:?}: the normal at {p} is not the distance's gradient"
            );
        }
        let mut written = Vec::new();
        s.write(&mut |key, _| written.push(key));
        for key in SurfaceGeometry::keys_of(s.kind()).unwrap() {
            assert!(written.contains(key), "{s:?} does not write its `{key}`");
        }
    }
}

#[test]
fn scene_json_reads_back_every_kind() {
    let shapes = random_shapes(9, 20);
    let back = scene_from_json(&scene_json(&shapes).to_string()).unwrap();
    assert_eq!(back.len(), shapes.len());
    for (a, b) in shapes.iter().zip(&back) {
        assert!(same_surface(a, b), "{a:?} came back as {b:?}");
    }
}

/// A free-space scenario file of the UR5 with `s` as its one surface (its shape's keys only).
fn with_surface(s: &SurfaceGeometry) -> String {
    let keys = SurfaceGeometry::keys_of(s.kind()).unwrap();
    let mut text = String::from(
        "format = 1\nname = \"s\"\nrobot = \"ur5\"\nstart_on_reference = true\n\n\
         [reference]\nkind = \"waypoints\"\ninterpolation = \"quintic\"\n\
         seed = [0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]\n\
         points = [[0.0, 0.4, -0.1, 0.3, 0.0, 1.5707963267948966, 0.0], \
         [1.0, 0.5, -0.1, 0.3, 0.0, 1.5707963267948966, 0.0]]\n\n\
         [position]\nlaw = \"task-space\"\n\n",
    );
    text += &format!("[[surfaces]]\nkind = \"{}\"\nstiffness = 1e4\n", s.kind());
    s.write(&mut |key, setting| {
        let value = match setting {
            Setting::Vector(v) => format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z),
            Setting::Number(x) => format!("{x:?}"),
            Setting::Numbers(xs) => format!("{xs:?}"),
            // Derived (a plane's axes): not a key of the file.
            Setting::Vectors(_) => return,
        };
        if keys.contains(&key) {
            text += &format!("{key} = {value}\n");
        }
    });
    text
}

fn parse(text: &str) -> Result<Scenario, armdyn::scenario::ScenarioError> {
    Scenario::parse("t.toml", text, Path::new("."))
}

#[test]
fn scenario_files_read_back_every_kind() {
    for s in random_shapes(11, 20) {
        let text = with_surface(&s);
        let back = parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
        assert!(same_surface(&s, &back.surfaces[0].geometry), "{text}");
    }
}

#[test]
fn keys_of_another_kind_and_unknown_keys_are_refused_by_name_and_line() {
    for s in random_shapes(12, 1) {
        let text = with_surface(&s);
        let last = text.lines().count() + 1;
        let e = parse(&format!("{text}colour = 1\n")).unwrap_err();
        assert_eq!(
            (e.key.as_str(), e.line),
            ("surfaces[0].colour", Some(last)),
            "{e}"
        );
        assert!(e.rule.starts_with("unknown field `colour`"), "{e}");
        let own = SurfaceGeometry::keys_of(s.kind()).unwrap();
        let other = ["radius", "normal"]
            .into_iter()
            .find(|k| !own.contains(k))
            .unwrap();
        let e = parse(&format!("{text}{other} = 1\n")).unwrap_err();
        assert!(e.rule.starts_with("does not belong here: a "), "{e}");
        let e = parse(&text.replace("stiffness = 1e4", "stiffness = \"soft\"")).unwrap_err();
        assert_eq!(
            (e.key.as_str(), e.rule.as_str()),
            (
                "surfaces[0].stiffness",
                "invalid type: string, expected a number"
            )
        );
    }
}

// Known values of each shape.

#[test]
fn a_plane_patch_gives_distance_normal_and_extent() {
    let s = Plane::new(Vector3::new(0.4, 0.0, 0.13), Vector3::z(), [0.2, 0.4]);
    let c = s.closest(&Vector3::new(0.5, 0.1, 0.11));
    assert!((c.signed_distance + 0.02).abs() < 1e-15);
    assert_eq!(c.normal, Vector3::z());
    assert!(c.covered);
    assert!(!s.closest(&Vector3::new(0.7, 0.0, 0.1)).covered);
    assert!(!s.closest(&Vector3::new(0.5, -0.41, 0.1)).covered);
    let up = s.shifted(0.01).closest(&Vector3::new(0.5, 0.1, 0.11));
    assert!((up.signed_distance + 0.03).abs() < 1e-15);
}

#[test]
fn a_tilted_planes_axes_are_orthonormal() {
    let a = 20_f64.to_radians();
    let n = Vector3::new(libm::sin(a), 0.0, libm::cos(a));
    let [u, v] = plane_axes(&n);
    for (x, y) in [(u, v), (u, n), (v, n)] {
        assert!(x.dot(&y).abs() < 1e-15);
    }
    assert!((u.norm() - 1.0).abs() < 1e-15 && (v.norm() - 1.0).abs() < 1e-15);
    assert!((v - Vector3::y()).norm() < 1e-15, "{v}");
}

#[test]
fn a_plane_is_drawn_as_its_rectangle_and_grid() {
    let d = Plane::new(Vector3::new(0.4, 0.0, 0.22), Vector3::z(), [0.2, 0.4]).drawing(&[], 48);
    assert_eq!(d.fills[0][0], Vector3::new(0.2, -0.4, 0.22));
    assert_eq!(d.fills[0][2], Vector3::new(0.6000000000000001, 0.4, 0.22));
    assert_eq!((d.lines.len(), d.grid.len()), (0, 22));
}

#[test]
fn a_sphere_is_convex_from_outside() {
    let s = Sphere {
        centre: Vector3::new(0.5, 0.0, -0.87),
        radius: 1.0,
    };
    let c = s.closest(&Vector3::new(0.5, 0.0, 0.12));
    assert!((c.signed_distance + 0.01).abs() < 1e-12);
    assert!((c.normal - Vector3::z()).norm() < 1e-15);
    assert!(
        (s.shifted(0.02)
            .closest(&Vector3::new(0.5, 0.0, 0.12))
            .signed_distance
            + 0.03)
            .abs()
            < 1e-12
    );
    // At the centre the normal is base z.
    assert_eq!(s.closest(&s.centre).normal, Vector3::z());
}

#[test]
fn every_drawn_point_is_on_the_sphere() {
    let s = Sphere {
        centre: Vector3::new(0.5, 0.1, 0.2),
        radius: 0.3,
    };
    let d = s.drawing(&[], 48);
    assert_eq!(d.lines.len(), 7);
    for p in d.lines.iter().flatten() {
        assert!(((p - s.centre).norm() - 0.3).abs() < 1e-12);
    }
}

#[test]
fn a_cylinder_is_convex_from_outside() {
    let c = Cylinder {
        point: Vector3::new(0.5, 0.0, -0.37),
        axis: Vector3::y(),
        radius: 0.5,
    };
    let p = Vector3::new(0.5, 0.3, 0.15);
    assert!((c.closest(&p).signed_distance - 0.02).abs() < 1e-12);
    assert!((c.closest(&p).normal - Vector3::z()).norm() < 1e-15);
    assert!((c.shifted(0.02).closest(&p).signed_distance).abs() < 1e-12);
}

#[test]
fn a_cylinder_is_drawn_over_the_path_on_its_mantle() {
    let c = Cylinder {
        point: Vector3::zeros(),
        axis: Vector3::y(),
        radius: 0.2,
    };
    let d = c.drawing(
        &[Vector3::new(0.0, -0.3, 0.2), Vector3::new(0.0, 0.5, 0.2)],
        48,
    );
    assert_eq!(d.lines.len(), 15);
    approx::assert_relative_eq!(d.lines[2][0].y, 0.1, epsilon = 1e-12);
    approx::assert_relative_eq!(d.lines[0][0].y, -0.4, epsilon = 1e-12);
    approx::assert_relative_eq!(d.lines[1][0].y, 0.6, epsilon = 1e-12);
    for p in d.lines.iter().flatten() {
        approx::assert_relative_eq!(p.x.hypot(p.z), 0.2, epsilon = 1e-12);
    }
}

fn bend() -> Torus {
    Torus {
        centre: Vector3::new(0.35, -1.0, 0.25),
        axis: Vector3::z(),
        radius: 1.0,
        tube_radius: 0.15,
    }
}

#[test]
fn a_torus_is_measured_outside_the_tube_and_inside_the_ring() {
    let t = bend();
    // Over the top of the tube where the ring crosses y = 0.
    let c = t.closest(&Vector3::new(0.35, 0.0, 0.41));
    assert!((c.signed_distance - 0.01).abs() < 1e-12);
    assert!((c.normal - Vector3::z()).norm() < 1e-12);
    // On the inner side of the ring, facing the axis.
    let c = t.closest(&Vector3::new(0.35, -0.2, 0.25));
    assert!((c.signed_distance - 0.05).abs() < 1e-12);
    assert!((c.normal + Vector3::y()).norm() < 1e-12);
    // On the axis every way out is as near: the first in-plane axis is taken.
    let c = t.closest(&t.centre);
    assert!((c.signed_distance - 0.85).abs() < 1e-12);
}
