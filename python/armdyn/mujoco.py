"""A scenario's controller in a loop nobody here wrote: MuJoCo as the plant.

``python3 -m armdyn.mujoco SCENARIO.toml --out DIR`` builds a MuJoCo model of the scenario's
robot from the generator's URDF, adds the tool as a small sphere at the tip and the
scenario's surfaces as geoms, and steps MuJoCo at the scenario's plant period while
``armdyn.Controller`` steps at the control period: MuJoCo's own integrator (RK4), its own soft
contact and friction, and what the controller's model does not know (joint armature, viscous
damping and dry friction, see ``UNKNOWNS``). The force sensor reads MuJoCo's contact force
at the tool; the scenario's sensor model (noise, bias, filter) and its sensor faults act on it
inside the controller, as in the project's simulator. It writes the same ``trajectory.csv``,
``metrics.json``, figures and ``view.html`` as ``armdyn run scenario``.

``python3 -m armdyn.mujoco compare SCENARIO.toml ... --out DIR`` runs each file in the
project's simulator and in MuJoCo, with and without the unknown joint effects, and prints a
Markdown table of the force and path metrics side by side.

The contact mapping: the project's surfaces are springs, ``f_n = k d + b d'`` for a
penetration ``d`` of the tool point. MuJoCo's soft constraint along a contact normal obeys
``a1 + i (B v + K i r) = (1 - i) a0`` (``i`` the impedance ``solimp``, ``a0`` the
unconstrained acceleration, and in MuJoCo's direct form ``solref = (-s0, -s1)``:
``K = s0 / i^2``, ``B = s1 / i``). For a body of effective mass ``m`` along the normal that is
a mass ``m / (1 - i)`` on a spring of stiffness ``m s0 / (1 - i)`` and a damper of
``m s1 / (1 - i)``. So each surface gets ``solimp = (i, i)`` with ``i = IMPEDANCE`` (the mass
raised by 1 %) and ``solref = (-k (1 - i) / m, -b (1 - i) / m)``, with
``m = 1 / (n^T J M^-1 J^T n)`` the arm's apparent mass along the surface's normal at the tool,
from MuJoCo's own ``M`` and ``J``, updated every control period. The tool is a sphere of
radius ``TOOL_RADIUS`` and every surface is moved back by it, so that contact starts when the
tool point reaches the surface.
Needs ``pip install -r python/requirements-mujoco.txt`` (MuJoCo, pinned; not a dependency of
the package).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import armdyn

try:
    import mujoco
except ImportError as e:  # pragma: no cover
    raise SystemExit(
        "armdyn.mujoco needs MuJoCo: python3 -m pip install -r python/requirements-mujoco.txt"
    ) from e

#: Radius of the tool's sphere, m; the surfaces are moved back by it.
TOOL_RADIUS = 0.005
#: MuJoCo's impedance of the surfaces' contacts (``solimp`` = (i, i, ...)): the arm's mass
#: along the normal is raised by ``1 / (1 - i)`` in contact.
IMPEDANCE = 0.01
#: Half thickness of a plane patch's box, m.
PLATE_HALF_THICKNESS = 0.02
#: Half length of a cylinder's geom, m (the project's cylinders are infinite).
CYLINDER_HALF_LENGTH = 2.0


@dataclass(frozen=True)
class Unknowns:
    """What the controller's model does not know, per joint: rotor inertia reflected to the
    joint (``armature``, kg m^2 or kg), viscous damping (``damping``, N m s/rad or N s/m) and
    dry friction (``friction``, MuJoCo's ``frictionloss``, N m or N)."""

    armature: float
    damping: float
    friction: float


#: Sizes of the published MuJoCo models of these arms: armature 0.1 kg m^2 on every joint of
#: the MuJoCo Menagerie's Panda and UR5e, damping 1 N m s/rad (the Menagerie Panda's default
#: class), dry friction 0.1 N m (robosuite's Panda sets frictionloss of that order).
UNKNOWNS = Unknowns(armature=0.1, damping=1.0, friction=0.1)
#: The ideal arm: the controller's model exactly.
IDEAL = Unknowns(armature=0.0, damping=0.0, friction=0.0)


class MujocoError(RuntimeError):
    """A scenario this plant cannot build (a robot without a URDF, an unsupported fault)."""


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _frame(z, x_hint):
    """A rotation matrix whose third column is ``z`` and first is ``x_hint`` made square to it."""
    z = _unit(z)
    x = np.asarray(x_hint, dtype=float) - z * np.dot(x_hint, z)
    if np.linalg.norm(x) < 1e-9:
        x = np.cross(z, [1.0, 0.0, 0.0])
        if np.linalg.norm(x) < 1e-9:
            x = np.cross(z, [0.0, 1.0, 0.0])
    x = _unit(x)
    return np.column_stack([x, np.cross(z, x), z])


def _quat(rot):
    q = np.zeros(4)
    mujoco.mju_mat2Quat(q, np.asarray(rot, dtype=float).reshape(9))
    return q


def _plate(surface, edge):
    """Centre, orientation and half sizes of the box whose top face is the plane patch moved
    back by the tool's radius, cut at ``edge`` if the surface ends."""
    n = _unit(surface["normal"])
    a0, a1 = (np.asarray(a, dtype=float) for a in surface["axes"])
    lo = -np.asarray(surface["half_extent"], dtype=float)
    hi = -lo
    centre = np.asarray(surface["point"], dtype=float)
    if edge is not None:
        beyond = _unit(edge["beyond"])
        along = [abs(np.dot(beyond, a0)), abs(np.dot(beyond, a1))]
        k = int(np.argmax(along))
        if along[k] < 1 - 1e-6:
            raise MujocoError(
                "an edge that is not square to a plane patch's axes cannot be built as a box"
            )
        axis = (a0, a1)[k]
        cut = np.dot(np.asarray(edge["point"], dtype=float) - centre, axis)
        if np.dot(beyond, axis) > 0:
            hi[k] = min(hi[k], cut)
        else:
            lo[k] = max(lo[k], cut)
    mid = (lo + hi) / 2
    half = (hi - lo) / 2
    pos = centre + a0 * mid[0] + a1 * mid[1] - n * (TOOL_RADIUS + PLATE_HALF_THICKNESS)
    rot = np.column_stack([a0, a1, n])
    return pos, rot, [half[0], half[1], PLATE_HALF_THICKNESS]


def build(plant: dict, unknowns: Unknowns):
    """The MuJoCo model of a scenario's plant (``armdyn.Controller.plant()``): the robot from
    its URDF with ``unknowns`` on every joint, the tool's sphere and site, the surfaces.
    Returns ``(model, surface geom ids, tool site id)``."""
    if plant["urdf"] is None:
        raise MujocoError(
            f"robot {plant['robot']!r} has no URDF in the package (a robot of your own: give "
            "its URDF, written by armdyn-codegen beside its graphs)"
        )
    spec = mujoco.MjSpec.from_string(plant["urdf"])
    spec.option.timestep = plant["plant_dt_s"]
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_RK4
    spec.option.gravity = plant["gravity"]
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    for joint in spec.joints:
        joint.armature = unknowns.armature
        joint.damping = [unknowns.damping, 0.0, 0.0]
        joint.frictionloss = unknowns.friction
        # The project's plant has end stops only when the scenario asks for them.
        if not plant["end_stops"]:
            joint.limited = mujoco.mjtLimited.mjLIMITED_FALSE
    tool = spec.body(plant["tool_link"])
    if tool is None:
        raise MujocoError(f"the URDF has no link {plant['tool_link']!r}")
    tool.add_site(name="armdyn_tool")
    tool.add_geom(
        name="armdyn_tool_sphere",
        type=mujoco.mjtGeom.mjGEOM_SPHERE,
        size=[TOOL_RADIUS, 0, 0],
        contype=1,
        conaffinity=0,
        friction=[0.0, 0.0, 0.0],
        mass=0.0,
        density=0.0,
    )
    world = spec.worldbody
    geoms = []
    for i, s in enumerate(plant["surfaces"]):
        edge = plant["edge"] if plant["edge"] and plant["edge"]["surface"] == i else None
        common = dict(
            name=f"armdyn_surface_{i}",
            contype=0,
            conaffinity=1,
            priority=1,
            friction=[s["friction"], 0.0, 0.0],
            condim=3 if s["friction"] > 0 else 1,
            solimp=[IMPEDANCE, IMPEDANCE, 0.001, 0.5, 2.0],
        )
        if s["kind"] == "plane":
            pos, rot, size = _plate(s, edge)
            world.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, pos=pos, quat=_quat(rot), size=size,
                           **common)
        elif edge is not None:
            raise MujocoError(f"surface {i}: only a plane patch can end here (a {s['kind']})")
        elif s["kind"] == "sphere":
            world.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, pos=s["point"],
                           size=[s["radius"] - TOOL_RADIUS, 0, 0], **common)
        elif s["kind"] == "cylinder":
            rot = _frame(s["axis"], [1.0, 0.0, 0.0])
            world.add_geom(type=mujoco.mjtGeom.mjGEOM_CYLINDER, pos=s["point"],
                           quat=_quat(rot),
                           size=[s["radius"] - TOOL_RADIUS, CYLINDER_HALF_LENGTH, 0], **common)
        else:
            raise MujocoError(f"surface {i}: MuJoCo has no geom for a {s['kind']!r} surface")
        geoms.append(f"armdyn_surface_{i}")
    try:
        model = spec.compile()
    except ValueError as e:
        if "A + B >= C" not in str(e):
            raise MujocoError(f"MuJoCo cannot compile the model: {e}") from e
        # A link whose inertia breaks the triangle inequality (the thesis SCARA's rods, taken
        # as lines): MuJoCo refuses it, so its diagonal is raised to the smallest that holds.
        spec.compiler.balanceinertia = True
        model = spec.compile()
        print(f"note: {e.args[0].splitlines()[-1]}: its inertia is balanced (MuJoCo's "
              "balanceinertia), the plant differs there from the controller's model",
              file=sys.stderr)
    ids = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, g) for g in geoms]
    site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, "armdyn_tool")
    return model, ids, site


