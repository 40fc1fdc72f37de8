#!/usr/bin/env python3
"""The new mechanisms of the library `mechanisms/`, solved independently of
the crate: the reference of tests/kinematics/library.rs.

    python3 benches/reference/mechanism_files.py

creates its own virtual environment (benches/reference/.venv, mpmath from
PyPI) on first use, as make_reference.py does, and writes

- tests/data/jansen_leg.csv: Jansen's leg with the published "holy
  numbers" (a = 38, b = 41.5, c = 39.3, d = 40.1, e = 55.8, f = 39.4,
  g = 36.7, h = 65.7, i = 49, j = 50, k = 61.9, l = 7.8, m = 15), the crank
  axle O at the origin, the frame pivot Z at (-a, -l);
- tests/data/quick_return.csv: a crank-and-slotted-lever quick return
  with a connecting rod to the ram (the fixed centres 240 apart, crank 120,
  slotted lever 450, rod 135, the ram's line 180 above the crank's centre);
- tests/data/trammel.csv: an elliptic trammel driven by its slider A
  (bar 0.25 m, the tracing point 0.1 m from A),

each at a dozen driver values, to 30 digits: the dependent coordinates and
the traced point. Each is solved in closed form, dyad by dyad (a point at
distance r1 from P and r2 from Q: the intersection of two circles, on the
side of the line P -> Q the branch keeps), at 50 digits, from the f64
dimensions and driver values the Rust code is given. The script also
checks that each mechanism assembles over its whole drive range, on a grid
of 36000 driver values: every dyad's centres closer than the sum of its
radii and farther apart than their difference, by the margin printed.

Branches (the assembly the files start from):
- Jansen: J (where j meets b) right of M -> Z, K (where k meets c) left of
  M -> Z, R (where f meets g) right of Q -> K; the upper triangle's vertex
  Q at the angle delta_bd counter-clockwise from Z -> J, the foot at
  delta_gi counter-clockwise from K -> R, each angle of its triangle by the
  law of cosines. (The leg in the usual drawings: the foot below.)
- The quick return: the block on the lever beyond the pivot C (s > 0), the
  ram to the right of the lever's tip P.
- The trammel: B above A's guide (the bar's angle in (0, pi)).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_venv import ROOT, ensure_venv  # noqa: E402

ensure_venv(__file__)

import mpmath as mp  # noqa: E402

mp.mp.dps = 50
DIGITS = 30
DATA = os.path.join(ROOT, "tests", "data")


def fmt(x):
    return mp.nstr(x, DIGITS, min_fixed=-5, max_fixed=5, strip_zeros=False)


def circles(p, r1, q, r2, left, lib=mp):
    """The point at distance r1 from p and r2 from q, left (or right) of
    the line p -> q; and the margin of the dyad (how far the distance |pq|
    is from the limits |r1 - r2| and r1 + r2)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = lib.sqrt(dx * dx + dy * dy)
    margin = min(r1 + r2 - d, d - abs(r1 - r2))
    if margin <= 0:
        return None, margin
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = lib.sqrt(r1 * r1 - a * a)
    ux, uy = dx / d, dy / d
    sign = 1 if left else -1
    x = p[0] + a * ux - sign * h * uy
    y = p[1] + a * uy + sign * h * ux
    return (x, y), margin


def angle(p, q, lib=mp):
    """The direction of p -> q."""
    return lib.atan2(q[1] - p[1], q[0] - p[0])


def wrap(x, lib=mp):
    """An angle in [-pi, pi)."""
    return x - 2 * lib.pi * lib.floor((x + lib.pi) / (2 * lib.pi))


JANSEN = dict(a=38.0, b=41.5, c=39.3, d=40.1, e=55.8, f=39.4, g=36.7, h=65.7,
              i=49.0, j=50.0, k=61.9, l=7.8, m=15.0)


def jansen(theta, lib=mp):
    """(u = [phi_j, phi_b, phi_k, phi_c, phi_f, phi_g], the foot, the
    smallest dyad margin), or (None, None, margin) where it cannot close."""
    n = {key: (lib.mpf(v) if lib is mp else v) for key, v in JANSEN.items()}
    z = (-n["a"], -n["l"])
    mpin = (n["m"] * lib.cos(theta), n["m"] * lib.sin(theta))
    jj, m1 = circles(mpin, n["j"], z, n["b"], left=False, lib=lib)
    kk, m2 = circles(mpin, n["k"], z, n["c"], left=True, lib=lib)
    if jj is None or kk is None:
        return None, None, min(m1, m2)
    phi_b = angle(z, jj, lib)
    bd = lib.acos((n["b"] ** 2 + n["d"] ** 2 - n["e"] ** 2) / (2 * n["b"] * n["d"]))
    q = (z[0] + n["d"] * lib.cos(phi_b + bd), z[1] + n["d"] * lib.sin(phi_b + bd))
    rr, m3 = circles(q, n["f"], kk, n["g"], left=False, lib=lib)
    if rr is None:
        return None, None, min(m1, m2, m3)
    phi_g = angle(kk, rr, lib)
    gi = lib.acos((n["g"] ** 2 + n["i"] ** 2 - n["h"] ** 2) / (2 * n["g"] * n["i"]))
    foot = (kk[0] + n["i"] * lib.cos(phi_g + gi), kk[1] + n["i"] * lib.sin(phi_g + gi))
    u = [angle(mpin, jj, lib), phi_b, angle(mpin, kk, lib), angle(z, kk, lib),
         angle(q, rr, lib), phi_g]
    return [wrap(x, lib) for x in u], foot, min(m1, m2, m3)


