//! Shared test support: the seeded random generator, an independent reading of the robot
//! descriptions (`robots/*.toml`), an independent forward kinematics built from them, and
//! comparison helpers with relative tolerances.
//!
//! Nothing here uses the generator or the generated code: the checks compare the generated
//! functions against quantities rebuilt from the description.
#![allow(dead_code)] // each test file uses a different part of this module

pub mod urdf_model;

use std::f64::consts::PI;
use std::path::PathBuf;

use nalgebra::{Matrix3, Matrix4, SMatrix, SVector, Vector3, Vector4};
use serde::Deserialize;

/// Number of random states per robot and per property (acceptance: 200+).
pub const STATES: usize = 256;

/// Seed of the random states; a failing state can be reproduced from it and the state's index.
pub const SEED: u64 = 0x5CA2_A0DE_2026_0001;

// ---------------------------------------------------------------------------------------
// Random states: the tests' one generator, `rand`'s Xoshiro256++ from a stated seed.

/// `rand`'s Xoshiro256++ seeded from a `u64` (the same stream on every platform), with the
/// one draw the shared checks need.
#[derive(Debug, Clone)]
pub struct Rng(rand::rngs::Xoshiro256PlusPlus);

impl Rng {
    pub fn new(seed: u64) -> Self {
        use rand::SeedableRng;
        Rng(rand::rngs::Xoshiro256PlusPlus::seed_from_u64(seed))
    }

    /// Uniform in `[lo, hi]`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        use rand::RngExt;
        self.0.random_range(lo..=hi)
    }
}

// ---------------------------------------------------------------------------------------
// The robot description, read independently of the generator.

/// A TOML value that is either a number or a text form (`"pi/2"`, `"q + 0.1"`, `"30deg"`).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum NumOrText {
    Num(f64),
    Text(String),
}

#[derive(Debug, Clone, Deserialize)]
pub struct RawLink {
    pub mass: f64,
    pub com: [f64; 3],
    pub inertia: [[f64; 3]; 3],
    #[serde(default)]
    pub accept_triangle_violation: bool,
}

#[derive(Debug, Clone, Deserialize)]
pub struct RawJoint {
    pub name: String,
    pub kind: String,
    pub a: NumOrText,
    pub alpha: NumOrText,
    pub d: NumOrText,
    pub theta: NumOrText,
    pub limits: [NumOrText; 2],
    pub effort: f64,
    pub link: RawLink,
}

#[derive(Debug, Clone, Deserialize)]
pub struct RawDescription {
    pub format: u32,
    pub name: String,
    pub description: String,
    pub convention: String,
    pub gravity: [f64; 3],
    pub joints: Vec<RawJoint>,
}

/// One joint and its link, with every angle and length resolved to a number.
#[derive(Debug, Clone)]
pub struct Joint {
    pub name: String,
    pub prismatic: bool,
    /// DH `a` (m) and `alpha` (rad), constant.
    pub a: f64,
    pub alpha: f64,
    /// Constant part of `d` (m) and `theta` (rad); the joint variable adds to `d` for a
    /// prismatic joint and to `theta` for a revolute one.
    pub d: f64,
    pub theta: f64,
    pub limits: [f64; 2],
    pub effort: f64,
    pub mass: f64,
    /// Centre of mass in frame i (m).
    pub com: Vector3<f64>,
    /// Inertia about the COM, axes of frame i (kg m^2).
    pub inertia: Matrix3<f64>,
}

/// A robot as read from `robots/<name>.toml`.
#[derive(Debug, Clone)]
pub struct Robot {
    pub name: String,
    /// Modified (Craig) DH instead of standard DH.
    pub modified: bool,
    pub gravity: Vector3<f64>,
    /// Per joint: name, kind, limits, effort; the DH fields and the link are those of a DH
    /// description (zero for a URDF one, whose links are in `urdf`).
    pub joints: Vec<Joint>,
    /// A URDF-based description (`convention = "urdf"`), read with `urdf-rs`.
    pub urdf: Option<urdf_model::UrdfChain>,
}

