"""The controllers in a loop nobody here wrote: MuJoCo as the plant (``armdyn.mujoco``).

With the controller's model exactly (``IDEAL``) and with joint armature, damping and friction
it does not know (``UNKNOWNS``), the shipped contact scenarios and variants of them (other
heights, tilts, forces) keep contact, trip nothing, saturate nothing, settle, and stay within
twice the project's simulator's force and path errors plus 0.5 N and 0.5 mm; a NaN sensor
sample and a surface that ends trip the supervisor as in the project's simulator. Needs
``pip install -r python/requirements-mujoco.txt`` (required under CI)."""

import math

import pytest

import armdyn
from conftest import ROOT, require

require("mujoco")
from armdyn import mujoco as mj  # noqa: E402

SCENARIOS = ROOT / "scenarios"


def _bars(name, simulated, mujoco):
    """The bars of a MuJoCo run against the project's simulator's."""
    assert mujoco["contact_losses_after_first_touch"] == 0, name
    assert not mujoco["safety_trips"], (name, mujoco["safety_trips"])
    assert mujoco["saturated_samples_total"] <= simulated["saturated_samples_total"], name
    assert mujoco["normal_force_settling_time_s"] is not None, name
    for key, slack in (("normal_force_rms_error_last3s_n", 0.5), ("path_rms_error_contact_mm", 0.5)):
        ours, theirs = simulated[key], mujoco[key]
        assert theirs <= 2 * ours + slack, f"{name}: {key} {theirs:.3f} against {ours:.3f}"


@pytest.mark.parametrize("file", ["thesis-hybrid.toml", "ur5-press-table.toml",
                                  "ur5-oblique.toml", "panda-wipe.toml", "panda-cylinder.toml"])
def test_the_ideal_plant_agrees_with_the_projects_simulator(file):
    simulated = armdyn.run_scenario(SCENARIOS / file).metrics
    _bars(file, simulated, mj.run(SCENARIOS / file, None, mj.IDEAL))


@pytest.mark.parametrize("file", ["thesis-hybrid.toml", "ur5-press-table.toml",
                                  "ur5-oblique.toml", "panda-wipe.toml"])
def test_unknown_armature_damping_and_friction_keep_the_bars(file):
    simulated = armdyn.run_scenario(SCENARIOS / file).metrics
    _bars(file, simulated, mj.run(SCENARIOS / file, None, mj.UNKNOWNS))


def _ur5_table(height, tilt_deg, force):
    """The UR5's table scenario at another height, tilted about x, pressed with another force."""
    import tomllib

    s = tomllib.loads((SCENARIOS / "ur5-press-table.toml").read_text())
    dz = height - 0.25
    for p in s["reference"]["points"]:
        p[3] += dz
    t = math.radians(tilt_deg)
    surface = s["surfaces"][0]
    surface["point"][2] += dz
    surface["normal"] = [0.0, -math.sin(t), math.cos(t)]
    s["force"]["value"] = force
    return s


@pytest.mark.parametrize("height, tilt, force", [(0.20, 0.0, 30.0), (0.30, 0.0, 20.0),
                                                 (0.25, 0.0, 45.0), (0.25, 10.0, 30.0)])
def test_other_tables_and_forces_keep_the_bars_with_the_unknowns(height, tilt, force):
    s = _ur5_table(height, tilt, force)
    simulated = armdyn.run_scenario(s).metrics
    _bars(f"ur5 table z={height} tilt={tilt} f={force}", simulated, mj.run(s, None, mj.UNKNOWNS))


@pytest.mark.parametrize("file", ["faults/panda-nan.toml", "faults/scara-surface-ends.toml",
                                  "faults/panda-surface-ends.toml"])
def test_faults_trip_the_supervisor_as_in_the_projects_simulator(file):
    simulated = armdyn.run_scenario(SCENARIOS / file).metrics
    mujoco = mj.run(SCENARIOS / file, None, mj.UNKNOWNS)
    first = lambda m: (m["safety_trips"][0]["cause"], m["safety_trips"][0]["reaction"])  # noqa: E731
    assert first(mujoco) == first(simulated), (file, mujoco["safety_trips"])
    assert mujoco["nan_torque_samples"] == 0


def test_a_run_writes_the_files_of_a_simulated_run(tmp_path):
    metrics = mj.run(SCENARIOS / "ur5-press-table.toml", tmp_path / "out", mj.IDEAL)
    assert metrics["robot"] == "ur5"
    for f in ("trajectory.csv", "metrics.json", "normal_force.svg", "view.html"):
        assert (tmp_path / "out" / f).is_file(), f


def test_bad_input_is_refused():
    with pytest.raises(SystemExit):
        mj.main(["scenarios/ur5-press-table.toml", "--out", "/tmp/x", "--damping", "-1"])
    assert mj.main([str(SCENARIOS / "nope.toml"), "--out", "/tmp/x"]) == 1


def test_a_surface_mujoco_has_no_geom_for_is_refused_by_name(tmp_path):
    # MuJoCo has no torus: the pipe bend is refused before anything runs, naming the surface.
    with pytest.raises(mj.MujocoError, match="surface 0: .*'torus'"):
        mj.run(SCENARIOS / "ur5-pipe-bend.toml", tmp_path / "out", mj.IDEAL)
    assert not (tmp_path / "out").exists()


def test_the_panda_on_its_cylinder_needs_the_armature_in_the_controllers_model():
    # The Menagerie's armature (0.1 kg m^2) is 2 to 15 times the Panda's wrist inertia: with
    # it unknown the redundant arm's null space goes unstable on the cylinder
    # (docs/mujoco.md); told in `controller_armature`, the controller keeps the bars.
    file = SCENARIOS / "panda-cylinder.toml"
    simulated = armdyn.run_scenario(file).metrics
    _bars("panda-cylinder, armature known", simulated,
          mj.run(file, None, mj.UNKNOWNS, controller_knows_armature=True))
