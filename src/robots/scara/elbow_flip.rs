//! The elbow switch as a planned manoeuvre (feature `std`): where the reference needs the
//! other elbow, the Cartesian reference pauses ([`crate::trajectory::pause`]), the arm moves
//! in joint space from one elbow's solution to the other's at the pause point (lifting the
//! tool first if a clearance above it is asked for), and the reference resumes, shifted in
//! time by the manoeuvre. Every joint move is a rest-to-rest quintic (continuous position,
//! velocity and acceleration), lies inside the joint limits (a straight line between two
//! configurations inside the limit box), and is as short as the model allows: the shortest
//! duration, found by scaling time, for which its inverse dynamics stays within a share of
//! each actuator's effort limit (thesis Section 4.4 made safe).
//!
//! With [`FlipOptions::optimal`] each move is instead the shortest optimised move within the
//! same share ([`crate::optimal::shortest_move`]: control-limited iLQR on the generated
//! derivatives, torque limits as a box, joint limits and the rest at the goal by an
//! augmented Lagrangian), which uses each actuator's share for longer than the quintic's
//! single peak does.

use std::sync::Arc;

use super::elbow_plan::{ElbowPlan, SwitchPolicy};
use super::{Elbow, ScaraGeometry};
use crate::model::{DynamicsDerivatives, JointVector, RobotModel};
use crate::optimal::{
    optimise_move, shortest_fitting, shortest_move, IlqrOptions, MoveProblem, OptimalMove,
};
use crate::target::JointTarget;
use crate::trajectory::pause::Pause;
use crate::trajectory::{sample, CartesianTrajectory};

/// Settings of a planned flip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlipOptions {
    /// Largest share of each actuator's effort limit the planned move may use (default 0.8).
    pub max_effort_share: f64,
    /// Lowest tool height during the flip, m (default, and never less than: the reference's
    /// height at the pause).
    pub clearance_z_m: Option<f64>,
    /// Length of the reference's smooth stop before and start after the flip, s (default 0.5).
    pub ramp_s: f64,
    /// How far above the clearance the flip is planned, m (default 1 mm), so that tracking
    /// errors keep the tool above it.
    pub clearance_margin_m: f64,
    /// Shortest joint move, s (default 0.05 s: fifty 1 ms control periods, so that a sampled
    /// controller can follow even a tiny lift).
    pub min_move_s: f64,
    /// Sampling of the reference when looking for the pause point, s (default 0.005).
    pub sample_dt_s: f64,
    /// Each move the shortest optimised move within the share instead of the quintic
    /// (default `false`).
    pub optimal: bool,
    /// Knot spacing of an optimised move, s (default 0.001: the thesis's control period,
    /// so that the controller samples the plan at its knots).
    pub optimal_step_s: f64,
    /// RK4 steps of an optimised move per knot step (default 1: the thesis plant's).
    pub optimal_substeps: usize,
    /// How far inside each joint limit an optimised move stays, rad or m (default 0.01, at
    /// most the start's and the goal's own distance): room for the tracking error, since the
    /// optimum runs along a limit it meets.
    pub optimal_limit_margin: f64,
    /// Largest joint speeds of an optimised move, rad/s or m/s (default `None`: each move's
    /// quintic's peak joint speeds, so that no joint moves faster than in the quintic flip
    /// and the two differ only in how they use the effort).
    pub optimal_max_joint_speed: Option<JointVector<4>>,
}

impl Default for FlipOptions {
    fn default() -> Self {
        Self {
            max_effort_share: 0.8,
            clearance_z_m: None,
            ramp_s: 0.5,
            clearance_margin_m: 1e-3,
            min_move_s: 0.05,
            sample_dt_s: 0.005,
            optimal: false,
            optimal_step_s: 0.001,
            optimal_substeps: 1,
            optimal_limit_margin: 0.01,
            optimal_max_joint_speed: None,
        }
    }
}

/// Why a flip cannot be planned.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FlipError {
    /// The reference itself is not reachable (the workspace planner's message).
    #[error("{0}")]
    Workspace(String),
    /// A setting is out of range.
    #[error("{0}")]
    Setting(&'static str),
    /// No instant of the switch window has both elbows' solutions.
    #[error(
        "no pause point for the elbow switch near t = {0:.3} s: the two solutions never coexist"
    )]
    NoPausePoint(f64),
    /// The clearance cannot be reached at the pause point.
    #[error("clearance z = {z:.4} m cannot be reached at the pause point ({why})")]
    Clearance {
        /// Height asked for, m.
        z: f64,
        /// Why not.
        why: String,
    },
    /// Even a very slow move exceeds the effort share (gravity alone is too much).
    #[error("no duration up to {0} s keeps the move within the effort share")]
    TooSlow(f64),
    /// The optimiser found no move (its message).
    #[error("the optimised flip: {0}")]
    Optimal(String),
}

