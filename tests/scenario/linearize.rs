//! `armdyn design linearize` against `armdyn design force`: the thesis scenario's closed loop,
//! linearised in contact, has the force loop's poles of the one-dimensional design model
//! (PI + FF + VD stable, PI + FF unstable), each within 1 % in the s plane.

use armdyn::control::design::{analyse, default_sweep, ForceGains, ForceLoop};
use armdyn::scenario::{
    contact_model,
    linearize::{linearize, linearize_equilibrium, nominal},
    Scenario,
};
use armdyn::sim::linearize::Modes;
use armdyn::sim::Sample;
use nalgebra::Complex;

fn scenario(kvd: f64) -> Scenario {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios/thesis-hybrid.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.replace("kvd = 2000.0", &format!("kvd = {kvd:?}"));
    Scenario::parse(
        "thesis-hybrid.toml",
        &text,
        std::path::Path::new(path).parent().unwrap(),
    )
    .unwrap()
}

/// The design model's poles and the linearisation's at `t`: every design pole has an
/// eigenvalue within 1 % (relative, s plane); returns whether the linearisation is stable.
fn check(kvd: f64, t: f64) -> bool {
    let s = scenario(kvd);
    let m = contact_model(&s).unwrap();
    let model = ForceLoop::new(m.mass_kg, m.stiffness, m.damping, s.control_dt_s, false).unwrap();
    let gains = ForceGains {
        kfp: 20.0,
        kfi: 5.0,
        kvd,
    };
    let design = analyse(&model, &gains, default_sweep(m.stiffness));
    let lin = linearize(&s, t).unwrap();
    assert!(
        lin.next_state_mismatch <= 1e-12,
        "{}",
        lin.next_state_mismatch
    );
    let modes = Modes::of(&lin.a, lin.dt, &lin.labels);
    let dt = s.control_dt_s;
    for z in design.poles.z() {
        let sd: Complex<f64> = z.ln() / dt;
        let best = modes
            .modes
            .iter()
            .map(|m| (m.s - sd).norm() / sd.norm())
            .fold(f64::INFINITY, f64::min);
        println!("kvd {kvd}: design pole z = {z:.6}, nearest eigenvalue off by {best:.2e}");
        assert!(
            best <= 0.01,
            "design pole {z} not found (nearest off by {best:e})"
        );
    }
    assert_eq!(modes.stable(), design.stable);
    modes.stable()
}

#[test]
fn damped_force_loop_poles_are_found_and_stable() {
    assert!(check(2000.0, 2.5));
}

#[test]
fn undamped_force_loop_poles_are_found_and_unstable() {
    // PI + FF bounces: 2.014 s is a sample in contact with no actuator saturated (at most
    // samples of the bounce the tool is off the surface, or d3's actuator saturates, and the
    // loop there is open).
    assert!(!check(0.0, 2.014));
}

/// Whether a run settles: in contact throughout after the first touch, and the part of the
/// RMS force error of the last 3 s that is not the steady offset (the mean error of the last
/// 1 s: a loop that converges to a biased force, as with an uncompensated tool, has settled)
/// within 20 % of the nominal force.
fn settles(s: &Scenario, r: &armdyn::scenario::Outcome) -> (bool, String) {
    let m = armdyn::scenario::metrics_json(s, r);
    let losses = m["contact_losses_after_first_touch"]
        .as_u64()
        .unwrap_or(u64::MAX);
    let rms = m["normal_force_rms_error_last3s_n"]
        .as_f64()
        .unwrap_or(f64::INFINITY);
    let offset = m["normal_force_steady_error_n"].as_f64().unwrap_or(0.0);
    let varying = (rms * rms - offset * offset).max(0.0).sqrt();
    let nominal = s.force.as_ref().unwrap().value_n.abs();
    (
        losses == 0 && varying <= 0.2 * nominal,
        format!(
            "{losses} contact losses, RMS force error of the last 3 s {rms:.3} N, steady offset \
             {offset:.3} N, of {nominal} N"
        ),
    )
}