/// Reads a URDF-based description.
fn load_urdf_robot(path: &std::path::Path, text: &str) -> Robot {
    let raw: urdf_model::RawUrdfDescription =
        toml::from_str(text).unwrap_or_else(|e| panic!("parsing {}: {e}", path.display()));
    assert_eq!(raw.format, 1);
    let chain = urdf_model::UrdfChain::load(path, &raw);
    let joints = (0..chain.chain.len())
        .map(|k| {
            let j = &chain.chain[k];
            let (limits, effort) = chain.limits(k);
            Joint {
                name: j.name.clone(),
                prismatic: urdf_model::UrdfChain::is_prismatic(j),
                a: 0.0,
                alpha: 0.0,
                d: 0.0,
                theta: 0.0,
                limits,
                effort,
                mass: 0.0,
                com: Vector3::zeros(),
                inertia: Matrix3::zeros(),
            }
        })
        .collect();
    Robot {
        name: raw.name,
        modified: false,
        gravity: Vector3::from(raw.gravity.unwrap_or([0.0, 0.0, -9.81])),
        joints,
        urdf: Some(chain),
    }
}

/// Parses an angle: a number, or `[-][k*]pi[/m]`, or `<x>deg`.
pub fn parse_angle(text: &str) -> f64 {
    let s = text.trim();
    if let Some(rest) = s.strip_prefix('-') {
        return -parse_angle(rest);
    }
    if let Some(rest) = s.strip_prefix('+') {
        return parse_angle(rest);
    }
    if let Some(deg) = s.strip_suffix("deg") {
        let deg: f64 = deg
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("bad angle {text:?}"));
        return deg * PI / 180.0;
    }
    if s.contains("pi") {
        let (num, den) = match s.split_once('/') {
            Some((n, d)) => (n.trim(), d.trim().parse::<f64>().expect("bad denominator")),
            None => (s, 1.0),
        };
        let factor = match num.strip_suffix("pi").map(str::trim) {
            Some("") => 1.0,
            Some(k) => k
                .trim_end_matches('*')
                .trim()
                .parse::<f64>()
                .unwrap_or_else(|_| panic!("bad angle {text:?}")),
            None => panic!("bad angle {text:?}"),
        };
        return factor * PI / den;
    }
    s.parse().unwrap_or_else(|_| panic!("bad angle {text:?}"))
}

/// A DH entry: `(is_variable, constant part)`. `"q"`, `"q + x"`, `"q - x"` are variable.
fn dh_entry(value: &NumOrText, angle: bool) -> (bool, f64) {
    match value {
        NumOrText::Num(x) => (false, *x),
        NumOrText::Text(t) => {
            let t = t.trim();
            if t == "q" {
                (true, 0.0)
            } else if let Some(rest) = t.strip_prefix('q') {
                let rest = rest.trim();
                let (sign, x) = if let Some(x) = rest.strip_prefix('+') {
                    (1.0, x)
                } else if let Some(x) = rest.strip_prefix('-') {
                    (-1.0, x)
                } else {
                    panic!("bad DH entry {t:?}")
                };
                (true, sign * parse_value(x, angle))
            } else {
                (false, parse_value(t, angle))
            }
        }
    }
}

fn parse_value(text: &str, angle: bool) -> f64 {
    if angle {
        parse_angle(text)
    } else {
        text.trim()
            .parse()
            .unwrap_or_else(|_| panic!("bad length {text:?}"))
    }
}

fn limit(value: &NumOrText) -> f64 {
    match value {
        NumOrText::Num(x) => *x,
        NumOrText::Text(t) => parse_angle(t),
    }
}

/// Path of `robots/<name>.toml`.
pub fn description_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("robots")
        .join(format!("{name}.toml"))
}

