#!/usr/bin/env python3
"""High-precision reference data for the tests and benchmarks of linkage.

Everything is computed with mpmath at 50 significant digits, from the closed
forms of the mechanisms, at driver values that are exactly representable as
f64 (the value the Rust code is given), and written as CSV under tests/data/.

    python3 benches/reference/make_reference.py [--bench | --all]

(the near-singular references; --bench the dense-sweep references of the
benchmarks; --all both) creates its own virtual environment (benches/reference/.venv) with mpmath from
PyPI on first use, then reruns itself inside it.
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
VENV = os.path.join(HERE, ".venv")
PY = os.path.join(VENV, "bin", "python")


def ensure_venv():
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(PY):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([PY, "-m", "pip", "install", "--quiet", "mpmath==1.3.0"])
    os.execv(PY, [PY, os.path.abspath(__file__)] + sys.argv[1:])


ensure_venv()

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


def main():
    global DIGITS
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