/// A rest-to-rest joint move `q(t) = from + (to - from) S((t - start) / T)`, `S` the quintic
/// blend `10 u^3 - 15 u^4 + 6 u^5`, or an optimised profile of the same duration.
#[derive(Clone, Debug, PartialEq)]
pub struct JointMove {
    /// Start, wall-clock s.
    pub start_s: f64,
    /// Duration `T`, s.
    pub duration_s: f64,
    /// Start configuration.
    pub from: JointVector<4>,
    /// End configuration.
    pub to: JointVector<4>,
    /// The optimised profile from `from` to `to` over `duration_s`; `None`: the quintic.
    pub profile: Option<Arc<OptimalMove<4>>>,
}

impl JointMove {
    /// End, s.
    #[must_use]
    pub fn end_s(&self) -> f64 {
        self.start_s + self.duration_s
    }

    /// The joint reference at wall time `t` (held at the ends outside the move).
    #[must_use]
    pub fn at(&self, t: f64) -> JointTarget<4> {
        if let Some(profile) = &self.profile {
            return profile.at(t - self.start_s);
        }
        let u = ((t - self.start_s) / self.duration_s).clamp(0.0, 1.0);
        let (u2, u3) = (u * u, u * u * u);
        let s = u3 * (10.0 - 15.0 * u + 6.0 * u2);
        let ds = 30.0 * u2 * (1.0 - u) * (1.0 - u) / self.duration_s;
        let dds = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2) / (self.duration_s * self.duration_s);
        let d = self.to - self.from;
        JointTarget {
            q: self.from + d * s,
            qd: d * ds,
            qdd: d * dds,
        }
    }

    /// The largest `|tau_i| / effort_i` of the move's inverse dynamics over `samples` points
    /// (an optimised move: the largest of its knots' torques, which a controller sampling
    /// the knots applies).
    #[must_use]
    pub fn effort_fraction<R: RobotModel<4>>(&self, robot: &R, samples: usize) -> f64 {
        // An optimised move's torques are its knots' (held over each control period).
        if let Some(profile) = &self.profile {
            return profile.peak_effort_share;
        }
        let limits = robot.effort_limits();
        (0..=samples)
            .map(|k| {
                let j = self.at(self.start_s + self.duration_s * k as f64 / samples as f64);
                let tau = robot.mass_matrix(&j.q) * j.qdd
                    + robot.coriolis(&j.q, &j.qd)
                    + robot.gravity(&j.q);
                (0..4)
                    .map(|i| (tau[i] / limits[i]).abs())
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max)
    }
}

/// Points at which a move's inverse dynamics is checked.
pub const EFFORT_SAMPLES: usize = 400;
/// Longest move considered, s.
pub const MAX_MOVE_S: f64 = 60.0;

/// The shortest duration (to 0.1 %) of the rest-to-rest move `from -> to` whose inverse
/// dynamics stays within `share` of every effort limit (0 for no motion).
///
/// # Errors
///
/// [`FlipError::TooSlow`] if even [`MAX_MOVE_S`] is too fast (or gravity alone is too much).
pub fn shortest_duration<R: RobotModel<4>>(
    robot: &R,
    from: &JointVector<4>,
    to: &JointVector<4>,
    share: f64,
) -> Result<f64, FlipError> {
    if (to - from).amax() == 0.0 {
        return Ok(0.0);
    }
    let fits = |t: f64| {
        JointMove {
            start_s: 0.0,
            duration_s: t,
            from: *from,
            to: *to,
            profile: None,
        }
        .effort_fraction(robot, EFFORT_SAMPLES)
            <= share
    };
    if !fits(MAX_MOVE_S) {
        return Err(FlipError::TooSlow(MAX_MOVE_S));
    }
    Ok(shortest_fitting(MAX_MOVE_S, 1e-3, fits))
}