QUICK = dict(r=120.0, d=240.0, lever=450.0, rod=135.0, y_r=180.0)


def quick_return(theta, lib=mp):
    """(u = [phi3, s, phi4, x_r], the ram R, the rod's margin)."""
    n = {key: (lib.mpf(v) if lib is mp else v) for key, v in QUICK.items()}
    a = (n["r"] * lib.cos(theta), n["r"] * lib.sin(theta))
    c = (0, -n["d"])
    s = lib.sqrt((a[0] - c[0]) ** 2 + (a[1] - c[1]) ** 2)
    phi3 = angle(c, a, lib)
    p = (n["lever"] * lib.cos(phi3), -n["d"] + n["lever"] * lib.sin(phi3))
    rise = n["y_r"] - p[1]
    margin = n["rod"] - abs(rise)
    if margin <= 0:
        return None, None, margin
    x_r = p[0] + lib.sqrt(n["rod"] ** 2 - rise ** 2)
    phi4 = lib.atan2(rise, x_r - p[0])
    return [wrap(phi3, lib), s, phi4, x_r], (x_r, n["y_r"]), min(margin, s)


TRAMMEL = dict(l=0.25, p=0.1)


def trammel(x_a, lib=mp):
    """(u = [phi, y_b], the tracing point P, the margin from A's limits)."""
    n = {key: (lib.mpf(v) if lib is mp else v) for key, v in TRAMMEL.items()}
    x_a = lib.mpf(x_a) if lib is mp else x_a
    margin = n["l"] - abs(x_a)
    if margin <= 0:
        return None, None, margin
    phi = lib.acos(-x_a / n["l"])
    y_b = n["l"] * lib.sin(phi)
    point = (x_a + n["p"] * lib.cos(phi), n["p"] * lib.sin(phi))
    return [phi, y_b], point, margin


def check_range(name, solve, lo, hi, count=36000):
    """Assembles at every one of `count` + 1 driver values from lo to hi
    (floats), with the smallest margin printed."""
    worst = math.inf
    for k in range(count + 1):
        v = lo + (hi - lo) * k / count
        u, _, margin = solve(v, lib=math)
        if u is None:
            raise SystemExit(f"{name} does not assemble at {v}: margin {margin}")
        worst = min(worst, margin)
    print(f"{name}: assembles over [{lo}, {hi}] ({count + 1} values), smallest margin {worst:.4g}")


def write(file, header, columns, rows):
    path = os.path.join(DATA, file)
    with open(path, "w") as out:
        out.write(header)
        out.write(",".join(columns) + "\n")
        for row in rows:
            out.write(",".join(row) + "\n")
    print(f"wrote {path}: {len(rows)} rows")


def main():
    check_range("Jansen's leg", jansen, 0.0, 2 * math.pi)
    check_range("quick return", quick_return, 0.0, 2 * math.pi)
    check_range("trammel", trammel, -0.2, 0.2)

    rows = []
    for k in range(12):
        theta = math.radians(30.0 * k)  # = (30k as f64).to_radians()
        u, foot, _ = jansen(mp.mpf(theta))
        rows.append([repr(theta)] + [fmt(x) for x in u] + [fmt(foot[0]), fmt(foot[1])])
    write(
        "jansen_leg.csv",
        "# Jansen's leg (mechanisms/jansen_leg.toml) at theta = 30k deg: u and the foot, "
        "solved dyad by dyad at 50 digits by benches/reference/mechanism_files.py\n",
        ["theta", "phi_j", "phi_b", "phi_k", "phi_c", "phi_f", "phi_g", "foot_x", "foot_y"],
        rows,
    )

    rows = []
    for k in range(12):
        theta = math.radians(30.0 * k)
        u, ram, _ = quick_return(mp.mpf(theta))
        rows.append([repr(theta)] + [fmt(x) for x in u])
        assert ram[0] == u[3]
    write(
        "quick_return.csv",
        "# The crank-and-slotted-lever quick return (mechanisms/quick_return.toml) at "
        "theta = 30k deg: u (the ram's x last), in closed form at 50 digits by "
        "benches/reference/mechanism_files.py\n",
        ["theta", "phi3", "s", "phi4", "x_r"],
        rows,
    )

    rows = []
    for k in range(9):
        x_a = -0.2 + 0.05 * k  # the f64 the Rust code computes the same way
        u, point, _ = trammel(mp.mpf(x_a))
        rows.append([repr(x_a)] + [fmt(x) for x in u] + [fmt(point[0]), fmt(point[1])])
    write(
        "trammel.csv",
        "# The elliptic trammel (mechanisms/trammel.toml) at x_a = -0.2 + 0.05k m: u and "
        "the tracing point P, in closed form at 50 digits by "
        "benches/reference/mechanism_files.py\n",
        ["x_a", "phi", "y_b", "p_x", "p_y"],
        rows,
    )


if __name__ == "__main__":
    main()
