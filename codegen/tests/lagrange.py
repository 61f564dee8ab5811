"""The slow, obviously-correct path: the thesis's Lagrangian method (Section 3.3).

World-frame rotation matrices from full 4 x 4 products (fixed placement, Rodrigues rotation
with ``sin(q)``/``cos(q)`` or translation, fixed post-placement) of the generator's chain, COM
velocities from Jacobians of COM positions, kinetic energy T = sum 1/2 m v.v + 1/2 w.(R I R^T) w,
potential U = -sum m g.p; then M = d2T/dqd2, Christoffel C from dM/dq, g = dU/dq.
Uses floats throughout and none of the generator's derivation code.
"""

import casadi as ca


def _transform(placement):
    from armdyn_codegen.description import to_float

    T = ca.SX.eye(4)
    for r in range(3):
        for k in range(3):
            T[r, k] = to_float(placement.R[r][k])
        T[r, 3] = to_float(placement.p[r])
    return T


def _motion(joint, qi):
    """4 x 4 rotation about (angle-axis, Rodrigues with sin/cos of q) or translation along the
    joint's unit axis."""
    from armdyn_codegen.description import to_float

    a = ca.DM([to_float(x) for x in joint.axis])
    T = ca.SX.eye(4)
    th = qi + to_float(joint.offset)
    if joint.revolute:
        K = ca.SX(3, 3)
        K[0, 1], K[0, 2], K[1, 0] = -a[2], a[1], a[2]
        K[1, 2], K[2, 0], K[2, 1] = -a[0], -a[1], a[0]
        T[:3, :3] = ca.SX.eye(3) + ca.sin(th) * K + (1 - ca.cos(th)) * ca.mtimes(K, K)
    else:
        T[:3, 3] = a * th
    return T


def build(robot):
    """``robot``: a ``chain.Chain`` (a DH table or a URDF, as the generator reads it)."""
    from armdyn_codegen.description import to_float

    n = robot.dof
    q = ca.SX.sym("q", n)
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    T = ca.SX.eye(4)
    frames = []
    for i, j in enumerate(robot.joints):
        T = ca.mtimes(ca.mtimes(ca.mtimes(T, _transform(j.placement)), _motion(j, q[i])),
                      _transform(j.post))
        frames.append(T)
    gvec = ca.DM([to_float(x) for x in robot.gravity])
    KE = 0
    U = 0
    for i, j in enumerate(robot.joints):
        R = frames[i][:3, :3]
        p = frames[i][:3, 3]
        com = ca.DM([to_float(x) for x in j.link.com])
        I = ca.DM([[to_float(x) for x in row] for row in j.link.inertia])
        m = to_float(j.link.mass)
        pc = p + ca.mtimes(R, com)
        v = ca.mtimes(ca.jacobian(pc, q), qd)
        Rdot = sum(ca.jacobian(R, q[k]).reshape((3, 3)) * qd[k] for k in range(n))
        W = ca.mtimes(Rdot, R.T)
        w = ca.vertcat(W[2, 1], W[0, 2], W[1, 0])
        KE += 0.5 * m * ca.dot(v, v) + 0.5 * ca.dot(w, ca.mtimes(ca.mtimes(R, ca.mtimes(I, R.T)), w))
        U += -m * ca.dot(gvec, pc)
    M = ca.hessian(KE, qd)[0]
    C = ca.SX(n, n)
    for k in range(n):
        for jj in range(n):
            C[k, jj] = sum(
                0.5 * (ca.jacobian(M[k, jj], q[i]) + ca.jacobian(M[k, i], q[jj]) - ca.jacobian(M[i, jj], q[k])) * qd[i]
                for i in range(n)
            )
    g = ca.gradient(U, q)
    ee = ca.mtimes(frames[-1], _transform(robot.tool))
    pe = ee[:3, 3]
    Jv = ca.jacobian(pe, q)
    # Angular rows: w = J_w qd, read off the skew part of Rdot R^T of the last frame.
    Rn = ee[:3, :3]
    Jw = ca.SX(3, n)
    for k in range(n):
        Wk = ca.mtimes(ca.jacobian(Rn, q[k]).reshape((3, 3)), Rn.T)
        Jw[0, k], Jw[1, k], Jw[2, k] = Wk[2, 1], Wk[0, 2], Wk[1, 0]
    J = ca.vertcat(Jv, Jw)
    jdot_qd = ca.mtimes(ca.jacobian(ca.mtimes(J, qd), q), qd)
    tau = ca.mtimes(M, qdd) + ca.mtimes(C, qd) + g
    return ca.Function(
        "lagrange",
        [q, qd, qdd],
        [ee, J, M, C, ca.mtimes(C, qd), g, jdot_qd, tau],
        ["q", "qd", "qdd"],
        ["pose", "jacobian", "mass_matrix", "coriolis_matrix", "coriolis", "gravity", "jdot_qd",
         "inverse_dynamics"],
    )
