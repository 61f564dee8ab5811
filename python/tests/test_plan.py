"""``armdyn.plan`` and ``armdyn.plan_terminal_cost``: optimised moves from Python, checked
against the model (the plan's accelerations are its forward dynamics), its limits and its
goal; bad input is a ValueError that names it."""

import numpy as np
import pytest

import armdyn

UR5_FROM = np.array([0.0, -1.2, 1.0, -0.5, 0.3, 0.0])
UR5_TO = np.array([1.2, -0.6, 0.4, -1.1, 0.9, 0.8])


def check_plan(robot, r, q_from, q_to, share):
    n = robot.dof
    K = r["tau"].shape[0]
    assert r["q"].shape == (K + 1, n) and r["qd"].shape == (K + 1, n)
    assert r["qdd"].shape == (K, n) and r["t"].shape == (K + 1,)
    assert r["t"][-1] == pytest.approx(r["duration_s"])
    np.testing.assert_array_equal(r["q"][0], q_from)
    np.testing.assert_array_equal(r["qd"][0], 0.0)
    # The accelerations are the model's forward dynamics of the plan's torques.
    fd = robot.forward_dynamics(r["q"][:-1], r["qd"][:-1], r["tau"])
    assert np.abs(fd - r["qdd"]).max() <= 1e-9 * max(1.0, np.abs(fd).max())
    # Within the effort share.
    assert np.abs(r["tau"] / robot.effort_limits).max() <= share + 1e-12
    assert r["peak_effort_share"] == pytest.approx(np.abs(r["tau"] / robot.effort_limits).max())
    assert r["iterations"] >= 1 and r["solve_time_s"] > 0.0


def test_minimum_effort_move_reaches_the_goal_at_rest():
    robot = armdyn.Robot("ur5")
    r = armdyn.plan("ur5", UR5_FROM, UR5_TO, 1.0, effort_share=0.6)
    check_plan(robot, r, UR5_FROM, UR5_TO, 0.6)
    assert r["violation"] <= 1e-6
    assert np.abs(r["q"][-1] - UR5_TO).max() <= 1e-6 and np.abs(r["qd"][-1]).max() <= 1e-6
    # The effort is the integral of sum (tau_i / e_i)^2.
    effort = r["step_s"] * np.sum((r["tau"] / robot.effort_limits) ** 2)
    assert r["effort_s"] == pytest.approx(effort, rel=1e-12)


def test_shortest_move_within_a_share_of_the_effort():
    robot = armdyn.Robot("scara")
    q_from, q_to = [0.3, 0.5, 0.15, 0.0], [0.8, -0.5, 0.2, 0.5]
    slow = armdyn.plan("scara", q_from, q_to, 1.0)
    r = armdyn.plan("scara", q_from, q_to, shortest=True, effort_share=0.5)
    check_plan(robot, r, q_from, q_to, 0.5)
    assert r["duration_s"] < slow["duration_s"]
    assert r["peak_effort_share"] > 0.4


def test_terminal_cost_move_from_given_torques():
    robot = armdyn.Robot("ur5")
    hold = np.tile(robot.generalized_gravity(UR5_FROM), (100, 1))
    r = armdyn.plan_terminal_cost("ur5", UR5_FROM, UR5_TO, 1.0, weight=1e4,
                                  initial_torques=hold, step=0.01, effort_share=0.5)
    check_plan(robot, r, UR5_FROM, UR5_TO, 0.5)
    assert r["cost"] < 1e-4 * r["initial_cost"]
    assert r["cost"] == pytest.approx(r["effort_s"] + r["terminal_cost"], rel=1e-12)
    goal = np.concatenate([UR5_TO, np.zeros(6)])
    last = np.concatenate([r["q"][-1], r["qd"][-1]])
    assert r["terminal_cost"] == pytest.approx(0.5e4 * np.sum((last - goal) ** 2), rel=1e-9)


def test_bad_requests_are_named():
    with pytest.raises(ValueError, match=r'robot: no robot called "kuka" \(one of panda'):
        armdyn.plan("kuka", UR5_FROM, UR5_TO, 1.0)
    with pytest.raises(ValueError, match=r"q_to: shape \(5,\) does not fit"):
        armdyn.plan("ur5", UR5_FROM, UR5_TO[:5], 1.0)
    with pytest.raises(ValueError, match=r"give a duration or shortest=True, not both"):
        armdyn.plan("ur5", UR5_FROM, UR5_TO, 1.0, shortest=True)
    with pytest.raises(ValueError, match=r"give the move's duration"):
        armdyn.plan("ur5", UR5_FROM, UR5_TO)
    with pytest.raises(ValueError, match=r"joint `shoulder_lift_joint` = 9 is outside its limits"):
        armdyn.plan("ur5", UR5_FROM, [0.0, 9.0, 0.0, 0.0, 0.0, 0.0], 1.0)
    with pytest.raises(ValueError, match=r"3 initial torques for 100 knot steps"):
        armdyn.plan_terminal_cost("ur5", UR5_FROM, UR5_TO, 1.0, weight=1.0,
                                  initial_torques=np.zeros((3, 6)), step=0.01)
    with pytest.raises(ValueError, match=r"terminal weight must be a positive number"):
        armdyn.plan_terminal_cost("ur5", UR5_FROM, UR5_TO, 1.0, weight=-1.0,
                                  initial_torques=np.zeros((100, 6)), step=0.01)
    with pytest.raises(ValueError, match=r"initial_torques\[2, 1\] is NaN"):
        torques = np.zeros((100, 6))
        torques[2, 1] = np.nan
        armdyn.plan_terminal_cost("ur5", UR5_FROM, UR5_TO, 1.0, weight=1.0,
                                  initial_torques=torques, step=0.01)
