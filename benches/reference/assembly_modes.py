#!/usr/bin/env python3
"""Every assembly of the test mechanisms at one driver value, counted and
located independently of the crate: the independent reference of
tests/kinematics/assembly.rs.

    python3 benches/reference/assembly_modes.py

creates its own virtual environment (benches/reference/.venv, mpmath and
SymPy from PyPI) on first use, as make_reference.py does, prints each
mechanism's count and writes tests/data/assembly_modes.csv: one row per
assembly, its dependent coordinates u (angles in [-pi, pi)) to 30 digits.

The method is elimination, not iteration: each mechanism's closure
equations are reduced to one polynomial in one unknown, whose real roots are
counted and found at 50 digits, and the other coordinates follow from each
root in closed form.

- One loop closed by a dyad (the four-bar, the five-bar, the slider-crank
  driven by its slider, the boom, the four-bar whose coupler is a body) and
  the six-bars whose loops close one after the other (the Watt six-bar, the
  four-bar with a dyad on its coupler): the point X at distance a from P
  and b from Q, X = P + a(cos phi, sin phi), satisfies
  K + A cos phi + B sin phi = 0 with K = |P - Q|^2 + a^2 - b^2,
  A = 2a(P - Q)_x, B = 2a(P - Q)_y; with t = tan(phi/2) this is the
  quadratic (K - A) t^2 + 2B t + (K + A) = 0, two real roots, one double
  root (a dead centre) or none.
- The slider-crank: l sin(theta3) = e - r sin(theta2) is the quadratic
  k t^2 - 2l t + k = 0 in t = tan(theta3/2), k = e - r sin(theta2).
- The Stephenson III six-bar (its driven crank in no four-bar loop): the two
  ternary links' angles theta3, theta4 must satisfy |F - C|^2 = l5^2 and
  |G - E|^2 = l6^2, each of bidegree (2, 2) in x = tan(theta3/2),
  y = tan(theta4/2) once multiplied by (1 + x^2)(1 + y^2). Their resultant
  in y (SymPy, exact rational arithmetic) is a polynomial of degree 8 in x,
  whose real roots are counted with Sturm sequences (SymPy's real_roots) and
  located at 50 digits; at each, the common root y of the two bivariate
  polynomials is the root of the first that the second shares, and theta5,
  theta6 follow from the directions of F - C and G - E. The driver's cosine
  and sine are the exact rationals 3/5 and 4/5.

The driver values are f64 numbers, taken exactly (their shortest repr is
written beside them), but for the Stephenson six-bar's (atan2(4, 3) and
atan2(5, 12), whose f64 cosines differ from 3/5 and 12/13 by less than
1e-16).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_venv import ROOT, ensure_venv  # noqa: E402

ensure_venv(__file__, ["mpmath==1.3.0", "sympy==1.14.0"])

import mpmath as mp  # noqa: E402
import sympy as sp  # noqa: E402

mp.mp.dps = 50
DIGITS = 30
OUT = os.path.join(ROOT, "tests", "data", "assembly_modes.csv")


def f64(x):
    """The f64 x, as an exact mpf."""
    return mp.mpf(float(x))


def e(phi):
    return (mp.cos(phi), mp.sin(phi))


def add(p, q, k=1):
    return (p[0] + k * q[0], p[1] + k * q[1])


def angle(v):
    return mp.atan2(v[1], v[0])


def wrap(phi):
    """phi in [-pi, pi)."""
    return phi - 2 * mp.pi * mp.floor((phi + mp.pi) / (2 * mp.pi))


def quadratic(a, b, c):
    """The real roots of a t^2 + b t + c = 0 (a != 0), ascending."""
    if a == 0:
        raise ValueError("a root at t = infinity: choose other dimensions")
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    r = mp.sqrt(disc)
    return sorted([(-b - r) / (2 * a), (-b + r) / (2 * a)])


def dyad(p, q, a, b):
    """The angles phi of X = P + a e(phi) with |X - Q| = b."""
    d = add(p, q, -1)
    k = d[0] ** 2 + d[1] ** 2 + a * a - b * b
    ca, sb = 2 * a * d[0], 2 * a * d[1]
    return [2 * mp.atan(t) for t in quadratic(k - ca, 2 * sb, k + ca)]


def four_bar(l1, l2, l3, l4, theta2):
    """The worksheet's model: l2 e2 + l3 e3 + l4 e4 = (l1, 0)."""
    b, d = (l2 * mp.cos(theta2), l2 * mp.sin(theta2)), (l1, mp.mpf(0))
    modes = []
    for t3 in dyad(b, d, l3, l4):
        c = add(b, e(t3), l3)
        modes.append([t3, angle(add(d, c, -1))])
    return modes


