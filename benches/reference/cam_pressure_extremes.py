#!/usr/bin/env python3
"""The extremes of a cam's pressure angle at 50 digits: the independent
reference of `Cam::pressure_extremes` (tests/machine/cam.rs).

    python3 benches/reference/cam_pressure_extremes.py

creates its own virtual environment (benches/reference/.venv, mpmath from
PyPI) on first use, as make_reference.py does, and writes

    tests/data/cam_pressure_extremes.csv

For four cams whose laws are smooth inside their segments (a rocker and a
translating follower with an offset, each turning either way; cycloidal,
harmonic and 3-4-5 rises and returns), every number given as the f64 the
Rust test gives: the largest and the smallest pressure angle over a turn and
the cam angle where each is.

How. The pressure angle θ(φ) is built here from its geometric definition
(the angle between the pitch curve's normal and the direction the follower
moves the roller centre, by inversion), written afresh in mpmath from the
follower's s(φ), s'(φ) in closed form; its derivative is mpmath's numerical
differentiation of θ at 50 digits (no analytic formula shared with the
Rust code). Each smooth piece (between the program's breakpoints) is
scanned at 2000 points for sign changes of θ', each is refined by
mpmath's findroot (the Anderson–Björck bracketing method, to 45 digits), and the best of these
and of the pieces' ends is kept. The script checks that every extreme it
writes is inside a piece (θ' = 0 there, θ'' of the right sign), so that its
abscissa is a well-defined number the test can measure.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_venv import ROOT, ensure_venv  # noqa: E402

ensure_venv(__file__)

import mpmath as mp  # noqa: E402

mp.mp.dps = 50
DIGITS = 40
PI = mp.pi


# The laws, normalized: (S, S') at x in [0, 1].
def cycloidal(x):
    w = 2 * PI
    return x - mp.sin(w * x) / w, 1 - mp.cos(w * x)


def harmonic(x):
    return (1 - mp.cos(PI * x)) / 2, PI * mp.sin(PI * x) / 2


def poly345(x):
    return 10 * x**3 - 15 * x**4 + 6 * x**5, 30 * x**2 * (1 - x) ** 2


LAWS = {"Cycloidal": cycloidal, "Harmonic": harmonic, "Polynomial345": poly345}


def f(x):
    """The f64 the Rust test writes as the literal x, exactly."""
    return mp.mpf(float(x))


class Program:
    """segments: [("rise" | "dwell" | "return", angle, law name or None)]."""

    def __init__(self, lift, segments):
        self.lift = f(lift)
        self.segments = [(kind, f(angle), law) for kind, angle, law in segments]

    def s(self, phi):
        """s, s' at phi in [0, 2π)."""
        start, level = mp.mpf(0), mp.mpf(0)
        for kind, a, law in self.segments:
            if phi < start + a:
                x = (phi - start) / a
                if kind == "dwell":
                    return level, mp.mpf(0)
                if kind == "rise":
                    S, dS = LAWS[law](x)
                    return self.lift * S, self.lift * dS / a
                S, dS = LAWS[law](1 - x)
                return self.lift * S, -self.lift * dS / a
            start += a
            level = self.lift if kind == "rise" else (0 if kind == "return" else level)
        return level, mp.mpf(0)

    def pieces(self):
        """The smooth pieces [a, b] of a turn (the laws here have no inner
        breakpoints)."""
        out, start = [], mp.mpf(0)
        for kind, a, law in self.segments:
            out.append((start, start + a, kind))
            start += a
        if start < 2 * PI:
            out.append((start, 2 * PI, "dwell"))
        return out


def rot(v, t):
    c, s = mp.cos(t), mp.sin(t)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


def perp(v):
    return (-v[1], v[0])


def theta(cam, phi):
    """The pressure angle at phi from its definition: K(φ) the roller centre
    in the cam's frame (the follower turned by −σφ about the cam's centre),
    n the pitch curve's normal pointing away from the cam's centre (the
    cam pushes the roller along it), m the direction the follower moves K;
    θ = σ·(the angle from m to n), folded into (−90°, 90°]."""
    sigma = cam["sigma"]
    s, ds = cam["program"].s(phi)
    if cam["kind"] == "rocker":
        arm, a_w, psi0, gamma0 = cam["arm"], cam["centre"], cam["initial"], cam["pivot"]
        gamma = gamma0 - sigma * phi
        beta = gamma + PI + psi0 + s / arm
        ug, ub = (mp.cos(gamma), mp.sin(gamma)), (mp.cos(beta), mp.sin(beta))
        k = (a_w * ug[0] + arm * ub[0], a_w * ug[1] + arm * ub[1])
        # K' by differentiating K: dγ = −σ, dβ = −σ + s'/l.
        dbeta = -sigma + ds / arm
        pg, pb = perp(ug), perp(ub)
        dk = (a_w * -sigma * pg[0] + arm * dbeta * pb[0], a_w * -sigma * pg[1] + arm * dbeta * pb[1])
        m = pb
    else:
        e, base, axis = cam["offset"], cam["base"], cam["axis"]
        u = (mp.cos(axis), mp.sin(axis))
        s0 = mp.sqrt(base**2 - e**2)
        local = (-u[1] * e + u[0] * (s0 + s), u[0] * e + u[1] * (s0 + s))
        t = -sigma * phi
        k = rot(local, t)
        # d/dφ R(t)·v = R(t)·(v' + t'·⟂v), t' = −σ.
        dlocal = (u[0] * ds, u[1] * ds)
        pl = perp(local)
        dk = rot((dlocal[0] - sigma * pl[0], dlocal[1] - sigma * pl[1]), t)
        m = rot(u, t)
    n = perp(dk)
    if n[0] * k[0] + n[1] * k[1] < 0:
        n = (-n[0], -n[1])
    ang = mp.atan2(m[0] * n[1] - m[1] * n[0], m[0] * n[0] + m[1] * n[1])
    if ang > PI / 2:
        ang -= PI
    elif ang <= -PI / 2:
        ang += PI
    return sigma * ang


