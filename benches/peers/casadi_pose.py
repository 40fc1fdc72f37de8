"""CasADi's generated C for the single-pose job of `Linkage::analyze` and for
the fused kernel of a sweep step, on the worksheet's four-bar:

- fourbar_newton(u, t) -> (u − Ψ_u⁻¹Ψ, ‖Δu‖∞): one Newton–Raphson step;
- fourbar_kinematics(u, t, tdot, tddot) -> (Ψ, u̇, ü): the velocities
  u̇ = −Ψ_u⁻¹Ψ_v ṫ and the accelerations ü = −Ψ_u⁻¹(Ψ_v ẗ + γ) at u;
- fourbar_kernel(x, sc) -> (Ψ, Ψ_u⁻¹, u′, u″): Ψ, the inverse and the
  analogs u′ = −Ψ_u⁻¹Ψ_v, u″ = −Ψ_u⁻¹γ(u′, 1) at a pose whose sines and
  cosines sc = (sin θ3, cos θ3, sin θ4, cos θ4, sin θ2, cos θ2) the caller
  supplies (carried along a sweep, as linkage's fast path does).

    python casadi_pose.py        # writes build/fourbar_pose.c and .h
"""
import os

import casadi as ca

from common import HERE, L1, L2, L3, L4


def psi(u, t):
    return ca.vertcat(
        L2 * ca.cos(t) + L3 * ca.cos(u[0]) + L4 * ca.cos(u[1]) - L1,
        L2 * ca.sin(t) + L3 * ca.sin(u[0]) + L4 * ca.sin(u[1]),
    )


def gamma(P, q, qd):
    """γ = (Ψ_q q̇)_q q̇"""
    return ca.jtimes(ca.jtimes(P, q, qd), q, qd)


def functions():
    u = ca.SX.sym("u", 2)
    t = ca.SX.sym("t")
    tdot = ca.SX.sym("tdot")
    tddot = ca.SX.sym("tddot")
    P = psi(u, t)
    Pu = ca.jacobian(P, u)
    Pv = ca.jacobian(P, t)
    step = -ca.solve(Pu, P)
    newton = ca.Function("fourbar_newton", [u, t], [u + step, ca.mmax(ca.fabs(step))])
    udot = -ca.solve(Pu, Pv * tdot)
    qd = ca.SX.sym("qd", 3)
    q = ca.vertcat(u, t)
    g = ca.Function("g", [u, t, qd], [gamma(P, q, qd)])(u, t, ca.vertcat(udot, tdot))
    uddot = -ca.solve(Pu, Pv * tddot + g)
    kinematics = ca.Function("fourbar_kinematics", [u, t, tdot, tddot], [P, udot, uddot])

    # The kernel on supplied sines and cosines: Ψ written in them.
    x = ca.SX.sym("x", 2)
    sc = ca.SX.sym("sc", 6)
    s3, c3, s4, c4, s2, c2 = (sc[i] for i in range(6))
    Pk = ca.vertcat(L2 * c2 + L3 * c3 + L4 * c4 - L1, L2 * s2 + L3 * s3 + L4 * s4)
    Puk = ca.horzcat(ca.vertcat(-L3 * s3, L3 * c3), ca.vertcat(-L4 * s4, L4 * c4))
    Pvk = ca.vertcat(-L2 * s2, L2 * c2)
    inverse = ca.inv(Puk)
    d1 = -ca.mtimes(inverse, Pvk)
    # γ(u′, 1) in the same sines and cosines (the four-bar's closed form of
    # (Ψ_q q̇)_q q̇, which CasADi cannot derive from symbols that are not
    # angles): −Σ lᵢ (cos θᵢ, sin θᵢ) θᵢ′².
    gk = -ca.vertcat(
        L3 * c3 * d1[0] ** 2 + L4 * c4 * d1[1] ** 2 + L2 * c2,
        L3 * s3 * d1[0] ** 2 + L4 * s4 * d1[1] ** 2 + L2 * s2,
    )
    d2 = -ca.mtimes(inverse, gk)
    kernel = ca.Function("fourbar_kernel", [x, sc], [Pk, ca.vec(inverse), d1, d2])
    return newton, kinematics, kernel


def main():
    cg = ca.CodeGenerator("fourbar_pose.c", {"with_header": True})
    for f in functions():
        cg.add(f)
    cg.generate(os.path.join(HERE, "build") + os.sep)


if __name__ == "__main__":
    main()
