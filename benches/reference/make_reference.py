#!/usr/bin/env python3
"""High-precision reference data for the tests and benchmarks of linkage.

Everything is computed with mpmath at 50 significant digits, from the closed
forms of the mechanisms, at driver values that are exactly representable as
f64 (the value the Rust code is given), and written as CSV under tests/data/.

    python3 benches/reference/make_reference.py [--bench | --all | --sensitivities]

(the near-singular references; --bench the dense-sweep references of the
benchmarks; --all both; --sensitivities the sensitivities to the parameters) creates its own virtual environment (benches/reference/.venv) with mpmath from
PyPI on first use, then reruns itself inside it.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_venv import ROOT, ensure_venv  # noqa: E402

ensure_venv(__file__)

import mpmath as mp  # noqa: E402

mp.mp.dps = 50


DIGITS = 40


def fmt(x):
    return mp.nstr(x, DIGITS, min_fixed=-5, max_fixed=5, strip_zeros=False)


def f64(x):
    """The f64 nearest to x, as an exact mpf, and its shortest repr."""
    d = float(x)
    return mp.mpf(d), repr(d)


def fourbar(l1, l2, l3, l4, theta2, sigma, omega2=1, alpha2=0):
    """θ3, θ4, ω3, ω4, α3, α4 of the worksheet's four-bar (θ4: angle of C→D)."""
    B = (l2 * mp.cos(theta2), l2 * mp.sin(theta2))
    D = (mp.mpf(l1), mp.mpf(0))
    d = (D[0] - B[0], D[1] - B[1])
    L = mp.sqrt(d[0] ** 2 + d[1] ** 2)
    a = (l3 ** 2 - l4 ** 2 + L ** 2) / (2 * L)
    h2 = l3 ** 2 - a ** 2
    if h2 < 0:
        return None
    h = mp.sqrt(h2)
    e = (d[0] / L, d[1] / L)
    C = (B[0] + a * e[0] - sigma * h * e[1], B[1] + a * e[1] + sigma * h * e[0])
    t3 = mp.atan2(C[1] - B[1], C[0] - B[0])
    t4 = mp.atan2(D[1] - C[1], D[0] - C[0])
    s34 = mp.sin(t3 - t4)
    w3 = -l2 * omega2 * mp.sin(theta2 - t4) / (l3 * s34)
    w4 = l2 * omega2 * mp.sin(theta2 - t3) / (l4 * s34)
    a3 = (-alpha2 * l2 * mp.sin(theta2 - t4) - l2 * omega2 ** 2 * mp.cos(theta2 - t4)
          - l3 * w3 ** 2 * mp.cos(t3 - t4) - l4 * w4 ** 2) / (l3 * s34)
    a4 = (alpha2 * l2 * mp.sin(theta2 - t3) + l2 * omega2 ** 2 * mp.cos(theta2 - t3)
          + l3 * w3 ** 2 + l4 * w4 ** 2 * mp.cos(t3 - t4)) / (l4 * s34)
    return t3, t4, w3, w4, a3, a4


def write(name, header, rows):
    path = os.path.join(ROOT, "tests", "data", name)
    with open(path, "w") as f:
        for line in header:
            f.write("# " + line + "\n")
        for row in rows:
            f.write(",".join(row) + "\n")
    print("wrote", os.path.relpath(path, ROOT), len(rows) - 1, "rows")


def near_singular(name, l2, singular, description):
    """The four-bar (80, l2, 50, 70) at θ2 = singular − δ, δ = 1e-1 … 1e-13."""
    rows = [["delta", "theta2", "theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4"]]
    for k in range(4, 53):
        delta = mp.mpf(10) ** (-mp.mpf(k) / 4)
        theta2, text = f64(singular - delta)
        exact_delta = singular - theta2
        r = fourbar(80, l2, 50, 70, theta2, 1)
        rows.append([fmt(exact_delta), text] + [fmt(x) for x in r])
    write(name, [
        description,
        "Written by benches/reference/make_reference.py (mpmath, 50 digits; 40 kept): the closed form at the",
        "f64 value of theta2 given in the second column, branch sigma = +1 (the worksheet's), omega2 = 1, alpha2 = 0",
        "(so omega and alpha are the first and second kinematic analogs). delta = exact distance to the singular pose.",
    ], rows)


def boom(length, ax=mp.mpf("0.4"), ay=mp.mpf("-0.3"), b=mp.mpf(1)):
    """The actuator-driven boom of the tests: K = b(cos θ, sin θ) at distance
    `length` from A = (ax, ay); φ the angle of A→K."""
    A = (ax, ay)
    dist = mp.sqrt(ax ** 2 + ay ** 2)
    # The angle γ between OA and OK, by the law of cosines in O-A-K; the
    # branch of the tests is θ = angle(OA) + γ (γ = π at full extension).
    cos_gamma = (b ** 2 + dist ** 2 - length ** 2) / (2 * b * dist)
    theta = mp.atan2(ay, ax) + mp.acos(cos_gamma)
    K = (b * mp.cos(theta), b * mp.sin(theta))
    phi = mp.atan2(K[1] - A[1], K[0] - A[0])
    return theta, phi