/// The shortest optimised move `from -> to` within the options' share (at least
/// [`FlipOptions::min_move_s`] long: the minimum-effort move of that duration if the shortest
/// is shorter).
fn optimal_leg<R: DynamicsDerivatives<4>>(
    robot: &R,
    from: &JointVector<4>,
    to: &JointVector<4>,
    options: &FlipOptions,
) -> Result<OptimalMove<4>, FlipError> {
    let (lo, hi) = (robot.lower_limits(), robot.upper_limits());
    let room = (0..4)
        .map(|i| {
            (from[i] - lo[i])
                .min(hi[i] - from[i])
                .min(to[i] - lo[i])
                .min(hi[i] - to[i])
        })
        .fold(f64::INFINITY, f64::min);
    let margin = options.optimal_limit_margin.min(room.max(0.0));
    // The quintic's peak speed is 15/8 of its mean: (to - from) 15 / (8 T).
    let speed = match options.optimal_max_joint_speed {
        Some(v) => v,
        None => {
            let t = shortest_duration(robot, from, to, options.max_effort_share)?;
            (to - from).map(|d| (d.abs() * 15.0 / (8.0 * t.max(options.min_move_s))).max(1e-6))
        }
    };
    let problem = MoveProblem {
        from: *from,
        to: *to,
        duration_s: options.min_move_s,
        step_s: options.optimal_step_s.min(options.min_move_s / 2.0),
        substeps: options.optimal_substeps,
        max_effort_share: options.max_effort_share,
        limit_margin: margin,
        max_joint_speed: Some(speed),
    };
    let ilqr = IlqrOptions::default();
    let fail = |e: crate::optimal::PlanError| FlipError::Optimal(e.to_string());
    // A move whose quintic is already shorter than the shortest allowed needs no search:
    // the optimised one would be shorter still.
    let quintic = crate::optimal::shortest_quintic(robot, from, to, options.max_effort_share)
        .map_err(fail)?;
    if quintic > options.min_move_s {
        let shortest = shortest_move(robot, &problem, &ilqr).map_err(fail)?;
        if shortest.duration_s() >= options.min_move_s {
            return Ok(shortest);
        }
    }
    optimise_move(robot, &problem, &ilqr).map_err(fail)
}

/// One planned flip.
#[derive(Clone, Debug, PartialEq)]
pub struct ElbowFlip {
    /// The reference's pause.
    pub pause: Pause,
    /// The joint moves filling the hold, in order (lift, flip, lower; absent ones omitted).
    pub moves: Vec<JointMove>,
    /// Configuration before.
    pub from: Elbow,
    /// Configuration after.
    pub to: Elbow,
    /// Lowest tool height planned during the flip, m.
    pub clearance_z_m: f64,
    /// Largest planned `|tau_i| / effort_i` over the moves.
    pub planned_effort_fraction: f64,
}

impl ElbowFlip {
    /// The move that swings the arm to the other elbow (between the lift and the lowering).
    #[must_use]
    pub fn swing(&self) -> Option<&JointMove> {
        self.moves
            .iter()
            .find(|m| m.from[0] != m.to[0] || m.from[1] != m.to[1])
    }

    /// Wall-clock start and end of the joint moves, s.
    #[must_use]
    pub fn interval(&self) -> (f64, f64) {
        let start = self.moves.first().map_or(0.0, |m| m.start_s);
        (start, self.moves.last().map_or(start, JointMove::end_s))
    }
}