/// Reads and resolves `robots/<name>.toml`.
pub fn load_robot(name: &str) -> Robot {
    let path = description_path(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    if text.contains("convention = \"urdf\"") {
        return load_urdf_robot(&path, &text);
    }
    let raw: RawDescription =
        toml::from_str(&text).unwrap_or_else(|e| panic!("parsing {}: {e}", path.display()));
    assert_eq!(raw.format, 1);
    let modified = match raw.convention.as_str() {
        "standard-dh" => false,
        "modified-dh" => true,
        other => panic!("unknown convention {other:?}"),
    };
    assert_eq!(raw.name, name);
    let joints = raw
        .joints
        .iter()
        .map(|j| {
            let prismatic = match j.kind.as_str() {
                "prismatic" => true,
                "revolute" => false,
                other => panic!("unknown joint kind {other:?}"),
            };
            let (a_var, a) = dh_entry(&j.a, false);
            let (alpha_var, alpha) = dh_entry(&j.alpha, true);
            let (d_var, d) = dh_entry(&j.d, false);
            let (theta_var, theta) = dh_entry(&j.theta, true);
            assert!(
                !a_var && !alpha_var,
                "joint {}: a/alpha cannot vary",
                j.name
            );
            assert_eq!(
                d_var, prismatic,
                "joint {}: d variable iff prismatic",
                j.name
            );
            assert_eq!(
                theta_var, !prismatic,
                "joint {}: theta variable iff revolute",
                j.name
            );
            Joint {
                name: j.name.clone(),
                prismatic,
                a,
                alpha,
                d,
                theta,
                limits: [limit(&j.limits[0]), limit(&j.limits[1])],
                effort: j.effort,
                mass: j.link.mass,
                com: Vector3::from(j.link.com),
                inertia: Matrix3::from_fn(|r, c| j.link.inertia[r][c]),
            }
        })
        .collect();
    Robot {
        name: raw.name,
        modified,
        gravity: Vector3::from(raw.gravity),
        joints,
        urdf: None,
    }
}

impl Robot {
    pub fn dof(&self) -> usize {
        self.joints.len()
    }

    /// Standard DH: `A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)`; modified DH:
    /// `A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)` (row `i` of the description
    /// holds `a_{i-1}`, `alpha_{i-1}`). Built as the product of the elementary transforms.
    pub fn link_transform(&self, i: usize, qi: f64) -> Matrix4<f64> {
        let j = &self.joints[i];
        let (theta, d) = if j.prismatic {
            (j.theta, j.d + qi)
        } else {
            (j.theta + qi, j.d)
        };
        let (st, ct) = theta.sin_cos();
        let (sa, ca) = j.alpha.sin_cos();
        #[rustfmt::skip]
        let rz = Matrix4::new(
            ct, -st, 0.0, 0.0,
            st, ct, 0.0, 0.0,
            0.0, 0.0, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
        );
        let mut tz = Matrix4::identity();
        tz[(2, 3)] = d;
        let mut tx = Matrix4::identity();
        tx[(0, 3)] = j.a;
        #[rustfmt::skip]
        let rx = Matrix4::new(
            1.0, 0.0, 0.0, 0.0,
            0.0, ca, -sa, 0.0,
            0.0, sa, ca, 0.0,
            0.0, 0.0, 0.0, 1.0,
        );
        if self.modified {
            rx * tx * rz * tz
        } else {
            rz * tz * tx * rx
        }
    }

    /// Poses of frames 1..=n in the base frame (a URDF's chain joints' child links).
    pub fn frame_poses(&self, q: &[f64]) -> Vec<Matrix4<f64>> {
        assert_eq!(q.len(), self.dof());
        if let Some(urdf) = &self.urdf {
            return urdf.frame_poses(q);
        }
        let mut t = Matrix4::identity();
        q.iter()
            .enumerate()
            .map(|(i, &qi)| {
                t *= self.link_transform(i, qi);
                t
            })
            .collect()
    }

    /// Pose of the end effector: frame n (DH) or the URDF's tip link.
    pub fn end_effector(&self, q: &[f64]) -> Matrix4<f64> {
        match &self.urdf {
            Some(urdf) => urdf.end_effector(q),
            None => *self.frame_poses(q).last().unwrap(),
        }
    }

    /// Every rigid body that moves: (body index 1..=n, mass, COM in the base frame, rotation
    /// of the axes its inertia is given in, inertia about the COM in those axes). One per DH
    /// link; one per URDF link that moves with the arm (not lumped).
    pub fn bodies(&self, q: &[f64]) -> Vec<urdf_model::Body> {
        if let Some(urdf) = &self.urdf {
            return urdf.bodies(q);
        }
        self.frame_poses(q)
            .iter()
            .zip(&self.joints)
            .enumerate()
            .map(|(i, (t, j))| {
                let c = t * Vector4::new(j.com.x, j.com.y, j.com.z, 1.0);
                (
                    i + 1,
                    j.mass,
                    c.xyz(),
                    t.fixed_view::<3, 3>(0, 0).into_owned(),
                    j.inertia,
                )
            })
            .collect()
    }

    /// The standard inertial parameters per link frame `[m, m c, I about the frame origin]`
    /// (10 per link): a DH link's own; a URDF body's summed over its links (placed at q = 0).
    pub fn standard_parameters(&self) -> Vec<f64> {
        let q = vec![0.0; self.dof()];
        let frames = self.frame_poses(&q);
        let mut out = Vec::new();
        for (k, frame) in frames.iter().enumerate() {
            let inv = frame.try_inverse().unwrap();
            let (mut m, mut h, mut io) = (0.0, Vector3::zeros(), Matrix3::zeros());
            for (body, mass, com, rot, inertia) in self.bodies(&q) {
                if body != k + 1 {
                    continue;
                }
                let c = (inv * Vector4::new(com.x, com.y, com.z, 1.0)).xyz();
                let r = inv.fixed_view::<3, 3>(0, 0) * rot;
                m += mass;
                h += mass * c;
                io += r * inertia * r.transpose()
                    + mass * (c.norm_squared() * Matrix3::identity() - c * c.transpose());
            }
            out.extend([
                m,
                h.x,
                h.y,
                h.z,
                io[(0, 0)],
                io[(0, 1)],
                io[(0, 2)],
                io[(1, 1)],
                io[(1, 2)],
                io[(2, 2)],
            ]);
        }
        out
    }

    /// A random joint state: `q` uniform within the joint limits, `qd` uniform in [-2, 2].
    pub fn random_state<const N: usize>(
        &self,
        rng: &mut Rng,
    ) -> (SVector<f64, N>, SVector<f64, N>) {
        assert_eq!(N, self.dof());
        let q = SVector::<f64, N>::from_fn(|i, _| {
            let [lo, hi] = self.joints[i].limits;
            rng.uniform(lo, hi)
        });
        let qd = SVector::<f64, N>::from_fn(|_, _| rng.uniform(-2.0, 2.0));
        (q, qd)
    }

    /// `count` random joint states drawn from `seed` (each as [`Self::random_state`]), each
    /// carrying its robot, index and seed for the failure messages.
    pub fn random_states<'d, 'a: 'd, const N: usize>(
        &'d self,
        robot: &'a str,
        seed: u64,
        count: usize,
    ) -> impl Iterator<Item = State<'a, N>> + 'd {
        let mut rng = Rng::new(seed);
        (0..count).map(move |index| {
            let (q, qd) = self.random_state(&mut rng);
            State {
                robot,
                index,
                seed,
                q,
                qd,
            }
        })
    }

    /// Kinetic energy (J) at `q` moving with `qd`, from frame velocities obtained by
    /// central differences of the frame poses along `qd` (step `h` in time):
    /// `T = sum_i 1/2 m_i |v_ci|^2 + 1/2 w_i^T R_i I_i R_i^T w_i`.
    pub fn kinetic_energy(&self, q: &[f64], qd: &[f64], h: f64) -> f64 {
        let plus: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a + h * b).collect();
        let minus: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a - h * b).collect();
        let (bp, bm, b0) = (self.bodies(&plus), self.bodies(&minus), self.bodies(q));
        let mut energy = 0.0;
        for i in 0..b0.len() {
            let (_, mass, _, r, inertia) = b0[i];
            let v = (bp[i].2 - bm[i].2) / (2.0 * h);
            let rdot = (bp[i].3 - bm[i].3) / (2.0 * h);
            let w = vee(&(rdot * r.transpose()));
            let inertia_base = r * inertia * r.transpose();
            energy += 0.5 * mass * v.norm_squared() + 0.5 * w.dot(&(inertia_base * w));
        }
        energy
    }

    /// Potential energy (J): `U = -sum_i m_i gravity . p_ci`.
    pub fn potential_energy(&self, q: &[f64]) -> f64 {
        self.bodies(q)
            .iter()
            .map(|(_, mass, c, _, _)| -mass * self.gravity.dot(c))
            .sum()
    }
}

