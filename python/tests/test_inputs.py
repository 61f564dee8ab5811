"""Shapes, dtypes and values that are wrong raise ValueError naming the argument; facts."""

import numpy as np
import pytest

import armdyn


@pytest.fixture
def ur5():
    return armdyn.Robot("ur5")


def test_robot_facts():
    assert armdyn.robots() == sorted(armdyn.robots())
    s = armdyn.Robot("scara")
    assert (s.name, s.dof) == ("scara", 4)
    assert s.joint_kinds == ["revolute", "revolute", "prismatic", "revolute"]
    assert s.joint_limits.shape == (4, 2) and s.effort_limits.shape == (4,)
    assert np.allclose(s.gravity, [0, 0, -9.8])  # the thesis's g
    assert len(s.source_sha256) == 64
    assert repr(s) == 'Robot("scara")'
    # Thesis check: at q = 0 the tool is at (0.8, 0, 0.35) m.
    assert np.allclose(s.end_effector_pose(np.zeros(4))[:3, 3], [0.8, 0.0, 0.35])


def test_unknown_robot():
    with pytest.raises(ValueError, match='name: no robot called "kuka".*panda'):
        armdyn.Robot("kuka")


def test_integers_and_lists_are_read_as_numbers(ur5):
    a = ur5.generalized_gravity([0, 1, 0, 0, 0, 0])
    b = ur5.generalized_gravity(np.array([0.0, 1.0, 0.0, 0.0, 0.0, 0.0]))
    assert np.array_equal(a, b)
    assert ur5.generalized_gravity(np.zeros(6, dtype=np.float32)).dtype == np.float64


@pytest.mark.parametrize(
    "value, message",
    [
        (np.zeros(5), r"q: shape \(5,\) does not fit: expected \(6,\) for one state or \(N, 6\)"),
        (np.zeros((3, 7)), r"q: shape \(3, 7\) does not fit"),
        (np.zeros((2, 3, 6)), r"q: shape \(2, 3, 6\) does not fit"),
        (np.zeros((0, 6)), r"q: an empty batch"),
        (np.zeros(6, dtype=complex), r"q: dtype complex128 is not a real number type"),
        (np.array(["a"] * 6), r"q: dtype <U1 is not a real number type"),
        (np.array([0, 0, np.nan, 0, 0, 0]), r"q\[2\] is NaN: every value must be finite"),
        (np.array([[0.0] * 6, [0, 0, 0, 0, np.inf, 0]]), r"q\[1, 4\] is inf"),
    ],
)
def test_bad_q_is_named(ur5, value, message):
    with pytest.raises(ValueError, match=message):
        ur5.mass_matrix(value)


def test_mismatched_arguments_are_named(ur5):
    with pytest.raises(ValueError, match=r"qd: 3 states where q has 2 states"):
        ur5.coriolis(np.zeros((2, 6)), np.zeros((3, 6)))
    with pytest.raises(ValueError, match=r"qd: 2 states where q has one state"):
        ur5.coriolis(np.zeros(6), np.zeros((2, 6)))
    with pytest.raises(ValueError, match=r"tau\[0, 0\] is NaN"):
        ur5.forward_dynamics(np.zeros((1, 6)), np.zeros((1, 6)), np.full((1, 6), np.nan))
    with pytest.raises(ValueError, match=r"parameters: shape \(3,\) does not fit: expected \(60,\)"):
        ur5.generalized_gravity(np.zeros(6), parameters=np.zeros(3))
    # The kinematics take no parameters: Python's own error for an unknown keyword.
    with pytest.raises(TypeError, match=r"parameters"):
        ur5.jacobian(np.zeros(6), parameters=ur5.standard_parameters())
    with pytest.raises(ValueError, match=r"q: cannot be read as an array"):
        ur5.generalized_gravity([[0.0, 1.0], [2.0]])


def test_odd_but_finite_input_gives_numbers_or_a_named_error(ur5):
    # Huge angles: sin and cos are still numbers, so is M (symmetric, positive diagonal).
    M = ur5.mass_matrix(np.full(6, 1e300))
    assert np.isfinite(M).all() and np.allclose(M, M.T) and (np.diag(M) > 0).all()
    # Parameters that no body has (all zero): M = 0, forward dynamics has no answer.
    with pytest.raises(ValueError, match=r"not finite \(their mass matrix is singular here\)"):
        ur5.forward_dynamics(np.zeros(6), np.zeros(6), np.zeros(6), parameters=np.zeros(60))
    # In a batch the error names the state.
    with pytest.raises(ValueError, match=r"^state 0: forward dynamics with these parameters"):
        ur5.forward_dynamics(np.zeros((3, 6)), np.zeros((3, 6)), np.zeros((3, 6)),
                             parameters=np.zeros(60))
