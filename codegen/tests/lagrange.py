"""The slow, obviously-correct path: the thesis's Lagrangian method (Section 3.3).

World-frame rotation matrices from full 4 x 4 DH products with ``sin(q)``/``cos(q)``, COM
velocities from Jacobians of COM positions, kinetic energy T = sum 1/2 m v.v + 1/2 w.(R I R^T) w,
potential U = -sum m g.p; then M = d2T/dqd2, Christoffel C from dM/dq, g = dU/dq.
Uses floats throughout and none of the generator's derivation code.
"""

import casadi as ca


def build(robot):
    from scara_codegen.description import to_float

    n = robot.dof
    q = ca.SX.sym("q", n)
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    a0, al0 = to_float(robot.base[0]), to_float(robot.base[1])
    T = ca.SX.eye(4)  # base transform Tx(a0) Rx(alpha0) of a converted modified-DH chain
    T[0, 3] = a0
    T[1, 1], T[1, 2], T[2, 1], T[2, 2] = ca.cos(al0), -ca.sin(al0), ca.sin(al0), ca.cos(al0)
    frames = []
    for i, j in enumerate(robot.joints):
        th = q[i] + to_float(j.theta) if j.revolute else to_float(j.theta)
        d = q[i] + to_float(j.d) if not j.revolute else to_float(j.d)
        a, al = to_float(j.a), to_float(j.alpha)
        A = ca.SX(4, 4)
        A[0, 0], A[0, 1], A[0, 2], A[0, 3] = ca.cos(th), -ca.sin(th) * ca.cos(al), ca.sin(th) * ca.sin(al), a * ca.cos(th)
        A[1, 0], A[1, 1], A[1, 2], A[1, 3] = ca.sin(th), ca.cos(th) * ca.cos(al), -ca.cos(th) * ca.sin(al), a * ca.sin(th)
        A[2, 1], A[2, 2], A[2, 3] = ca.sin(al), ca.cos(al), d
        A[3, 3] = 1
        T = ca.mtimes(T, A)
        frames.append(T)
    gvec = ca.DM([to_float(x) for x in robot.gravity])
    KE = 0
    U = 0
    # The description's own frames (a converted modified-DH chain: frame i = chain frame i
    # times (Tx(a) Rx(alpha))^-1), where its links are given.
    for i, (oa, oal) in enumerate(robot.frame_offsets):
        oa, oal = to_float(oa), to_float(oal)
        Xinv = ca.SX.eye(4)
        Xinv[1, 1], Xinv[1, 2], Xinv[2, 1], Xinv[2, 2] = ca.cos(oal), ca.sin(oal), -ca.sin(oal), ca.cos(oal)
        Xinv[0, 3] = -oa
        frames[i] = ca.mtimes(frames[i], Xinv)
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
    pe = frames[-1][:3, 3]
    Jv = ca.jacobian(pe, q)
    # Angular rows: w = J_w qd, read off the skew part of Rdot R^T of the last frame.
    Rn = frames[-1][:3, :3]
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
        [frames[-1], J, M, C, ca.mtimes(C, qd), g, jdot_qd, tau],
        ["q", "qd", "qdd"],
        ["pose", "jacobian", "mass_matrix", "coriolis_matrix", "coriolis", "gravity", "jdot_qd",
         "inverse_dynamics"],
    )