/// The last sample of the run in contact (normal push above 20 % of the nominal force, so
/// that the contact model is on its smooth branch), force controlled, with no actuator
/// saturated, and one period before the end.
fn late_contact_sample<const N: usize>(s: &Scenario, samples: &[Sample<N>]) -> Option<f64> {
    let nominal = s.force.as_ref()?.value_n.abs();
    let end = samples.last()?.t - s.control_dt_s;
    samples
        .iter()
        .rev()
        .find(|x| {
            x.t <= end
                && x.force_controlled
                && x.wrench.fixed_rows::<3>(0).norm() > 0.2 * nominal
                && x.tau_command == x.tau
        })
        .map(|x| x.t)
}

/// Surface stiffnesses every shipped contact scenario is also run on, N/m.
const STIFFNESS_VARIANTS_N_PER_M: [f64; 3] = [1e3, 1e4, 1e5];

/// For every shipped contact scenario, as shipped, with the force law's velocity damping
/// removed (PI + FF: the thesis's unstable law), and on surfaces of 1, 10 and 100 kN/m, the
/// linearisation at a late sample in contact says the run settles (stable, and the run in one
/// mode over the last second: `Linearization::settles`) exactly when the simulation
/// settles. Each is run nominal (no sensor
/// noise, no faults, the description's plant) so that the simulated loop is the one
/// linearised.
#[test]
fn linearised_stability_agrees_with_settling_for_every_shipped_contact_scenario() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let (mut checked, mut unstable, mut stable) = (0, 0, 0);
    let mut switching = Vec::new();
    for path in files {
        // Sweep files are distributions over a scenario, not scenarios: skipped.
        let Ok(shipped) = Scenario::load(&path) else {
            assert!(
                std::fs::read_to_string(&path).unwrap().contains("[sweep]"),
                "{} does not load",
                path.display()
            );
            continue;
        };
        let Some(force) = &shipped.force else {
            continue;
        };
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let mut variants = vec![(name.clone(), shipped.clone())];
        if force.gains.2 != 0.0 {
            let mut pi_ff = shipped.clone();
            pi_ff.force.as_mut().unwrap().gains.2 = 0.0;
            variants.push((format!("{name} without velocity damping"), pi_ff));
        }
        // The same loop on surfaces of other stiffness (every surface of the scene), without
        // the safety supervisor: a stiffer surface than the gains were designed for makes the
        // first impact bounce, which its contact-lost check may trip on and hold the arm; a
        // trip on a transient says nothing of the loop's stability, which is what is compared.
        for stiffness in STIFFNESS_VARIANTS_N_PER_M {
            let mut other = shipped.clone();
            for surface in &mut other.surfaces {
                surface.stiffness = stiffness;
            }
            other.safety.enabled = false;
            variants.push((format!("{name} at {} kN/m", stiffness / 1e3), other));
        }
        for (label, variant) in variants {
            let mut s = nominal(&variant);
            s.plant = armdyn::scenario::PlantSpec {
                friction_viscous: s.plant.friction_viscous.clone(),
                friction_coulomb: s.plant.friction_coulomb.clone(),
                friction_smoothing: s.plant.friction_smoothing,
                ..armdyn::scenario::PlantSpec::nominal(s.plant.mass_scale.len())
            };
            let (r, at) = armdyn::with_robot_named!(s.robot.as_str(), |robot: R, N, _m| {
                let recorded = armdyn::scenario::prepare_for(&s, robot)
                    .unwrap()
                    .execute(&s, |_| {})
                    .unwrap();
                let at = late_contact_sample(&s, &recorded.samples);
                (recorded.outcome, at)
            })
            .unwrap();
            let (settled, why) = settles(&s, &r);
            let Some(at) = at else {
                // Never in steady contact: it cannot have settled.
                assert!(
                    !settled,
                    "{label}: settles ({why}) but has no sample in contact"
                );
                continue;
            };
            let lin = linearize(&s, at).unwrap_or_else(|e| panic!("{label} at {at} s: {e}"));
            let modes = Modes::of(&lin.a, lin.dt, &lin.labels);
            let largest = modes
                .modes
                .iter()
                .find(|m| !m.is_neutral())
                .map_or(0.0, |m| m.magnitude);
            println!(
                "{label}: at {at:.3} s, largest |z| {largest:.6} ({}, {} exits from its mode in \
                 the last second); simulation {} ({why})",
                if modes.stable() { "stable" } else { "unstable" },
                lin.mode_exits,
                if settled {
                    "settles"
                } else {
                    "does not settle"
                }
            );
            if lin.mode_exits > 0 {
                switching.push(label.clone());
            }
            assert_eq!(
                lin.settles(),
                settled,
                "{label}: linearisation at {at} s says stable = {} with {} exits from its mode in \
                 the last second, the simulation: {why}",
                modes.stable(),
                lin.mode_exits
            );
            checked += 1;
            if settled {
                stable += 1;
            } else {
                unstable += 1;
            }
        }
    }
    println!(
        "{checked} loops agree: {stable} settle, {unstable} do not; of these, {} switch between \
         force and position control: {switching:?}",
        switching.len()
    );
    assert!(
        stable >= 10 && unstable >= 1,
        "{stable} settling, {unstable} not"
    );
}