/// The vector of the skew-symmetric part of `m`: `w` with `[w]x = (m - m^T) / 2`.
pub fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(
        0.5 * (m[(2, 1)] - m[(1, 2)]),
        0.5 * (m[(0, 2)] - m[(2, 0)]),
        0.5 * (m[(1, 0)] - m[(0, 1)]),
    )
}

// ---------------------------------------------------------------------------------------
// Comparisons.

/// Largest absolute entry.
pub fn max_abs<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> f64 {
    m.iter().fold(0.0_f64, |acc, x| acc.max(x.abs()))
}

/// Asserts `|got - expected| <= tol * max(1, scale)` entrywise; the message names the
/// quantity, the robot, the state and the worst entry.
pub fn assert_close<const R: usize, const C: usize>(
    what: &str,
    got: &SMatrix<f64, R, C>,
    expected: &SMatrix<f64, R, C>,
    tol: f64,
    scale: f64,
    context: &dyn std::fmt::Display,
) {
    let bound = tol * scale.max(1.0);
    let mut worst = (0.0_f64, 0, 0);
    for r in 0..R {
        for c in 0..C {
            let err = (got[(r, c)] - expected[(r, c)]).abs();
            if err.is_nan() {
                panic!("{what}: entry ({r}, {c}) is NaN at {context}\n got = {got}\n expected = {expected}");
            }
            if err > worst.0 {
                worst = (err, r, c);
            }
        }
    }
    let (err, r, c) = worst;
    assert!(
        err <= bound,
        "{what}: entry ({r}, {c}) differs by {err:e} > {bound:e} (tol {tol:e}, scale {scale:e}) \
         at {context}\n got      = {got}\n expected = {expected}"
    );
}

