//! Recorded runs as CSV text, with units in the column names.
//!
//! Numbers are written with Rust's shortest round-trip formatting (`{:?}` of `f64`): reading
//! a value back gives the same bits, and very small or large values use an exponent
//! (`1e-20`) rather than twenty zeros.

use crate::model::JointKind;
use crate::sim::Sample;
use crate::target::orientation;
use std::fmt::Write;

/// The unit of a joint's generalised force, written without a space for column names.
fn effort_unit(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "Nm",
        JointKind::Prismatic => "N",
    }
}

/// The header line (without newline) of [`trajectory_csv`].
///
/// Columns, for joint `i` (1-based) with name `name_i` and position unit `u_i` (`rad` or
/// `m`) and effort unit `e_i` (`Nm` or `N`):
///
/// | columns | meaning |
/// | --- | --- |
/// | `t_s` | time |
/// | `{name_i}_{u_i}` | joint position |
/// | `{name_i}_ref_{u_i}` | joint position reference |
/// | `qd{i}_{u_i}_s` | joint velocity |
/// | `qd{i}_ref_{u_i}_s` | joint velocity reference |
/// | `tau{i}_{e_i}` | applied joint torque or force (after saturation) |
/// | `tau{i}_cmd_{e_i}` | controller output before saturation |
/// | `x_m y_m z_m roll_rad pitch_rad yaw_rad` | end-effector position and orientation (fixed axes x-y-z, REP-103) |
/// | `x_ref_m y_ref_m z_ref_m roll_ref_rad pitch_ref_rad yaw_ref_rad` | Cartesian reference |
/// | `fx_N fy_N fz_N` | measured force of the tool on the environment |
/// | `fx_ref_N fy_ref_N fz_ref_N` | desired force |
///
/// # Example
///
/// ```
/// use armdyn::model::{RobotModel, Scara};
/// use armdyn::report::trajectory_csv_header;
///
/// let header = trajectory_csv_header(&Scara::JOINT_NAMES, &Scara::JOINT_KINDS);
/// assert!(header.starts_with("t_s,q1_rad,q2_rad,d3_m,q4_rad,q1_ref_rad,"));
/// assert!(header.contains(",qd3_m_s,"));
/// assert!(header.contains(",tau1_Nm,tau2_Nm,tau3_N,tau4_Nm,"));
/// assert!(header.ends_with(",fz_N,fx_ref_N,fy_ref_N,fz_ref_N"));
/// ```
pub fn trajectory_csv_header<const N: usize>(
    joint_names: &[&str; N],
    joint_kinds: &[JointKind; N],
) -> String {
    let mut cols: Vec<String> = vec!["t_s".into()];
    let units = joint_kinds.map(|k| k.position_unit());
    cols.extend((0..N).map(|i| format!("{}_{}", joint_names[i], units[i])));
    cols.extend((0..N).map(|i| format!("{}_ref_{}", joint_names[i], units[i])));
    cols.extend((0..N).map(|i| format!("qd{}_{}_s", i + 1, units[i])));
    cols.extend((0..N).map(|i| format!("qd{}_ref_{}_s", i + 1, units[i])));
    cols.extend((0..N).map(|i| format!("tau{}_{}", i + 1, effort_unit(joint_kinds[i]))));
    cols.extend((0..N).map(|i| format!("tau{}_cmd_{}", i + 1, effort_unit(joint_kinds[i]))));
    for name in [
        "x_m",
        "y_m",
        "z_m",
        "roll_rad",
        "pitch_rad",
        "yaw_rad",
        "x_ref_m",
        "y_ref_m",
        "z_ref_m",
        "roll_ref_rad",
        "pitch_ref_rad",
        "yaw_ref_rad",
        "fx_N",
        "fy_N",
        "fz_N",
        "fx_ref_N",
        "fy_ref_N",
        "fz_ref_N",
    ] {
        cols.push(name.into());
    }
    cols.join(",")
}

/// Appends `,v` with `v` in shortest round-trip form.
fn push(out: &mut String, v: f64) {
    // Writing to a String cannot fail.
    let _ = write!(out, ",{v:?}");
}