def _closest_normal(surface, p):
    """The surface's outward unit normal at the point of it nearest to ``p``."""
    kind = surface["kind"]
    if kind == "plane":
        return _unit(surface["normal"])
    if kind == "sphere":
        return _unit(p - np.asarray(surface["point"], dtype=float))
    if kind == "cylinder":
        a = _unit(surface["axis"])
        d = p - np.asarray(surface["point"], dtype=float)
        return _unit(d - a * np.dot(d, a))
    raise MujocoError(f"no MuJoCo model of a {kind!r} surface")


class Plant:
    """MuJoCo stepping a scenario's plant; ``wrench()`` is the tool's on the environment."""

    def __init__(self, plant: dict, unknowns: Unknowns):
        self.plant = plant
        self.model, self.geoms, self.site = build(plant, unknowns)
        self.data = mujoco.MjData(self.model)
        self.n = self.model.nv
        self.data.qpos[:] = plant["q0"]
        self.data.qvel[:] = plant["qd0"]
        self.jacp = np.zeros((3, self.n))
        self.stiffness = [s["stiffness"] for s in plant["surfaces"]]
        mujoco.mj_forward(self.model, self.data)

    def tool(self):
        """The tool point, base frame, m."""
        return self.data.site_xpos[self.site].copy()

    def soften(self, t: float):
        """Each surface's ``solref`` from its stiffness and damping and the arm's apparent mass
        along its normal at the tool now (see the module's documentation)."""
        m, d = self.model, self.data
        mujoco.mj_jacSite(m, d, self.jacp, None, self.site)
        p = self.tool()
        step = self.plant["stiffness_step"]
        for i, (s, g) in enumerate(zip(self.plant["surfaces"], self.geoms)):
            n = _closest_normal(s, p)
            row = (n @ self.jacp).reshape(1, self.n)
            minv_row = np.zeros((1, self.n))
            mujoco.mj_solveM(m, d, minv_row, row)
            inv_mass = float((row @ minv_row.T)[0, 0])
            mass = 1.0 / max(inv_mass, 1e-12)
            k = self.stiffness[i]
            if step is not None and step[0] == i and t >= step[1]:
                k *= step[2]
            scale = (1 - IMPEDANCE) / mass
            m.geom_solref[g] = [-k * scale, -s["damping"] * scale]

    def wrench(self, t: float):
        """The wrench the tool exerts on the environment now, base frame (N, N m): minus
        MuJoCo's contact forces on the tool's sphere, and a held payload's weight."""
        m, d = self.model, self.data
        mujoco.mj_forward(m, d)
        f = np.zeros(3)
        out = np.zeros(6)
        for k in range(d.ncon):
            c = d.contact[k]
            if c.geom1 not in self.geoms and c.geom2 not in self.geoms:
                continue
            mujoco.mj_contactForce(m, d, k, out)
            frame = np.asarray(c.frame).reshape(3, 3)
            world = frame.T @ out[:3]
            # MuJoCo's force acts on geom2 from geom1 along the normal from geom1 to geom2:
            # the tool (geom1 or geom2) pushes the surface with the opposite of what it gets.
            f += world if c.geom2 in self.geoms else -world
        w = np.zeros(6)
        w[:3] = f
        payload = self.plant["payload"]
        if payload is not None and t < payload[1]:
            w[:3] += -np.asarray(payload[2]) * payload[0]
        return w

    def step(self, tau, t: float, substeps: int):
        """Holds ``tau`` (and the payload's weight at the tool) for ``substeps`` plant steps."""
        m, d = self.model, self.data
        d.qfrc_applied[:] = tau
        payload = self.plant["payload"]
        if payload is not None and t < payload[1]:
            force = np.asarray(payload[2]) * payload[0]
            mujoco.mj_applyFT(m, d, force, np.zeros(3), self.tool(), m.site_bodyid[self.site],
                              d.qfrc_applied)
        for _ in range(substeps):
            mujoco.mj_step(m, d)