def near_limit_boom():
    """The boom as its actuator approaches full extension L* = b + |A| = 1.5."""
    top = mp.mpf("1.5")
    rows = [["delta", "length", "theta", "phi", "dtheta", "dphi", "ddtheta", "ddphi"]]
    for k in range(4, 53):
        delta = mp.mpf(10) ** (-mp.mpf(k) / 4)
        length, text = f64(top - delta)
        exact_delta = top - length
        th = lambda x: boom(x)[0]
        ph = lambda x: boom(x)[1]
        values = [th(length), ph(length), mp.diff(th, length), mp.diff(ph, length),
                  mp.diff(th, length, 2), mp.diff(ph, length, 2)]
        rows.append([fmt(exact_delta), text] + [fmt(x) for x in values])
    write("near_limit_boom.csv", [
        "The boom of tests/common (A = (0.4, -0.3), b = 1) as its actuator length approaches full extension L* = 1.5,",
        "where the cylinder lines up with the boom (a limit position of the actuator).",
        "Written by benches/reference/make_reference.py (mpmath, 50 digits; 40 kept): the closed form (circle intersection)",
        "at the f64 length of the second column, and its first and second derivatives d/dL by mpmath's diff.",
    ], rows)


# The dense sweep of the benchmarks: N samples per revolution, theta2_k =
# (TAU * k) / N computed in f64 exactly as the Rust code does; the reference
# is written at every STRIDE-th sample (3600 rows).
N = 1_008_000
STRIDE = 280


def grid():
    tau = 2 * 3.141592653589793  # TAU, exactly as in Rust
    for k in range(0, N, STRIDE):
        theta2 = (tau * k) / N
        yield k, mp.mpf(theta2), repr(theta2)


def dense_fourbar():
    omega2 = 400 * 2 * mp.pi / 60
    rows = [["k", "theta2", "theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4"]]
    for k, theta2, text in grid():
        r = fourbar(80, 20, 50, 70, theta2, 1, omega2=omega2, alpha2=0)
        rows.append([str(k), text] + [fmt(x) for x in r])
    write("bench_fourbar.csv", [
        "The worksheet's four-bar (80/20/50/70, branch sigma = +1), omega2 = 400 rpm, alpha2 = 0, on the dense grid",
        "theta2 = (TAU*k)/1008000 (f64), every 280th sample: the reference of the speed-accuracy benchmark.",
        "Written by benches/reference/make_reference.py (mpmath at 40 digits, 22 kept), from the closed form.",
    ], rows)


def derivatives(f, x):
    """f, f', f'' of a scalar function at x, by mpmath's high-precision diff."""
    return f(x), mp.diff(f, x), mp.diff(f, x, 2)


def dense_slider_crank():
    r, l, e = mp.mpf("0.05"), mp.mpf("0.2"), mp.mpf("0.01")
    theta3 = lambda t: mp.asin((e - r * mp.sin(t)) / l)
    s = lambda t: r * mp.cos(t) + l * mp.cos(theta3(t))
    rows = [["k", "theta2", "theta3", "s", "dtheta3", "ds", "ddtheta3", "dds"]]
    for k, theta2, text in grid():
        a = derivatives(theta3, theta2)
        b = derivatives(s, theta2)
        rows.append([str(k), text] + [fmt(x) for x in (a[0], b[0], a[1], b[1], a[2], b[2])])
    write("bench_slider_crank.csv", [
        "The offset slider-crank of the tests (r = 0.05, l = 0.2, e = 0.01 m) on the dense grid theta2 = (TAU*k)/1008000,",
        "every 280th sample: theta3 = asin((e - r sin theta2)/l), s = r cos theta2 + l cos theta3 and their first and second",
        "derivatives with respect to theta2 (kinematic analogs). Written by benches/reference/make_reference.py (mpmath).",
    ], rows)


def circle(p0, r0, p1, r1, sigma):
    d = (p1[0] - p0[0], p1[1] - p0[1])
    L = mp.sqrt(d[0] ** 2 + d[1] ** 2)
    a = (r0 ** 2 - r1 ** 2 + L ** 2) / (2 * L)
    h = mp.sqrt(r0 ** 2 - a ** 2)
    e = (d[0] / L, d[1] / L)
    return (p0[0] + a * e[0] - sigma * h * e[1], p0[1] + a * e[1] + sigma * h * e[0])