def slider_crank(r, l, ecc, theta2):
    """r e2 + l e3 = (s, e): u = (theta3, s)."""
    k = ecc - r * mp.sin(theta2)
    modes = []
    for t in quadratic(k, -2 * l, k):
        t3 = 2 * mp.atan(t)
        modes.append([t3, r * mp.cos(theta2) + l * mp.cos(t3)])
    return modes


def slider_driven(r, l, ecc, s):
    """The same loop driven by s: u = (theta2, theta3)."""
    o, slider = (mp.mpf(0), mp.mpf(0)), (s, ecc)
    modes = []
    for t2 in dyad(o, slider, r, l):
        b = e(t2)
        b = (r * b[0], r * b[1])
        modes.append([t2, angle(add(slider, b, -1))])
    return modes


def boom(ax, ay, b, length):
    """A + L e(phi) = b e(theta): u = (theta, phi)."""
    o, a = (mp.mpf(0), mp.mpf(0)), (ax, ay)
    modes = []
    for t in dyad(o, a, b, length):
        k = (b * mp.cos(t), b * mp.sin(t))
        modes.append([t, angle(add(k, a, -1))])
    return modes


def five_bar(l1, l2, l3, l4, l5, theta2, theta5):
    """B + l3 e3 = D + l4 e4: u = (theta3, theta4)."""
    b = (l2 * mp.cos(theta2), l2 * mp.sin(theta2))
    d = (l1 + l5 * mp.cos(theta5), l5 * mp.sin(theta5))
    modes = []
    for t3 in dyad(b, d, l3, l4):
        c = add(b, e(t3), l3)
        modes.append([t3, angle(add(c, d, -1))])
    return modes


def coupler(xa, ya, xd, yd, l2, l4, bx, by, cx, cy, theta2):
    """A body through B (crank tip) and C (rocker tip): u = (x_p, y_p,
    theta3, theta4), B = P + R(theta3)(bx, by), C = P + R(theta3)(cx, cy)."""
    b = (xa + l2 * mp.cos(theta2), ya + l2 * mp.sin(theta2))
    d = (xd, yd)
    k = mp.sqrt((bx - cx) ** 2 + (by - cy) ** 2)
    modes = []
    for t4 in dyad(d, b, l4, k):
        c = add(d, e(t4), l4)
        t3 = angle(add(b, c, -1)) - mp.atan2(by - cy, bx - cx)
        rb = (bx * mp.cos(t3) - by * mp.sin(t3), bx * mp.sin(t3) + by * mp.cos(t3))
        p = add(b, rb, -1)
        modes.append([p[0], p[1], t3, t4])
    return modes


def six_bar(l1, l2, l3, l4, ee, beta, l5, l6, gx, gy, theta2):
    """The four-bar with the dyad E-F-G on its coupler (tests/models/six_bar.rs)."""
    b = (l2 * mp.cos(theta2), l2 * mp.sin(theta2))
    g = (gx, gy)
    modes = []
    for t3, t4 in four_bar(l1, l2, l3, l4, theta2):
        pe = add(b, e(t3 + beta), ee)
        for t5 in dyad(pe, g, l5, l6):
            f = add(pe, e(t5), l5)
            modes.append([t3, t4, t5, angle(add(f, g, -1))])
    return modes


def watt_six_bar(l1, l2, l3, l4, le, beta, l5, l6, gx, gy, theta2):
    """The Watt six-bar (tests/models/watt_six_bar.rs): its second loop
    from E on the rocker, (l1, 0) + le e(theta4 + beta), through F to G."""
    g = (gx, gy)
    modes = []
    for t3, t4 in four_bar(l1, l2, l3, l4, theta2):
        pe = add((l1, mp.mpf(0)), e(t4 + beta), le)
        for t5 in dyad(pe, g, l5, l6):
            f = add(pe, e(t5), l5)
            modes.append([t3, t4, t5, angle(add(g, f, -1))])
    return modes