def _told_armature(scenario, base_dir, armature: float):
    """``scenario`` as a dict whose controller's model has ``armature`` at every joint
    (``controller_armature``), and the folder its relative names resolve in."""
    import tomllib

    if isinstance(scenario, dict):
        s = dict(scenario)
    else:
        path = Path(scenario)
        s = tomllib.loads(path.read_text())
        base_dir = base_dir or path.parent
    dof = armdyn.Robot(s["robot"]).dof
    s["controller_armature"] = [armature] * dof
    return s, base_dir


def run(scenario, out=None, unknowns: Unknowns = UNKNOWNS, *, base_dir=None, safety=None,
        controller_knows_armature=False):
    """Runs ``scenario`` with MuJoCo as the plant; returns its ``metrics.json`` as a dict and
    writes its files into ``out`` if given. With ``controller_knows_armature`` the
    controller's model has the plant's armature (``controller_armature``)."""
    if controller_knows_armature:
        scenario, base_dir = _told_armature(scenario, base_dir, unknowns.armature)
    c = armdyn.Controller(scenario, base_dir=base_dir, safety=safety)
    plant = c.plant()
    p = Plant(plant, unknowns)
    control = plant["control_dt_s"]
    substeps = max(1, round(control / plant["plant_dt_s"]))
    steps = round(plant["duration_s"] / control)
    c.record()
    c.reset(0.0, p.data.qpos, p.data.qvel)
    for k in range(steps + 1):
        t = k * control
        p.soften(t)
        q, qd = p.data.qpos.copy(), p.data.qvel.copy()
        if not (np.all(np.isfinite(q)) and np.all(np.isfinite(qd))):
            raise armdyn.SimulationError(f"MuJoCo's state is not finite at t = {t:.3f} s")
        tau = c.step(t, q, qd, p.wrench(t))
        if k == steps:
            break
        p.step(tau, t, substeps)
    return c.finish(None if out is None else os.fspath(out))