/// Plans every elbow switch `trajectory` needs as a flip (none if one elbow serves it).
/// Returns the flips and the elbow plan in wall-clock time of the paused reference.
///
/// # Errors
///
/// [`FlipError`] naming what cannot be planned.
pub fn plan_flips<R: DynamicsDerivatives<4>>(
    robot: &R,
    geometry: &ScaraGeometry,
    trajectory: &dyn CartesianTrajectory,
    options: &FlipOptions,
) -> Result<(Vec<ElbowFlip>, ElbowPlan), FlipError> {
    if !(options.max_effort_share > 0.0 && options.max_effort_share <= 1.0) {
        return Err(FlipError::Setting("the effort share must be in (0, 1]"));
    }
    if !(options.ramp_s > 0.0 && options.sample_dt_s > 0.0) {
        return Err(FlipError::Setting(
            "the ramp and the sampling step must be > 0 s",
        ));
    }
    let plan = geometry
        .plan_trajectory(trajectory, options.sample_dt_s, SwitchPolicy::Latest)
        .map_err(|e| FlipError::Workspace(e.to_string()))?;
    let samples = sample(trajectory, options.sample_dt_s);
    let mut flips = Vec::new();
    let mut switches = Vec::new();
    let mut shift = 0.0;
    let mut previous_end = f64::NEG_INFINITY;
    let mut elbow = plan.initial();
    for sw in plan.switches() {
        // The pause point: inside the window where both solutions exist, away from the
        // previous flip, where the joint jump is smallest.
        let (old, new) = (elbow, sw.to);
        let mut best: Option<(f64, JointVector<4>, JointVector<4>, f64)> = None;
        for s in samples
            .iter()
            .filter(|s| s.t >= sw.earliest && s.t < sw.latest)
        {
            if s.t - options.ramp_s / 2.0 < previous_end {
                continue;
            }
            let (Ok(a), Ok(b)) = (
                geometry.inverse(&s.position, s.yaw(), old),
                geometry.inverse(&s.position, s.yaw(), new),
            ) else {
                continue;
            };
            let jump = (a - b).amax();
            if best.as_ref().is_none_or(|(_, _, _, j)| jump < *j) {
                best = Some((s.t, a, b, jump));
            }
        }
        let (at_s, q_a, q_b, _) = best.ok_or(FlipError::NoPausePoint(sw.t))?;
        let z_pause = geometry.forward(&q_a).0.z;
        let z_clear = options.clearance_z_m.map_or(z_pause, |z| z.max(z_pause));
        let z_flip = z_clear + options.clearance_margin_m;
        let lift = |q: &JointVector<4>| -> Result<JointVector<4>, FlipError> {
            let mut l = *q;
            l[2] = q[2] - (z_flip - z_pause);
            if geometry.within_limits(&l) {
                Ok(l)
            } else {
                Err(FlipError::Clearance {
                    z: z_clear,
                    why: format!("d3 would be {:.4} m, outside its limits", l[2]),
                })
            }
        };
        let (a_up, b_up) = (lift(&q_a)?, lift(&q_b)?);
        let share = options.max_effort_share;
        let mut legs = Vec::new();
        for (from, to) in [(q_a, a_up), (a_up, b_up), (b_up, q_b)] {
            if (to - from).amax() == 0.0 {
                continue;
            }
            let leg = if options.optimal {
                let profile = optimal_leg(robot, &from, &to, options)?;
                (from, to, profile.duration_s(), Some(Arc::new(profile)))
            } else {
                let t = shortest_duration(robot, &from, &to, share)?;
                (from, to, t.max(options.min_move_s), None)
            };
            legs.push(leg);
        }
        let hold_s: f64 = legs.iter().map(|l| l.2).sum();
        let pause = Pause {
            at_s,
            ramp_s: options.ramp_s,
            hold_s,
        };
        let mut start = at_s + shift + options.ramp_s / 2.0;
        let mut moves = Vec::new();
        for (from, to, duration_s, profile) in legs {
            moves.push(JointMove {
                start_s: start,
                duration_s,
                from,
                to,
                profile,
            });
            start += duration_s;
        }
        let planned_effort_fraction = moves
            .iter()
            .map(|m| m.effort_fraction(robot, EFFORT_SAMPLES))
            .fold(0.0, f64::max);
        let flip = ElbowFlip {
            pause,
            moves,
            from: old,
            to: new,
            clearance_z_m: z_clear,
            planned_effort_fraction,
        };
        switches.push((flip.interval().1, new));
        shift += pause.shift_s();
        previous_end = at_s + options.ramp_s / 2.0;
        elbow = new;
        flips.push(flip);
    }
    Ok((
        flips,
        ElbowPlan::from_switch_times(plan.initial(), &switches),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Scara;
    use crate::robots::scara::thesis::ThreeZone;

    #[test]
    fn the_three_zone_flip_is_within_limits_and_effort() {
        let g = ScaraGeometry::from_model(&Scara);
        let (flips, plan) =
            plan_flips(&Scara, &g, &ThreeZone::new(), &FlipOptions::default()).unwrap();
        assert_eq!(flips.len(), 1);
        let f = &flips[0];
        assert_eq!((f.from, f.to), (Elbow::Down, Elbow::Up));
        assert!(
            f.planned_effort_fraction <= 0.8 + 1e-12,
            "{}",
            f.planned_effort_fraction
        );
        assert!(
            f.planned_effort_fraction > 0.75,
            "the shortest move uses the share: {}",
            f.planned_effort_fraction
        );
        let (start, end) = f.interval();
        assert_eq!(plan.elbow_at(start), Elbow::Down);
        assert_eq!(plan.elbow_at(end), Elbow::Up);
        for m in &f.moves {
            for k in 0..=1000 {
                let j = m.at(m.start_s + m.duration_s * f64::from(k) / 1000.0);
                assert!(g.within_limits(&j.q), "{}", j.q);
            }
        }
    }

    #[test]
    fn halving_the_share_lengthens_a_gravity_free_move_by_sqrt_2() {
        // q1, q2, q4 move and d3 stays: no gravity acts on the moving joints, and the torque
        // of a time-scaled move is M qdd + c, both proportional to 1 / T^2.
        let from = JointVector::<4>::new(1.2, -2.0, 0.25, 0.0);
        let to = JointVector::<4>::new(-0.7, 2.0, 0.25, 0.3);
        let t8 = shortest_duration(&Scara, &from, &to, 0.8).unwrap();
        let t4 = shortest_duration(&Scara, &from, &to, 0.4).unwrap();
        assert!((t4 / t8 / 2_f64.sqrt() - 1.0).abs() < 3e-3, "{t8} {t4}");
    }
}
