//! What every shape of [`SurfaceGeometry::KINDS`] must do, checked on shapes drawn at random
//! from their own settings (so a new shape is checked without a line here): the drawing lies
//! on the surface, the normal is the unit gradient of the signed distance, a shift moves
//! the distance by exactly its amount, and every setting read is written.

use nalgebra::Vector3;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

use super::{SettingsReader, SurfaceGeometry};

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
pub(crate) fn random_shapes(seed: u64, count: usize) -> Vec<SurfaceGeometry> {
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
pub(crate) fn same_surface(a: &SurfaceGeometry, b: &SurfaceGeometry) -> bool {
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