def six_bar(theta2, sigma2=1):
    l1, l2, l3, l4 = 80, 20, 50, 70
    e, beta, l5, l6, gx, gy = 40, mp.pi / 6, 60, 50, 20, 90
    t3, t4 = fourbar(l1, l2, l3, l4, theta2, 1)[:2]
    B = (l2 * mp.cos(theta2), l2 * mp.sin(theta2))
    E = (B[0] + e * mp.cos(t3 + beta), B[1] + e * mp.sin(t3 + beta))
    G = (mp.mpf(gx), mp.mpf(gy))
    Fp = circle(E, l5, G, l6, sigma2)
    return t3, t4, mp.atan2(Fp[1] - E[1], Fp[0] - E[0]), mp.atan2(Fp[1] - G[1], Fp[0] - G[0])


def dense_six_bar():
    rows = [["k", "theta2"] + [f"{p}theta{i}" for p in ("", "d", "dd") for i in (3, 4, 5, 6)]]
    for k, theta2, text in grid():
        values, firsts, seconds = [], [], []
        for i in range(4):
            f = lambda t, i=i: six_bar(t)[i]
            a = derivatives(f, theta2)
            values.append(a[0])
            firsts.append(a[1])
            seconds.append(a[2])
        rows.append([str(k), text] + [fmt(x) for x in values + firsts + seconds])
    write("bench_six_bar.csv", [
        "The two-loop six-bar of the tests (the worksheet's four-bar; coupler point at 40 mm, 30 deg; dyad 60/50 to the",
        "ground pivot (20, 90); dyad branch sigma = +1) on the dense grid theta2 = (TAU*k)/1008000, every 280th sample:",
        "theta3..theta6 and their first and second derivatives with respect to theta2 (kinematic analogs), by mpmath's",
        "diff on the closed form. Written by benches/reference/make_reference.py.",
    ], rows)


# The sensitivities: every coordinate and point of four mechanisms as
# closed forms X(v, p) of the driver v and the parameters p; the motion's
# velocity and acceleration Ẋ = X_v v̇, Ẍ = X_vv v̇² + X_v v̈ (one driver);
# and their derivatives by each parameter, X_p, X_vp v̇, X_vvp v̇² + X_vp v̈,
# by mpmath's diff (mixed partial derivatives at extra precision).


def fourbar_pose(v, p):
    l1, l2, l3, l4 = p
    t3, t4 = fourbar(l1, l2, l3, l4, v, 1)[:2]
    B = (l2 * mp.cos(v), l2 * mp.sin(v))
    C = (B[0] + l3 * mp.cos(t3), B[1] + l3 * mp.sin(t3))
    G4 = (C[0] + l4 * mp.cos(t4) / 2, C[1] + l4 * mp.sin(t4) / 2)
    return {"theta3": t3, "theta4": t4, "B.x": B[0], "B.y": B[1], "C.x": C[0], "C.y": C[1],
            "G2.x": B[0] / 2, "G2.y": B[1] / 2, "G3.x": (B[0] + C[0]) / 2,
            "G3.y": (B[1] + C[1]) / 2, "G4.x": G4[0], "G4.y": G4[1]}


def slider_crank_pose(v, p):
    r, l, e = p
    t3 = mp.asin((e - r * mp.sin(v)) / l)
    s = r * mp.cos(v) + l * mp.cos(t3)
    B = (r * mp.cos(v), r * mp.sin(v))
    return {"theta3": t3, "s": s, "B.x": B[0], "B.y": B[1], "P.x": s, "P.y": e,
            "G3.x": B[0] + l * mp.cos(t3) / 2, "G3.y": B[1] + l * mp.sin(t3) / 2}


def boom_pose(v, p):
    ax, ay, b, lb = p
    theta, phi = boom(v, ax, ay, b)
    return {"theta": theta, "phi": phi, "K.x": b * mp.cos(theta), "K.y": b * mp.sin(theta),
            "T.x": lb * mp.cos(theta), "T.y": lb * mp.sin(theta)}


def six_bar_pose(v, p):
    l1, l2, l3, l4, e, beta, l5, l6, gx, gy = p
    t3, t4 = fourbar(l1, l2, l3, l4, v, 1)[:2]
    B = (l2 * mp.cos(v), l2 * mp.sin(v))
    C = (B[0] + l3 * mp.cos(t3), B[1] + l3 * mp.sin(t3))
    E = (B[0] + e * mp.cos(t3 + beta), B[1] + e * mp.sin(t3 + beta))
    Fp = circle(E, l5, (gx, gy), l6, 1)
    t5 = mp.atan2(Fp[1] - E[1], Fp[0] - E[0])
    t6 = mp.atan2(Fp[1] - gy, Fp[0] - gx)
    return {"theta3": t3, "theta4": t4, "theta5": t5, "theta6": t6, "B.x": B[0], "B.y": B[1],
            "C.x": C[0], "C.y": C[1], "E.x": E[0], "E.y": E[1], "F.x": Fp[0], "F.y": Fp[1]}