COLUMNS = [
    ("force overshoot (%)", "normal_force_overshoot_pct", "{:.1f}"),
    ("settling (s)", "normal_force_settling_time_s", "{:.3f}"),
    ("RMS force error, last 3 s (N)", "normal_force_rms_error_last3s_n", "{:.2f}"),
    ("path RMS in contact (mm)", "path_rms_error_contact_mm", "{:.3f}"),
    ("tool angle RMS (deg)", "tool_normal_angle_error_deg", "{:.3f}"),
    ("contact losses", "contact_losses_after_first_touch", "{}"),
    ("saturated samples", "saturated_samples_total", "{}"),
    ("trips", "safety_trips", None),
]


def _cell(metrics, key, fmt):
    v = metrics.get(key)
    if key == "safety_trips":
        return str(len(v or []))
    if v is None:
        return "-"
    if isinstance(v, float) and not math.isfinite(v):
        return str(v)
    return fmt.format(v)


def compare(files, out: Path):
    """Each scenario in the project's simulator, in MuJoCo with the controller's model exactly
    (``ideal``), with the unknown joint effects (``unknowns``), and with them but the armature
    told to the controller: a Markdown table."""
    rows = []
    for f in files:
        name = Path(f).stem
        simulated = armdyn.run_scenario(f).metrics
        ideal = run(f, out / name / "mujoco-ideal", IDEAL)
        real = run(f, out / name / "mujoco-unknowns", UNKNOWNS)
        told = run(f, out / name / "mujoco-unknowns-armature-known", UNKNOWNS,
                   controller_knows_armature=True)
        for plant, m in (("armdyn", simulated), ("MuJoCo, ideal", ideal),
                         ("MuJoCo, unknowns", real),
                         ("MuJoCo, unknowns, armature in the controller", told)):
            rows.append([name, plant] + [_cell(m, key, fmt) for _, key, fmt in COLUMNS])
    head = ["scenario", "plant"] + [c for c, _, _ in COLUMNS]
    lines = ["| " + " | ".join(head) + " |",
             "| :-- | :-- | " + " | ".join("--:" for _ in COLUMNS) + " |"]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] == "compare":
        ap = argparse.ArgumentParser(prog="python3 -m armdyn.mujoco compare",
                                     description="The project's simulator against MuJoCo.")
        ap.add_argument("scenarios", nargs="+")
        ap.add_argument("--out", type=Path, required=True)
        a = ap.parse_args(argv[1:])
        print(compare(a.scenarios, a.out))
        return 0
    ap = argparse.ArgumentParser(prog="python3 -m armdyn.mujoco", description=__doc__.split("\n\n")[0])
    ap.add_argument("scenario", help="a scenario file")
    ap.add_argument("--out", type=Path, required=True, help="the folder of the run's files")
    ap.add_argument("--ideal", action="store_true",
                    help="no armature, damping or friction the controller does not know")
    ap.add_argument("--armature", type=float, default=UNKNOWNS.armature)
    ap.add_argument("--damping", type=float, default=UNKNOWNS.damping)
    ap.add_argument("--friction", type=float, default=UNKNOWNS.friction)
    ap.add_argument("--no-safety", action="store_true", help="run without the supervisor")
    ap.add_argument("--controller-knows-armature", action="store_true",
                    help="the controller's model has the plant's armature (controller_armature)")
    a = ap.parse_args(argv)
    unknowns = IDEAL if a.ideal else Unknowns(a.armature, a.damping, a.friction)
    for name, v in (("armature", unknowns.armature), ("damping", unknowns.damping),
                    ("friction", unknowns.friction)):
        if not (math.isfinite(v) and v >= 0):
            ap.error(f"--{name} must be a finite number >= 0, got {v}")
    try:
        metrics = run(a.scenario, a.out, unknowns, safety=False if a.no_safety else None,
                      controller_knows_armature=a.controller_knows_armature)
    except (armdyn.ScenarioError, MujocoError, armdyn.SimulationError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    for label, key, fmt in COLUMNS:
        print(f"{label}: {_cell(metrics, key, fmt)}")
    print(f"wrote {a.out}/: trajectory.csv, metrics.json, figures, view.html")
    return 0


if __name__ == "__main__":
    sys.exit(main())