/// `panda-tool-uncompensated` on a 100 kN/m table: the biased reading (the tool's weight read
/// as a pull) leaves the contact selection's switch-in and loss levels 1.5 N of contact force
/// apart, and after each switch the stiff contact's transient crosses the loss level: the run
/// cycles between force and position control. The loop linearised in force control is stable
/// there, and so is its equilibrium (the reference rests from 10.6 s), found by Newton's method
/// from the cycling run's state; the analysis reports the cycle through the switch.
#[test]
fn a_switching_cycle_is_reported_and_its_force_mode_equilibrium_is_stable() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/panda-tool-uncompensated.toml"
    );
    let mut s = Scenario::load(std::path::Path::new(path)).unwrap();
    for surface in &mut s.surfaces {
        surface.stiffness = 1e5;
    }
    s.safety.enabled = false;
    let at = 11.0;
    let lin = linearize(&s, at).unwrap();
    let modes = Modes::of(&lin.a, lin.dt, &lin.labels);
    println!(
        "at {at} s: {} exits from its mode in the last second, stable = {}",
        lin.mode_exits,
        modes.stable()
    );
    assert!(lin.mode_exits >= 4, "{}", lin.mode_exits);
    assert!(modes.stable());
    assert!(!lin.settles());
    assert!(lin.equilibrium.is_none());

    let eq = linearize_equilibrium(&s, at).unwrap();
    let found = eq.equilibrium.as_ref().unwrap();
    println!("equilibrium: {found:?}");
    assert!(found.residual <= 1e-11, "{found:?}");
    assert!(eq.qd.iter().all(|v| v.abs() < 1e-9), "{:?}", eq.qd);
    assert!(found.joint_distance < 1e-2, "{found:?}");
    assert!(Modes::of(&eq.a, eq.dt, &eq.labels).stable());
    // The same map, the same switches counted before the sample.
    assert_eq!(eq.mode_exits, lin.mode_exits);
}

/// A moving reference has no rest point: the thesis scenario at 3 s (the tool sliding along
/// its line) is refused by name, not linearised somewhere arbitrary.
#[test]
fn an_equilibrium_is_refused_while_the_reference_moves() {
    let err = linearize_equilibrium(&scenario(2000.0), 3.0).unwrap_err();
    assert!(err.to_string().contains("the reference moves"), "{err}");
}