def sensitivity_rows(name, pose, names, params, v, vdot, vddot):
    """The rows of one mechanism: its driver, every quantity's value,
    velocity and acceleration, then its derivatives by each parameter."""
    p = [mp.mpf(x) for x in params]
    v, vdot, vddot = mp.mpf(v), mp.mpf(vdot), mp.mpf(vddot)
    rows = [[name, "driver", "-", repr(float(v)), repr(float(vdot)), repr(float(vddot))]]
    for quantity in pose(v, p):
        def at(x, j=None, y=None):
            q = list(p)
            if j is not None:
                q[j] = y
            return pose(x, q)[quantity]
        d1 = mp.diff(lambda x: at(x), v)
        d2 = mp.diff(lambda x: at(x), v, 2)
        rows.append([name, quantity, "-", fmt(at(v)), fmt(d1 * vdot),
                     fmt(d2 * vdot ** 2 + d1 * vddot)])
        for j, pname in enumerate(names):
            f = lambda x, y, j=j: at(x, j, y)
            dp = mp.diff(f, (v, p[j]), (0, 1))
            dvp = mp.diff(f, (v, p[j]), (1, 1))
            dvvp = mp.diff(f, (v, p[j]), (2, 1))
            rows.append([name, quantity, pname, fmt(dp), fmt(dvp * vdot),
                         fmt(dvvp * vdot ** 2 + dvp * vddot)])
    return rows


def sensitivities():
    omega2 = 400.0 * (2 * 3.141592653589793) / 60.0  # OMEGA2, as in Rust
    theta2 = 20.0 * (3.141592653589793 / 180.0)  # 20f64.to_radians()
    rows = [["mechanism", "quantity", "param", "by_param", "dot_by_param", "ddot_by_param"]]
    rows += sensitivity_rows("fourbar", fourbar_pose, ["l1", "l2", "l3", "l4"],
                             [80, 20, 50, 70], theta2, omega2, 0.0)
    rows += sensitivity_rows("slider_crank", slider_crank_pose, ["r", "l", "e"],
                             ["0.05", "0.2", "0.01"], 1.0, omega2, -2.0)
    rows += sensitivity_rows("boom", boom_pose, ["ax", "ay", "b", "lb"],
                             ["0.4", "-0.3", "1", "2.5"], 1.1, 0.1, 0.02)
    beta = float(mp.pi / 6)  # PI / 6.0 in f64
    rows += sensitivity_rows("six_bar", six_bar_pose,
                             ["l1", "l2", "l3", "l4", "e", "beta", "l5", "l6", "gx", "gy"],
                             [80, 20, 50, 70, 40, beta, 60, 50, 20, 90], 0.5, 1.0, 0.5)
    write("sensitivities.csv", [
        "Sensitivities to the parameters of the worksheet's four-bar (theta2 = 20 deg, 400 rpm, alpha2 = 0), the offset",
        "slider-crank, the actuator-driven boom and the two-loop six-bar of the tests, at the driver position, speed and",
        "acceleration of each 'driver' row (f64 values). Rows with param '-': the quantity X, its velocity and acceleration;",
        "other rows: dX/dp, d(Xdot)/dp, d(Xddot)/dp. Written by benches/reference/make_reference.py --sensitivities",
        "(mpmath, 50 digits, 40 kept): each quantity in closed form X(v, p), its motion X_v vdot and X_vv vdot^2 + X_v vddot,",
        "and the mixed partial derivatives by mpmath's diff.",
    ], rows)


def main():
    global DIGITS
    if "--sensitivities" in sys.argv:
        sensitivities()
        return
    if "--bench" in sys.argv or "--all" in sys.argv:
        # 22 digits are plenty to measure f64 errors, and keep the files small.
        mp.mp.dps, DIGITS = 40, 22
        dense_fourbar()
        dense_slider_crank()
        dense_six_bar()
        mp.mp.dps, DIGITS = 50, 40
        if "--bench" in sys.argv:
            return
    near_limit_boom()
    limit = mp.acos((mp.mpf(80) ** 2 + 45 ** 2 - 120 ** 2) / (2 * 80 * 45))
    near_singular(
        "near_limit.csv", 45, limit,
        "Non-Grashof four-bar l = 80/45/50/70 approaching its limit position theta2* = acos((80^2+45^2-120^2)/(2*80*45)) = "
        + mp.nstr(limit, 30) + " rad.",
    )
    near_singular(
        "near_branch.csv", 40, mp.pi,
        "Change-point four-bar l = 80/40/50/70 approaching its branch point theta2 = pi (all joints collinear).",
    )


if __name__ == "__main__":
    main()
