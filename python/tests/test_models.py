"""Every robot's M, c, g, inverse and forward dynamics and their derivatives, Jacobian and tool
pose against Pinocchio reading the robot's URDF (``generated/urdf/<robot>.urdf``, written from the same
description), to 1e-9 relative, for single states and batches."""

import numpy as np
import pytest

import armdyn
from conftest import ROOT, require

TOL = 1e-9
STATES = 32


def relative(got, want):
    return float(np.abs(got - want).max()) / max(1.0, float(np.abs(want).max()))


def pinocchio_model(robot):
    pin = require("pinocchio")
    model = pin.buildModelFromUrdf(str(ROOT / "generated/urdf" / f"{robot.name}.urdf"))
    model.gravity.linear = robot.gravity
    names = [model.names[i] for i in range(1, model.njoints)]
    assert names == robot.joint_names
    return pin, model


def states(robot, seed):
    rng = np.random.default_rng(seed)
    lim = robot.joint_limits
    q = rng.uniform(lim[:, 0], lim[:, 1], size=(STATES, robot.dof))
    qd = rng.uniform(-2.0, 2.0, size=(STATES, robot.dof))
    qdd = rng.uniform(-5.0, 5.0, size=(STATES, robot.dof))
    return q, qd, qdd


@pytest.mark.parametrize("name", armdyn.robots())
def test_dynamics_equal_pinocchio_single_and_batched(name):
    robot = armdyn.Robot(name)
    pin, model = pinocchio_model(robot)
    data = model.createData()
    q, qd, qdd = states(robot, 7)
    tau = robot.inverse_dynamics(q, qd, qdd)
    batch = {
        "M": robot.mass_matrix(q),
        "c": robot.coriolis(q, qd),
        "g": robot.generalized_gravity(q),
        "rnea": tau,
        "aba": robot.forward_dynamics(q, qd, tau + 3.0),
    }
    M_b, b_b = robot.mass_matrix_and_bias(q, qd)
    worst = 0.0
    for k in range(STATES):
        M = pin.crba(model, data, q[k])
        M = np.triu(M) + np.triu(M, 1).T
        nle = pin.nonLinearEffects(model, data, q[k], qd[k]).copy()
        g = pin.computeGeneralizedGravity(model, data, q[k]).copy()
        want = {
            "M": M,
            "c": nle - g,
            "g": g,
            "rnea": pin.rnea(model, data, q[k], qd[k], qdd[k]).copy(),
            "aba": pin.aba(model, data, q[k], qd[k], tau[k] + 3.0).copy(),
        }
        single = {
            "M": robot.mass_matrix(q[k]),
            "c": robot.coriolis(q[k], qd[k]),
            "g": robot.generalized_gravity(q[k]),
            "rnea": robot.inverse_dynamics(q[k], qd[k], qdd[k]),
            "aba": robot.forward_dynamics(q[k], qd[k], tau[k] + 3.0),
        }
        for what in want:
            assert single[what].shape == want[what].shape, what
            for got in (single[what], batch[what][k]):
                err = relative(got, want[what])
                worst = max(worst, err)
                assert err <= TOL, f"{name} {what} state {k}: {err:.3e}"
        assert relative(M_b[k], M) <= TOL and relative(b_b[k], nle) <= TOL
    print(f"{name}: largest relative difference from Pinocchio {worst:.2e}")


def symmetric(m):
    """Pinocchio fills the upper triangle of symmetric results only."""
    return np.triu(m) + np.triu(m, 1).T


@pytest.mark.parametrize("name", armdyn.robots())
def test_derivatives_equal_pinocchio_single_and_batched(name):
    """``inverse_dynamics_derivatives`` against ``computeRNEADerivatives`` and
    ``forward_dynamics_derivatives`` against ``computeABADerivatives``, block by block, to 1e-9
    relative, for one state and for a batch (an odd count, so the last SIMD call is padded)."""
    robot = armdyn.Robot(name)
    pin, model = pinocchio_model(robot)
    data = model.createData()
    q, qd, qdd = states(robot, 5)
    q, qd, qdd = q[:-1], qd[:-1], qdd[:-1]
    tau = robot.inverse_dynamics(q, qd, qdd) + 2.0
    did = robot.inverse_dynamics_derivatives(q, qd, qdd)
    dfd = robot.forward_dynamics_derivatives(q, qd, tau)
    n = robot.dof
    assert len(did) == 2 and len(dfd) == 3
    assert all(m.shape == (len(q), n, n) for m in did + dfd)
    worst = 0.0
    for k in range(len(q)):
        dtau_dq, dtau_dv, _ = (np.array(m).copy()
                               for m in pin.computeRNEADerivatives(model, data, q[k], qd[k], qdd[k]))
        ddq_dq, ddq_dv, ddq_dtau = (np.array(m).copy()
                                    for m in pin.computeABADerivatives(model, data, q[k], qd[k], tau[k]))
        one_id = robot.inverse_dynamics_derivatives(q[k], qd[k], qdd[k])
        one_fd = robot.forward_dynamics_derivatives(q[k], qd[k], tau[k])
        assert all(m.shape == (n, n) for m in one_id + one_fd)
        wants = (dtau_dq, dtau_dv, ddq_dq, ddq_dv, symmetric(ddq_dtau))
        names = ("d tau/d q", "d tau/d qd", "d qdd/d q", "d qdd/d qd", "M^-1")
        for what, want, batch, single in zip(names, wants, did + dfd, one_id + one_fd):
            for got in (batch[k], single):
                err = relative(got, want)
                worst = max(worst, err)
                assert err <= TOL, f"{name} {what} state {k}: {err:.3e}"
    print(f"{name}: derivatives' largest relative difference from Pinocchio {worst:.2e}")