/// A closed-loop run as CSV: the header of [`trajectory_csv_header`], then one line per
/// sample, `\n`-terminated.
///
/// # Example
///
/// ```
/// use armdyn::model::{RobotModel, Scara};
/// use armdyn::report::trajectory_csv;
/// use armdyn::sim::Sample;
///
/// let samples: Vec<Sample<4>> = Vec::new();
/// let text = trajectory_csv(&samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS);
/// assert_eq!(text.lines().count(), 1); // the header alone
/// ```
pub fn trajectory_csv<const N: usize>(
    samples: &[Sample<N>],
    joint_names: &[&str; N],
    joint_kinds: &[JointKind; N],
) -> String {
    let header = trajectory_csv_header(joint_names, joint_kinds);
    // About 20 characters a number.
    let mut out = String::with_capacity(header.len() + 1 + samples.len() * (6 * N + 15) * 20);
    out.push_str(&header);
    out.push('\n');
    for s in samples {
        let _ = write!(out, "{:?}", s.t);
        let sp = &s.setpoint;
        for v in [
            &s.q,
            &sp.joint.q,
            &s.qd,
            &sp.joint.qd,
            &s.tau,
            &s.tau_command,
        ] {
            for x in v.iter() {
                push(&mut out, *x);
            }
        }
        let c = &sp.cartesian;
        let (roll, pitch, yaw) = orientation::rpy(&s.orientation);
        let (roll_ref, pitch_ref, yaw_ref) = orientation::rpy(&c.orientation);
        for x in [
            s.position.x,
            s.position.y,
            s.position.z,
            roll,
            pitch,
            yaw,
            c.position.x,
            c.position.y,
            c.position.z,
            roll_ref,
            pitch_ref,
            yaw_ref,
            s.wrench[0],
            s.wrench[1],
            s.wrench[2],
            sp.wrench[0],
            sp.wrench[1],
            sp.wrench[2],
        ] {
            push(&mut out, x);
        }
        out.push('\n');
    }
    out
}

/// An open-loop run (`armdyn simulate`) as CSV: header `t,q1,..,qN,qd1,..,qdN`, then one
/// line per sample, `\n`-terminated. Units are SI (s, rad or m, rad/s or m/s), as in the
/// torque CSV it answers.
///
/// # Example
///
/// ```
/// use armdyn::report::open_loop_csv;
/// use armdyn::sim::Sample;
///
/// let text = open_loop_csv::<4>(&[]);
/// assert_eq!(text, "t,q1,q2,q3,q4,qd1,qd2,qd3,qd4\n");
/// ```
pub fn open_loop_csv<const N: usize>(samples: &[Sample<N>]) -> String {
    let mut out = String::with_capacity(16 * N + samples.len() * (2 * N + 1) * 20);
    out.push('t');
    for i in 1..=N {
        let _ = write!(out, ",q{i}");
    }
    for i in 1..=N {
        let _ = write!(out, ",qd{i}");
    }
    out.push('\n');
    for s in samples {
        let _ = write!(out, "{:?}", s.t);
        for x in s.q.iter().chain(s.qd.iter()) {
            push(&mut out, *x);
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RobotModel, Scara};
    use crate::report::test_support::synthetic_run;

    #[test]
    fn header_and_rows_have_the_same_width() {
        let samples = synthetic_run(101, 1.0);
        let text = trajectory_csv(&samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 1 + samples.len());
        let width = lines[0].split(',').count();
        assert_eq!(width, 1 + 6 * 4 + 18);
        for line in &lines[1..] {
            assert_eq!(line.split(',').count(), width);
        }
        assert!(text.ends_with('\n'));
        assert_eq!(
            &lines[0][..lines[0].find(",qd1").unwrap()],
            "t_s,q1_rad,q2_rad,d3_m,q4_rad,q1_ref_rad,q2_ref_rad,d3_ref_m,q4_ref_rad"
        );
    }

    #[test]
    fn values_round_trip_exactly() {
        let samples = synthetic_run(11, 1.0);
        let text = trajectory_csv(&samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS);
        let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
        for (s, line) in samples.iter().zip(text.lines().skip(1)) {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            assert_eq!(v[col("t_s")].to_bits(), s.t.to_bits());
            assert_eq!(v[col("d3_m")].to_bits(), s.q[2].to_bits());
            assert_eq!(v[col("q2_ref_rad")], s.setpoint.joint.q[1]);
            assert_eq!(v[col("qd4_rad_s")], s.qd[3]);
            assert_eq!(v[col("tau3_N")], s.tau[2]);
            assert_eq!(v[col("tau1_cmd_Nm")], s.tau_command[0]);
            assert_eq!(v[col("y_m")], s.position.y);
            assert_eq!(v[col("z_ref_m")], s.setpoint.cartesian.position.z);
            assert_eq!(v[col("yaw_rad")], orientation::rpy(&s.orientation).2);
            assert_eq!(v[col("fz_N")], s.wrench[2]);
            assert_eq!(v[col("fz_ref_N")], s.setpoint.wrench[2]);
        }
    }

    #[test]
    fn tiny_values_use_an_exponent() {
        let mut samples = synthetic_run(1, 1.0);
        samples[0].q[0] = 1e-20;
        let text = open_loop_csv(&samples);
        let row = text.lines().nth(1).unwrap();
        assert_eq!(row.split(',').nth(1), Some("1e-20"));
    }

    #[test]
    fn open_loop_header_and_rows() {
        let samples = synthetic_run(5, 0.5);
        let text = open_loop_csv(&samples);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "t,q1,q2,q3,q4,qd1,qd2,qd3,qd4");
        assert_eq!(lines.len(), 6);
        assert!(lines[1..].iter().all(|l| l.split(',').count() == 9));
        assert_eq!(open_loop_csv::<2>(&[]), "t,q1,q2,qd1,qd2\n");
    }
}
