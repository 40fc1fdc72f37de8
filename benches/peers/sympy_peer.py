"""SymPy the way its users do it: the closure equations and their Jacobians
derived symbolically, lambdify'd to NumPy, Newton warm-started from the
previous pose in a Python loop, then the velocity and acceleration solves
with numpy.linalg.solve."""
import sys
import time

import numpy as np
import sympy as sp

from common import L1, L2, L3, L4, OMEGA2, N, STRIDE, errors, row, start, theta2

t3, t4, t2, w3, w4, w2 = sp.symbols("theta3 theta4 theta2 omega3 omega4 omega2")
psi = sp.Matrix([
    L2 * sp.cos(t2) + L3 * sp.cos(t3) + L4 * sp.cos(t4) - L1,
    L2 * sp.sin(t2) + L3 * sp.sin(t3) + L4 * sp.sin(t4),
])
q = sp.Matrix([t3, t4, t2])
qdot = sp.Matrix([w3, w4, w2])
psi_u = psi.jacobian([t3, t4])
psi_v = psi.jacobian([t2])
gamma = (psi.jacobian(q) * qdot).jacobian(q) * qdot

f_psi = sp.lambdify((t3, t4, t2), psi, "numpy")
f_psi_u = sp.lambdify((t3, t4, t2), psi_u, "numpy")
f_psi_v = sp.lambdify((t3, t4, t2), psi_v, "numpy")
f_gamma = sp.lambdify((t3, t4, t2, w3, w4, w2), gamma, "numpy")


def sweep(every):
    """Every `every`-th sample of the dense grid; returns the results at the
    reference samples and the number of samples."""
    u = np.array(start())
    results = {}
    count = 0
    for k in range(0, N, every):
        th = theta2(k)
        for _ in range(20):
            r = np.asarray(f_psi(u[0], u[1], th), dtype=float).ravel()
            du = np.linalg.solve(np.asarray(f_psi_u(u[0], u[1], th), dtype=float), -r)
            u = u + du
            if np.max(np.abs(du)) <= 1e-14 * max(1.0, np.max(np.abs(u))):
                break
        J = np.asarray(f_psi_u(u[0], u[1], th), dtype=float)
        Jv = np.asarray(f_psi_v(u[0], u[1], th), dtype=float).ravel()
        udot = np.linalg.solve(J, -Jv * OMEGA2)
        g = np.asarray(f_gamma(u[0], u[1], th, udot[0], udot[1], OMEGA2), dtype=float).ravel()
        uddot = np.linalg.solve(J, -g)
        count += 1
        if k % STRIDE == 0:
            results[k] = (u[0], u[1], udot[0], udot[1], uddot[0], uddot[1])
    return results, count


if __name__ == "__main__":
    every = 28  # 36 000 samples per revolution, the reference among them
    sweep(every * 10)  # warm up
    times = []
    for _ in range(3):
        t = time.perf_counter()
        results, count = sweep(every)
        times.append((time.perf_counter() - t) * 1e9 / count)
    times.sort()
    print(row("SymPy lambdify + NumPy Newton in a Python loop", times[1], errors(results), count))