@pytest.mark.parametrize("name", armdyn.robots())
def test_jacobian_and_tool_pose_equal_pinocchio(name):
    robot = armdyn.Robot(name)
    pin, model = pinocchio_model(robot)
    data = model.createData()
    fid = model.getFrameId(f"{name}_tool")
    q, qd, _ = states(robot, 11)
    J = robot.jacobian(q)
    T = robot.end_effector_pose(q)
    poses = robot.frame_poses(q)
    assert poses.shape == (STATES, robot.dof, 4, 4)
    assert J.shape == (STATES, 6, robot.dof) and T.shape == (STATES, 4, 4)
    for k in range(STATES):
        pin.computeJointJacobians(model, data, q[k])
        pin.framesForwardKinematics(model, data, q[k])
        Jp = pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
        assert relative(J[k], Jp) <= TOL, (name, k)
        assert relative(robot.jacobian(q[k]), Jp) <= TOL
        assert relative(T[k], data.oMf[fid].homogeneous) <= TOL
        # A URDF robot's link frame i is the child link of joint i, whose frame is the
        # joint's (a DH robot's are its DH frames, which Pinocchio does not have).
        if name in ("ur5", "panda"):
            for i in range(robot.dof):
                assert relative(poses[k, i], data.oMi[i + 1].homogeneous) <= TOL, (name, k, i)
        # The tool sits at a fixed offset from the last link frame.
        offset = np.linalg.inv(poses[k, -1]) @ T[k]
        assert relative(offset, np.linalg.inv(poses[0, -1]) @ T[0]) <= 1e-9, (name, k)
        # Jdot qd: the tool's classical acceleration at qdd = 0.
        pin.forwardKinematics(model, data, q[k], qd[k], np.zeros(robot.dof))
        pin.updateFramePlacements(model, data)
        a = pin.getFrameClassicalAcceleration(model, data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
        assert relative(robot.jdot_qd(q[k], qd[k]), a.vector) <= TOL, (name, k)


@pytest.mark.parametrize("name", armdyn.robots())
def test_regressor_and_parameters_give_the_same_torques(name):
    robot = armdyn.Robot(name)
    q, qd, qdd = states(robot, 3)
    p = robot.standard_parameters()
    assert p.shape == (10 * robot.dof,)
    Y = robot.regressor(q, qd, qdd)
    assert Y.shape == (STATES, robot.dof, 10 * robot.dof)
    tau = robot.inverse_dynamics(q, qd, qdd)
    assert relative(Y @ p, tau) <= TOL
    assert relative(robot.inverse_dynamics(q, qd, qdd, parameters=p), tau) <= TOL
    assert relative(robot.mass_matrix(q, parameters=p), robot.mass_matrix(q)) <= TOL
    # Heavier links: the torques change, the kinematics do not.
    heavier = p * 1.5
    assert relative(robot.inverse_dynamics(q, qd, qdd, parameters=heavier), 1.5 * tau) <= TOL
    qdd_back = robot.forward_dynamics(q, qd, tau * 1.5, parameters=heavier)
    assert relative(qdd_back, qdd) <= 1e-7


def test_large_batches_in_parallel_equal_the_serial_loop():
    robot = armdyn.Robot("panda")
    n = armdyn.PARALLEL_MIN_STATES * 3 + 17
    rng = np.random.default_rng(1)
    q = rng.uniform(-1, 1, (n, 7))
    qd = rng.uniform(-1, 1, (n, 7))
    a = robot.forward_dynamics(q, qd, qd)
    b = robot.forward_dynamics(q, qd, qd, parallel=False)
    assert np.array_equal(a, b)
    M, bias = robot.mass_matrix_and_bias(q, qd)
    # A state's result does not depend on its place in the batch (each SIMD lane is its own).
    M1, bias1 = robot.mass_matrix_and_bias(q[123], qd[123])
    assert np.array_equal(M[123], M1) and np.array_equal(bias[123], bias1)
    assert relative(M[123], robot.mass_matrix(q[123])) <= 1e-12
    for parallel in (True, False):
        d = robot.forward_dynamics_derivatives(q, qd, qd, parallel=parallel)
        one = robot.forward_dynamics_derivatives(q[n - 1], qd[n - 1], qd[n - 1])
        assert all(np.array_equal(a[n - 1], b) for a, b in zip(d, one))