/// A random state of a robot, described in failure messages by its robot, index and seed.
pub struct State<'a, const N: usize> {
    pub robot: &'a str,
    pub index: usize,
    pub seed: u64,
    pub q: SVector<f64, N>,
    pub qd: SVector<f64, N>,
}

impl<const N: usize> std::fmt::Display for State<'_, N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "robot {} state #{} (seed {:#x}): q = {:?}, qd = {:?}",
            self.robot,
            self.index,
            self.seed,
            self.q.as_slice(),
            self.qd.as_slice()
        )
    }
}

/// Defines one `#[test]` per robot of the generated registry calling `$check(&Robot, "name")`
/// for a generic `fn $check<const N: usize, R: RobotModel<N>>(robot: &R, name: &str)`. The
/// tests are named `$check::<robot>` (`$check::scara`, `$check::panda`, ...).
#[macro_export]
macro_rules! per_robot {
    ($($check:ident),* $(,)?) => {
        $( armdyn_generated::for_each_robot!(per_robot_one, $check); )*
    };
}

/// One check for every robot (the callback of `armdyn_generated::for_each_robot!`).
#[macro_export]
macro_rules! per_robot_one {
    ([$check:ident] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        mod $check {
            $(
                #[test]
                fn $module() {
                    super::$check(&armdyn::model::$ty, stringify!($module));
                }
            )*
        }
    };
}