def dtheta(cam, phi):
    return mp.diff(lambda x: theta(cam, x), phi)


def extremes(cam):
    """[(φ, θ) at the maximum, (φ, θ) at the minimum], each inside a piece."""
    found = []  # (phi, theta, inside)
    for a, b, kind in cam["program"].pieces():
        found += [(a, theta(cam, a), False), (b, theta(cam, b - mp.mpf(10) ** -40), False)]
        if kind == "dwell":
            continue
        n = 2000
        xs = [a + (b - a) * (i + mp.mpf(1) / 2) / n for i in range(n)]
        ds = [dtheta(cam, x) for x in xs]
        for i in range(n - 1):
            if (ds[i] > 0) != (ds[i + 1] > 0):
                root = mp.findroot(lambda x: dtheta(cam, x), (xs[i], xs[i + 1]), solver="anderson")
                assert xs[i] <= root <= xs[i + 1]
                assert abs(dtheta(cam, root)) < mp.mpf(10) ** -40
                found.append((root, theta(cam, root), True))
    out = []
    for sign in (1, -1):
        best = max(found, key=lambda t: sign * t[1])
        phi, value, inside = best
        assert inside, (cam["name"], sign, best)
        # Strictly the best: every other candidate at least 1e-6 rad below.
        rivals = [t for t in found if abs(t[0] - phi) > mp.mpf(10) ** -6]
        assert all(sign * (value - t[1]) > mp.mpf(10) ** -6 for t in rivals), cam["name"]
        curvature = mp.diff(lambda x: theta(cam, x), phi, 2)
        assert sign * curvature < 0, (cam["name"], sign, curvature)
        out.append((phi, value, curvature))
    return out


def cams():
    smooth = Program(
        0.045,
        [("rise", 1.2, "Cycloidal"), ("dwell", 0.5, None), ("return", 1.6, "Polynomial345")],
    )
    harmonic = Program(
        0.03,
        [("rise", 1.5, "Harmonic"), ("dwell", 0.3, None), ("return", 1.4, "Cycloidal")],
    )
    rocker = dict(kind="rocker", program=smooth, arm=f(0.15), centre=f(0.3), initial=f(0.9),
                  pivot=f(-1.5707963267948966))
    translating = dict(kind="translating", program=harmonic, offset=f(0.01), base=f(0.05),
                       axis=f(1.5707963267948966))
    return [
        dict(rocker, name="rocker_ccw", sigma=1),
        dict(rocker, name="rocker_cw", sigma=-1),
        dict(translating, name="translating_ccw", sigma=1),
        dict(translating, name="translating_cw", sigma=-1),
    ]


def main():
    rows = []
    for cam in cams():
        (phi_max, th_max, c_max), (phi_min, th_min, c_min) = extremes(cam)
        rows.append((cam["name"], "max", phi_max, th_max, c_max))
        rows.append((cam["name"], "min", phi_min, th_min, c_min))
        print(cam["name"], mp.nstr(phi_max, 20), mp.nstr(th_max, 20), mp.nstr(phi_min, 20), mp.nstr(th_min, 20))
    path = os.path.join(ROOT, "tests", "data", "cam_pressure_extremes.csv")
    with open(path, "w") as out:
        out.write("# The extremes of the pressure angle of four cams over a turn (tests/machine/cam.rs builds the same cams),\n")
        out.write("# made by benches/reference/cam_pressure_extremes.py (mpmath 1.3.0, 50 digits; roots of dθ/dφ, 40 digits kept).\n")
        out.write("# theta_second: d²θ/dφ² there (rad/rad²), the scale of how flat the extreme is.\n")
        out.write("cam,extreme,phi,theta,theta_second\n")
        for name, which, phi, th, c in rows:
            out.write(f"{name},{which},{mp.nstr(phi, DIGITS)},{mp.nstr(th, DIGITS)},{mp.nstr(c, 12)}\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