def stephenson_three(p, c2, s2):
    """The Stephenson III six-bar (tests/models/stephenson_three.rs) at the
    crank angle of cosine c2, sine s2 (exact rationals)."""
    l2, l3, ex, ey, dx, dy, l4, gx, gy, l5, l6 = [sp.Rational(v) for v in p]
    x, y, c3, s3, c4, s4 = sp.symbols("x y c3 s3 c4 s4")
    b = (l2 * c2, l2 * s2)
    c = (b[0] + l3 * c3, b[1] + l3 * s3)
    pe = (b[0] + ex * c3 - ey * s3, b[1] + ex * s3 + ey * c3)
    f = (dx + l4 * c4, dy + l4 * s4)
    g = (dx + gx * c4 - gy * s4, dy + gx * s4 + gy * c4)

    def half_angle(expr):
        # Affine in (c3, s3) and in (c4, s4) once s^2 = 1 - c^2.
        expr = sp.expand(expr)
        expr = sp.expand(expr.subs({s3**2: 1 - c3**2, s4**2: 1 - c4**2}))
        expr = sp.expand(expr * (1 + x**2) * (1 + y**2))
        expr = expr.subs({c3: (1 - x**2) / (1 + x**2), s3: 2 * x / (1 + x**2),
                          c4: (1 - y**2) / (1 + y**2), s4: 2 * y / (1 + y**2)})
        return sp.Poly(sp.cancel(expr), x, y)

    p1 = half_angle((f[0] - c[0]) ** 2 + (f[1] - c[1]) ** 2 - l5**2)
    p2 = half_angle((g[0] - pe[0]) ** 2 + (g[1] - pe[1]) ** 2 - l6**2)
    assert p1.degree(x) == 2 and p1.degree(y) == 2 and p2.degree(y) == 2
    res = sp.Poly(sp.resultant(p1.as_expr(), p2.as_expr(), y), x)
    assert res.degree() == 8, "a root at theta3 = pi: choose other dimensions"
    # A double root of the resultant would be a dead centre or two
    # assemblies sharing theta3: neither, at these dimensions.
    assert sp.gcd(res, res.diff(x)).degree() == 0
    count = len(res.real_roots())
    coefficients = [rat(sp.Rational(k)) for k in res.all_coeffs()]
    roots = [r.real for r in mp.polyroots(coefficients, maxsteps=200, extraprec=200)
             if abs(r.imag) < mp.mpf(10) ** -40]
    assert len(roots) == count, (len(roots), count)
    modes = []
    for xr in sorted(roots):
        qy = [mp.mpf(0)] * 3
        for (i, j), k in p1.terms():
            qy[2 - j] += rat(k) * xr**i
        ys = quadratic(*qy)
        resid = []
        for yr in ys:
            v = mp.mpf(0)
            for (i, j), k in p2.terms():
                v += rat(k) * xr**i * yr**j
            resid.append(abs(v))
        yr = ys[resid.index(min(resid))]
        assert min(resid) < mp.mpf(10) ** -30 and max(resid) > mp.mpf(10) ** -10
        t3, t4 = 2 * mp.atan(xr), 2 * mp.atan(yr)
        bb = (rat(c2) * rat(l2), rat(s2) * rat(l2))
        cc = (bb[0] + rat(l3) * mp.cos(t3), bb[1] + rat(l3) * mp.sin(t3))
        ff = (rat(dx) + rat(l4) * mp.cos(t4), rat(dy) + rat(l4) * mp.sin(t4))
        ee = (bb[0] + rat(ex) * mp.cos(t3) - rat(ey) * mp.sin(t3),
              bb[1] + rat(ex) * mp.sin(t3) + rat(ey) * mp.cos(t3))
        gg = (rat(dx) + rat(gx) * mp.cos(t4) - rat(gy) * mp.sin(t4),
              rat(dy) + rat(gx) * mp.sin(t4) + rat(gy) * mp.cos(t4))
        modes.append([t3, t4, angle(add(ff, cc, -1)), angle(add(gg, ee, -1))])
    return count, modes


def rat(k):
    """A SymPy rational as an mpf."""
    return mp.mpf(k.p) / k.q


def check(name, modes, closure):
    """Every mode closes to 50 digits, and no two are the same pose."""
    for u in modes:
        worst = max(abs(r) for r in closure(u))
        assert worst < mp.mpf(10) ** -35, (name, worst)
    for i in range(len(modes)):
        for j in range(i):
            gap = max(abs(wrap(a - b)) for a, b in zip(modes[i], modes[j]))
            assert gap > mp.mpf(10) ** -6, (name, i, j)


