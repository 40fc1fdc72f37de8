"""CasADi: one step of the same continuation as linkage's sweep — the
second-order predictor from the previous pose's analogs, then Ψ, its
Jacobians, one Newton correction and the analogs u', u'' at the prediction —
built as an SX
function (CasADi shares common subexpressions itself), iterated over the
revolution by mapaccum in CasADi's virtual machine, and generated as C for
the harness in casadi_harness.c.

    python casadi_peer.py vm        # time the VM, print a results row
    python casadi_peer.py codegen   # write fourbar_step.c
"""
import os
import sys
import time

import casadi as ca
import numpy as np

from common import HERE, L1, L2, L3, L4, OMEGA2, N, STRIDE, errors, row, start, theta2


def step_function():
    u = ca.SX.sym("u", 2)        # previous pose
    du = ca.SX.sym("du", 2)      # previous first analogs du/dtheta2
    ddu = ca.SX.sym("ddu", 2)    # previous second analogs
    t_prev = ca.SX.sym("t_prev")
    t = ca.SX.sym("t")

    def psi(u, t):
        return ca.vertcat(
            L2 * ca.cos(t) + L3 * ca.cos(u[0]) + L4 * ca.cos(u[1]) - L1,
            L2 * ca.sin(t) + L3 * ca.sin(u[0]) + L4 * ca.sin(u[1]),
        )

    h = t - t_prev
    # Everything at the predicted pose, as linkage's fast path: Ψ, Ψ_u, Ψ_v,
    # the Newton correction, and the analogs u' = −Ψ_u⁻¹Ψ_v,
    # u'' = −Ψ_u⁻¹γ(u, u', v' = 1).
    x = ca.SX.sym("x", 2)
    tt = ca.SX.sym("tt")
    P = psi(x, tt)
    Pu = ca.jacobian(P, x)
    Pv = ca.jacobian(P, tt)
    d1 = -ca.solve(Pu, Pv)
    # γ = (Ψ_q q̇)_q q̇ with q̇ an independent symbol, then q̇ = (u', 1).
    q = ca.vertcat(x, tt)
    qd = ca.SX.sym("qd", 3)
    gamma_of = ca.Function("gamma", [x, tt, qd], [ca.jtimes(ca.jtimes(P, q, qd), q, qd)])
    gamma = gamma_of(x, tt, ca.vertcat(d1, 1))
    d2 = -ca.solve(Pu, gamma)
    newton = -ca.solve(Pu, P)
    kernel = ca.Function("kernel", [x, tt], [x + newton, d1, d2])
    pred = u + du * h + ddu * (0.5 * h * h)
    corrected, a1, a2 = kernel(pred, t)
    return ca.Function(
        "fourbar_step",
        [u, du, ddu, t_prev, t],
        [corrected, a1, a2],
        ["u", "du", "ddu", "t_prev", "t"],
        ["u_next", "du_next", "ddu_next"],
    )


def vm(samples):
    """The revolution by mapaccum in the VM: state (u, du, ddu, t)."""
    step = step_function()
    s = ca.SX.sym("s", 7)
    t = ca.SX.sym("t")
    u, du, ddu = step(s[0:2], s[2:4], s[4:6], s[6], t)
    body = ca.Function("body", [s, t], [ca.vertcat(u, du, ddu, t)])
    sweep = body.mapaccum("sweep", samples)
    every = N // samples
    ts = np.array([theta2(k) for k in range(every, N + 1, every)])
    u0 = start()
    # The analogs at the start, from one step of length 0.
    first = step(ca.DM(u0), ca.DM.zeros(2), ca.DM.zeros(2), 0.0, 0.0)
    s0 = np.concatenate([np.array(first[0]).ravel(), np.array(first[1]).ravel(), np.array(first[2]).ravel(), [0.0]])
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        out = np.array(sweep(s0, ts.reshape(1, -1)))
        times.append((time.perf_counter() - t0) * 1e9 / samples)
    times.sort()
    results = {0: (s0[0], s0[1], s0[2] * OMEGA2, s0[3] * OMEGA2, s0[4] * OMEGA2 ** 2, s0[5] * OMEGA2 ** 2)}
    for j, k in enumerate(range(every, N + 1, every)):
        if k % STRIDE == 0 and k < N:
            c = out[:, j]
            results[k] = (c[0], c[1], c[2] * OMEGA2, c[3] * OMEGA2, c[4] * OMEGA2 ** 2, c[5] * OMEGA2 ** 2)
    return row("CasADi SX mapaccum in its VM", times[1], errors(results), samples)


def codegen():
    step = step_function()
    cg = ca.CodeGenerator("fourbar_step.c", {"with_header": True})
    cg.add(step)
    cg.generate(os.path.join(HERE, "build") + os.sep)


if __name__ == "__main__":
    if sys.argv[1:] == ["codegen"]:
        codegen()
    else:
        print(vm(N))