def main():
    deg20 = math.radians(20.0)
    rows = []
    cases = []

    # The worksheet's four-bar at theta2 = 20 deg; the same four-bar
    # whose coupler and rocker are too short to reach D (no assembly).
    for name, ls in [("four_bar", (80, 20, 50, 70)), ("four_bar_too_short", (80, 20, 10, 20))]:
        l1, l2, l3, l4 = map(f64, ls)
        th = f64(deg20)
        modes = four_bar(l1, l2, l3, l4, th)
        check(name, modes, lambda u: [
            l2 * mp.cos(th) + l3 * mp.cos(u[0]) + l4 * mp.cos(u[1]) - l1,
            l2 * mp.sin(th) + l3 * mp.sin(u[0]) + l4 * mp.sin(u[1])])
        cases.append((name, repr(deg20), modes))

    # The offset slider-crank of tests/models/slider_crank.rs at theta2 = 1.
    r, l, ecc = f64(0.05), f64(0.2), f64(0.01)
    th = f64(1.0)
    modes = slider_crank(r, l, ecc, th)
    check("slider_crank", modes, lambda u: [
        r * mp.cos(th) + l * mp.cos(u[0]) - u[1], r * mp.sin(th) + l * mp.sin(u[0]) - ecc])
    cases.append(("slider_crank", repr(1.0), modes))

    # The same, driven by its slider at s = 0.2.
    s = f64(0.2)
    modes = slider_driven(r, l, ecc, s)
    check("slider_driven", modes, lambda u: [
        r * mp.cos(u[0]) + l * mp.cos(u[1]) - s, r * mp.sin(u[0]) + l * mp.sin(u[1]) - ecc])
    cases.append(("slider_driven", repr(0.2), modes))

    # The boom of tests/models/boom.rs at the actuator length 1.
    ax, ay, bl, length = f64(0.4), f64(-0.3), f64(1.0), f64(1.0)
    modes = boom(ax, ay, bl, length)
    check("boom", modes, lambda u: [
        ax + length * mp.cos(u[1]) - bl * mp.cos(u[0]),
        ay + length * mp.sin(u[1]) - bl * mp.sin(u[0])])
    cases.append(("boom", repr(1.0), modes))

    # The five-bar of tests/models/five_bar.rs at theta2 = 1, theta5 = 2.
    fl = list(map(f64, (40, 15, 50, 50, 15)))
    t2, t5 = f64(1.0), f64(2.0)
    modes = five_bar(*fl, t2, t5)
    check("five_bar", modes, lambda u: [
        fl[1] * mp.cos(t2) + fl[2] * mp.cos(u[0]) - fl[0] - fl[4] * mp.cos(t5) - fl[3] * mp.cos(u[1]),
        fl[1] * mp.sin(t2) + fl[2] * mp.sin(u[0]) - fl[4] * mp.sin(t5) - fl[3] * mp.sin(u[1])])
    cases.append(("five_bar", "1.0 2.0", modes))

    # The coupler-body four-bar of the motion-generation test
    # (tests/synthesis/main.rs, `known`) at theta2 = 0.5.
    cp = list(map(f64, (0, 0, 80, 0, 20, 70, -25, -10, 25, -10)))
    th = f64(0.5)
    modes = coupler(*cp, th)

    def coupler_closure(u):
        xa, ya, xd, yd, l2, l4, bx, by, cx, cy = cp
        xp, yp, t3, t4 = u
        return [
            xa + l2 * mp.cos(th) - (xp + bx * mp.cos(t3) - by * mp.sin(t3)),
            ya + l2 * mp.sin(th) - (yp + bx * mp.sin(t3) + by * mp.cos(t3)),
            xd + l4 * mp.cos(t4) - (xp + cx * mp.cos(t3) - cy * mp.sin(t3)),
            yd + l4 * mp.sin(t4) - (yp + cx * mp.sin(t3) + cy * mp.cos(t3))]
    check("coupler", modes, coupler_closure)
    cases.append(("coupler", repr(0.5), modes))

    # The four-bar with a dyad on its coupler (tests/models/six_bar.rs,
    # SIX_BAR) at theta2 = 20 deg.
    sb = [f64(v) for v in (80, 20, 50, 70, 40, math.pi / 6, 60, 50, 20, 90)]
    th = f64(deg20)
    modes = six_bar(*sb, th)

    def six_bar_closure(u):
        l1, l2, l3, l4, ee, beta, l5, l6, gx, gy = sb
        t3, t4, t5, t6 = u
        ex = l2 * mp.cos(th) + ee * mp.cos(t3 + beta)
        ey = l2 * mp.sin(th) + ee * mp.sin(t3 + beta)
        return [
            l2 * mp.cos(th) + l3 * mp.cos(t3) + l4 * mp.cos(t4) - l1,
            l2 * mp.sin(th) + l3 * mp.sin(t3) + l4 * mp.sin(t4),
            ex + l5 * mp.cos(t5) - gx - l6 * mp.cos(t6),
            ey + l5 * mp.sin(t5) - gy - l6 * mp.sin(t6)]
    check("six_bar", modes, six_bar_closure)
    cases.append(("six_bar", repr(deg20), modes))

    # The Watt six-bar of tests/models/watt_six_bar.rs (WATT_SIX_BAR) at
    # theta2 = 20 deg.
    wb = [f64(v) for v in (80, 20, 50, 70, 40, 0.5, 60, 50, 100, 60)]
    modes = watt_six_bar(*wb, th)

    def watt_closure(u):
        l1, l2, l3, l4, le, beta, l5, l6, gx, gy = wb
        t3, t4, t5, t6 = u
        return [
            l2 * mp.cos(th) + l3 * mp.cos(t3) + l4 * mp.cos(t4) - l1,
            l2 * mp.sin(th) + l3 * mp.sin(t3) + l4 * mp.sin(t4),
            l1 + le * mp.cos(t4 + beta) + l5 * mp.cos(t5) + l6 * mp.cos(t6) - gx,
            le * mp.sin(t4 + beta) + l5 * mp.sin(t5) + l6 * mp.sin(t6) - gy]
    check("watt_six_bar", modes, watt_closure)
    cases.append(("watt_six_bar", repr(deg20), modes))

    # The Stephenson III six-bar of tests/models/stephenson_three.rs
    # (STEPHENSON_THREE) at the crank angle atan2(4, 3).
    st = (10, 60, -7, 30, 49, -16, 65, 20, 29, 73, 55)
    count, modes = stephenson_three(st, sp.Rational(3, 5), sp.Rational(4, 5))
    assert count == len(modes)
    c2, s2 = mp.mpf(3) / 5, mp.mpf(4) / 5

    def stephenson_closure(u):
        l2, l3, ex, ey, dx, dy, l4, gx, gy, l5, l6 = map(mp.mpf, st)
        t3, t4, t5, t6 = u
        b = (l2 * c2, l2 * s2)
        return [
            b[0] + l3 * mp.cos(t3) + l5 * mp.cos(t5) - dx - l4 * mp.cos(t4),
            b[1] + l3 * mp.sin(t3) + l5 * mp.sin(t5) - dy - l4 * mp.sin(t4),
            b[0] + ex * mp.cos(t3) - ey * mp.sin(t3) + l6 * mp.cos(t6)
            - (dx + gx * mp.cos(t4) - gy * mp.sin(t4)),
            b[1] + ex * mp.sin(t3) + ey * mp.cos(t3) + l6 * mp.sin(t6)
            - (dy + gx * mp.sin(t4) + gy * mp.cos(t4))]
    check("stephenson_three", modes, stephenson_closure)
    cases.append(("stephenson_three", repr(math.atan2(4.0, 3.0)), modes))

    # The same at the crank angle atan2(5, 12): four.
    count, modes = stephenson_three(st, sp.Rational(12, 13), sp.Rational(5, 13))
    assert count == len(modes)
    c2, s2 = mp.mpf(12) / 13, mp.mpf(5) / 13
    check("stephenson_three_four", modes, stephenson_closure)
    cases.append(("stephenson_three", repr(math.atan2(5.0, 12.0)), modes))

    for name, driver, modes in cases:
        print(f"{name:20} at {driver:24}: {len(modes)} real assemblies")
        if not modes:
            rows.append(f"{name},{driver},0,,")
        modes = [[wrap(x) if is_angle(name, i) else x for i, x in enumerate(u)] for u in modes]
        for k, u in enumerate(sorted(modes)):
            values = ",".join(mp.nstr(x, DIGITS, strip_zeros=False) for x in u)
            rows.append(f"{name},{driver},{len(modes)},{k},{values}")
    with open(OUT, "w") as f:
        f.write("mechanism,driver,modes,mode,u\n")
        f.write("\n".join(rows) + "\n")
    print(f"wrote {OUT}")


# The coordinates that are lengths, not angles.
LENGTHS = {"slider_crank": {1}, "coupler": {0, 1}}


def is_angle(name, i):
    return i not in LENGTHS.get(name, set())


if __name__ == "__main__":
    main()
