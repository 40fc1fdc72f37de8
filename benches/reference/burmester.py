#!/usr/bin/env python3
"""Burmester's centre and circle points at 50 digits: the independent
reference of the four- and five-position motion-generation tests
(tests/synthesis/burmester.rs).

    python3 benches/reference/burmester.py

creates its own virtual environment (benches/reference/.venv, mpmath from
PyPI) on first use, as make_reference.py does, and writes

    tests/data/burmester_poses.csv    the poses (f64 values, exactly as the tests read them)
    tests/data/burmester_dyads.csv    every real Burmester dyad of five poses
    tests/data/burmester_pairs.csv    which pairs of them make a four-bar that runs the poses
    tests/data/burmester_curves.csv   four poses: the circle-point and centre-point cubics
    tests/data/burmester_samples.csv  four poses: dyads sampled along them

The problem. A moving plane in the poses (d_i, θ_i), i = 1..n (d_i the
position of its reference point, θ_i its angle, R_i the rotation by θ_i). A
point b of the plane (the circle point, in the plane's frame) is at
w_i = d_i + R_i b in pose i; it is a Burmester point if its n positions lie
on one circle, about the centre point a of the fixed plane:
|w_i − a|² = |w_1 − a|² for i = 2..n. As |R_i b| = |b|, the |b|² and |a|²
cancel, and each condition is bilinear in a and b:

    E_i(a, b) = |d_i|² − |d_1|² + 2 (R_iᵀd_i − R_1ᵀd_1)·b − 2 a·(d_i − d_1) − 2 a·(R_i − R_1) b = 0.

For b fixed they are linear in (a_x, a_y, 1): rows N_i(b), affine in b. For
a fixed, linear in (b_x, b_y, 1): rows M_i(a), affine in a.

Four poses: three conditions; a circle point needs N_2, N_3, N_4 (3 × 3)
singular, so the circle points lie on the cubic det N(b) = 0 and the centre
points on the cubic det M(a) = 0 (Burmester's circle-point and centre-point
curves). They are written as polynomials, and dyads are sampled on them:
b_x on a grid, b_y the real roots of the cubic, a the null vector of N(b).

Five poses: the 4 × 3 matrix N(b) must have rank 2: f = det(N_2, N_3, N_4)
and g = det(N_2, N_3, N_5) vanish (two cubics in b). How all solutions are
found (a resultant, not a search): every common zero of f and g has its
b_x a root of the resultant R(x) = Res_y(f, g) (the 6 × 6 Sylvester
determinant, expanded exactly in the coefficients, 100 digits). Bézout
gives 9 common zeros; both cubics pass through the two circular points at
infinity (the first two columns of N have rank 1 there), so R has degree 7
(checked: its x⁸ and x⁹ coefficients vanish to rounding, the y³
coefficients of f and g do not, so no finite zero escapes to y = ∞). All 7
roots of R are found by mpmath's polyroots (Durand–Kerner, with its error
estimate, checked), each gives exactly one common zero (the other roots of
f(x, ·) are checked not to be zeros of g) polished by Newton on (f, g).
Then each zero is classified: a Burmester point if all four 3 × 3 minors of
N(b) vanish; otherwise spurious (N_2 and N_3 dependent there, so f and g
vanish without the fifth position being on the circle: 3 such points, the
degree of that rank-1 locus). So the Burmester points found are all of
them: 4 (complex or real), as Burmester's theory says. For each real one, a
is N's null vector and the five distances |w_i − a| are checked equal.

The pairs. Two dyads (a1, b1), (a2, b2) make a four-bar A = a1, D = a2,
crank |w − a1|, rocker |w − a2|, coupler |b2 − b1|, driven by the first
dyad's angle θ2. It runs the poses in order if (i) C is on the same side of
the line BD at every pose (one assembly branch), and (ii) the crank can turn
from each pose's θ2 to the next, all one way, without meeting a limit
position (|BD| = l3 + l4 or |l3 − l4|: those crank angles are solved in
closed form) — checked both ways round. Written as crank,rocker indices.

Poses: the coupler of a four-bar at five crank angles (the closed form,
rounded to f64: those f64 values are the poses everyone is given, the
four-bar's own dyads are then Burmester dyads only to rounding), and a set
of general poses (not a four-bar's). Four poses: the first four of each.
"""
import os
import sys
from functools import lru_cache

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_venv import ROOT, ensure_venv  # noqa: E402

ensure_venv(__file__)

import mpmath as mp  # noqa: E402

mp.mp.dps = 50
DIGITS = 40
SCRIPT = "benches/reference/burmester.py"


def fmt(x):
    return mp.nstr(x, DIGITS, min_fixed=-5, max_fixed=5, strip_zeros=False)


def write(name, header, rows):
    path = os.path.join(ROOT, "tests", "data", name)
    with open(path, "w") as f:
        for line in header:
            f.write("# " + line + "\n")
        for row in rows:
            f.write(",".join(row) + "\n")
    print("wrote", os.path.relpath(path, ROOT), len(rows) - 1, "rows")


# Polynomials in two variables: {(i, j): coefficient of x^i y^j}.

def padd(*ps):
    r = {}
    for p in ps:
        for k, a in p.items():
            r[k] = r.get(k, 0) + a
    return r


def pmul(p, q):
    r = {}
    for (i, j), a in p.items():
        for (k, l), b in q.items():
            r[(i + k, j + l)] = r.get((i + k, j + l), 0) + a * b
    return r


def pscale(p, s):
    return {k: a * s for k, a in p.items()}


def peval(p, x, y):
    return mp.fsum(a * x ** i * y ** j for (i, j), a in p.items())


def pdx(p):
    return {(i - 1, j): a * i for (i, j), a in p.items() if i > 0}


def pdy(p):
    return {(i, j - 1): a * j for (i, j), a in p.items() if j > 0}


def affine(c, cx, cy):
    """c + cx x + cy y"""
    return {(0, 0): mp.mpf(c), (1, 0): mp.mpf(cx), (0, 1): mp.mpf(cy)}


def det3(m):
    t = lambda a, b, c: pmul(pmul(a, b), c)
    return padd(
        t(m[0][0], m[1][1], m[2][2]), t(m[0][1], m[1][2], m[2][0]), t(m[0][2], m[1][0], m[2][1]),
        pscale(t(m[0][2], m[1][1], m[2][0]), -1), pscale(t(m[0][0], m[1][2], m[2][1]), -1),
        pscale(t(m[0][1], m[1][0], m[2][2]), -1))


def rot(t):
    c, s = mp.cos(t), mp.sin(t)
    return ((c, -s), (s, c))


def world(pose, b):
    c, s = mp.cos(pose[2]), mp.sin(pose[2])
    return (pose[0] + c * b[0] - s * b[1], pose[1] + s * b[0] + c * b[1])


def rows_n(poses, origin=(0, 0), scale=1):
    """N_i(b), i = 2..n: the coefficients of (a_x, a_y, 1) as affine
    polynomials in B, b = origin + scale·B."""
    (x1, y1, t1) = poses[0]
    R1 = rot(t1)
    out = []
    for (xi, yi, ti) in poses[1:]:
        Ri = rot(ti)
        D = [[Ri[r][c] - R1[r][c] for c in range(2)] for r in range(2)]
        dd = (xi - x1, yi - y1)
        g = [Ri[0][c] * xi + Ri[1][c] * yi - (R1[0][c] * x1 + R1[1][c] * y1) for c in range(2)]
        const = xi ** 2 + yi ** 2 - x1 ** 2 - y1 ** 2
        row = []
        for r in range(2):
            # −2((R_i − R_1) b + d_i − d_1)_r
            c0 = -2 * (dd[r] + D[r][0] * origin[0] + D[r][1] * origin[1])
            row.append(affine(c0, -2 * D[r][0] * scale, -2 * D[r][1] * scale))
        c0 = const + 2 * (g[0] * origin[0] + g[1] * origin[1])
        row.append(affine(c0, 2 * g[0] * scale, 2 * g[1] * scale))
        out.append(row)
    return out


def rows_m(poses, origin=(0, 0), scale=1):
    """M_i(a), i = 2..n: the coefficients of (b_x, b_y, 1) as affine
    polynomials in A, a = origin + scale·A."""
    (x1, y1, t1) = poses[0]
    R1 = rot(t1)
    out = []
    for (xi, yi, ti) in poses[1:]:
        Ri = rot(ti)
        D = [[Ri[r][c] - R1[r][c] for c in range(2)] for r in range(2)]
        dd = (xi - x1, yi - y1)
        g = [Ri[0][c] * xi + Ri[1][c] * yi - (R1[0][c] * x1 + R1[1][c] * y1) for c in range(2)]
        const = xi ** 2 + yi ** 2 - x1 ** 2 - y1 ** 2
        row = []
        for c in range(2):
            # 2 g_c − 2 ((R_i − R_1)ᵀ a)_c
            c0 = 2 * g[c] - 2 * (D[0][c] * origin[0] + D[1][c] * origin[1])
            row.append(affine(c0, -2 * D[0][c] * scale, -2 * D[1][c] * scale))
        c0 = const - 2 * (dd[0] * origin[0] + dd[1] * origin[1])
        row.append(affine(c0, -2 * dd[0] * scale, -2 * dd[1] * scale))
        out.append(row)
    return out


def at(rows, x, y):
    return [[peval(p, x, y) for p in r] for r in rows]


def null3(rows):
    """(a_x, a_y) from rows of a rank-2 n × 3 matrix: the cross product of
    the two rows that are farthest from parallel."""
    best = None
    for i in range(len(rows)):
        for j in range(i + 1, len(rows)):
            u, v = rows[i], rows[j]
            c = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            if best is None or abs(c[2]) > abs(best[2]):
                best = c
    return (best[0] / best[2], best[1] / best[2])


# Univariate polynomials in x: lists of coefficients, lowest power first.

def uadd(a, b):
    r = [mp.mpf(0)] * max(len(a), len(b))
    for i, x in enumerate(a):
        r[i] += x
    for i, x in enumerate(b):
        r[i] += x
    return r


def umul(a, b):
    r = [mp.mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def in_y(p):
    """p as a polynomial in y whose coefficients are polynomials in x."""
    out = [[mp.mpf(0)] * 4 for _ in range(4)]
    for (i, j), a in p.items():
        out[j][i] += a
    return out


def resultant_y(f, g):
    """Res_y(f, g) of two cubics: the Sylvester determinant, by Laplace
    expansion with polynomial entries (exact in the coefficients)."""
    fy, gy = in_y(f), in_y(g)
    zero = [mp.mpf(0)]
    S = []
    for P in (fy, gy):
        for s in range(3):
            row = [zero] * 6
            for k in range(4):
                row[s + 3 - k] = P[k]
            S.append(row)

    @lru_cache(None)
    def minor(r, cols):
        if r == 6:
            return (mp.mpf(1),)
        total = [mp.mpf(0)]
        for n, c in enumerate(cols):
            if all(v == 0 for v in S[r][c]):
                continue
            term = umul(S[r][c], list(minor(r + 1, tuple(x for x in cols if x != c))))
            if n % 2:
                term = [-t for t in term]
            total = uadd(total, term)
        return tuple(total)

    return list(minor(0, tuple(range(6)))), fy, gy


def burmester_points(poses):
    """All Burmester points of five poses: (real dyads, count of complex
    ones, certificate notes)."""
    assert len(poses) == 5
    with mp.workdps(100):
        # Work about the poses' centroid, scaled, for the conditioning.
        ox = mp.fsum(p[0] for p in poses) / 5
        oy = mp.fsum(p[1] for p in poses) / 5
        s = max(max(abs(p[0] - ox), abs(p[1] - oy)) for p in poses)
        N = rows_n(poses, (ox, oy), s)
        f = det3([N[0], N[1], N[2]])
        g = det3([N[0], N[1], N[3]])
        norm = max(abs(c) for c in f.values())
        f = pscale(f, 1 / norm)
        g = pscale(g, 1 / max(abs(c) for c in g.values()))
        res, fy, gy = resultant_y(f, g)
        big = max(abs(c) for c in res)
        res = [c / big for c in res]
        assert all(abs(c) < mp.mpf(10) ** -60 for c in res[8:]), "the resultant's x^8, x^9 terms"
        assert abs(res[7]) > mp.mpf(10) ** -30, "degree 7"
        assert abs(fy[3][0]) > mp.mpf(10) ** -30 and abs(gy[3][0]) > mp.mpf(10) ** -30, "y^3 terms"
        roots, err = mp.polyroots(res[:8][::-1], maxsteps=800, extraprec=400, error=True)
        assert err < mp.mpf(10) ** -60, err
        assert len(roots) == 7
        genuine, spurious = [], 0
        for x in roots:
            fc = [mp.fsum(fy[k][i] * x ** i for i in range(4)) for k in range(4)]
            ys = sorted(mp.polyroots(fc[::-1], maxsteps=400, extraprec=400),
                        key=lambda y: abs(peval(g, x, y)))
            y = ys[0]
            assert abs(peval(g, x, ys[1])) > mp.mpf(10) ** -20, "two common zeros over one x"
            for _ in range(8):  # Newton on (f, g), complex
                F = mp.matrix([peval(f, x, y), peval(g, x, y)])
                J = mp.matrix([[peval(pdx(f), x, y), peval(pdy(f), x, y)],
                               [peval(pdx(g), x, y), peval(pdy(g), x, y)]])
                d = mp.lu_solve(J, F)
                x, y = x - d[0], y - d[1]
                if abs(d[0]) + abs(d[1]) < mp.mpf(10) ** -80:
                    break
            rows = at(N, x, y)
            minors = [mp.det(mp.matrix([rows[i] for i in idx]))
                      for idx in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))]
            scale_rows = max(abs(v) for r in rows for v in r) ** 3
            if max(abs(m) for m in minors) < mp.mpf(10) ** -50 * scale_rows:
                genuine.append((x, y))
            else:
                spurious += 1
        assert len(genuine) == 4 and spurious == 3, (len(genuine), spurious)
        real, complex_ = [], 0
        for x, y in genuine:
            if abs(mp.im(x)) > mp.mpf(10) ** -40 or abs(mp.im(y)) > mp.mpf(10) ** -40:
                complex_ += 1
                continue
            X, Y = mp.re(x), mp.re(y)
            b = (ox + s * X, oy + s * Y)
            a = null3(at(rows_n(poses), b[0], b[1]))
            dist = [mp.sqrt((w[0] - a[0]) ** 2 + (w[1] - a[1]) ** 2) for w in (world(p, b) for p in poses)]
            spread = max(dist) - min(dist)
            assert spread < mp.mpf(10) ** -45 * max(dist), spread
            real.append((a, b, dist[0], spread))
        return real, complex_


def fourbar_pose(A, D, l2, l4, bpt, cpt, theta2, sigma=1):
    """The coupler's pose (x_p, y_p, θ3) of the four-bar with ground pivots
    A, D, crank l2 (at θ2), rocker l4, the coupler's pivots at bpt and cpt
    in its frame (origin the coupler point P), branch σ (C left of B→D for
    σ = +1)."""
    B = (A[0] + l2 * mp.cos(theta2), A[1] + l2 * mp.sin(theta2))
    l3 = mp.sqrt((cpt[0] - bpt[0]) ** 2 + (cpt[1] - bpt[1]) ** 2)
    d = (D[0] - B[0], D[1] - B[1])
    L = mp.sqrt(d[0] ** 2 + d[1] ** 2)
    along = (l3 ** 2 - l4 ** 2 + L ** 2) / (2 * L)
    h = mp.sqrt(l3 ** 2 - along ** 2)
    e = (d[0] / L, d[1] / L)
    C = (B[0] + along * e[0] - sigma * h * e[1], B[1] + along * e[1] + sigma * h * e[0])
    t3 = mp.atan2(C[1] - B[1], C[0] - B[0]) - mp.atan2(cpt[1] - bpt[1], cpt[0] - bpt[0])
    R = rot(t3)
    P = (B[0] - (R[0][0] * bpt[0] + R[0][1] * bpt[1]), B[1] - (R[1][0] * bpt[0] + R[1][1] * bpt[1]))
    return P[0], P[1], t3


def runs(poses, crank, rocker):
    """Whether the four-bar of the dyads `crank` (driven) and `rocker` runs
    the poses in order: (directions that work, reason if none)."""
    (a1, b1, r1), (a2, b2, r2) = crank, rocker
    l3 = mp.sqrt((b2[0] - b1[0]) ** 2 + (b2[1] - b1[1]) ** 2)
    theta, side = [], []
    for p in poses:
        B, C = world(p, b1), world(p, b2)
        theta.append(mp.atan2(B[1] - a1[1], B[0] - a1[0]))
        side.append(mp.sign((C[0] - B[0]) * (a2[1] - B[1]) - (C[1] - B[1]) * (a2[0] - B[0])))
    if len(set(side)) > 1:
        return "", "branch"
    g = mp.sqrt((a1[0] - a2[0]) ** 2 + (a1[1] - a2[1]) ** 2)
    phi = mp.atan2(a1[1] - a2[1], a1[0] - a2[0])
    limits = []
    for L in (l3 + r2, abs(l3 - r2)):
        c = (L ** 2 - r1 ** 2 - g ** 2) / (2 * r1 * g)
        if abs(c) <= 1:
            limits += [phi + mp.acos(c), phi - mp.acos(c)]
    ways = ""
    for sign, name in ((1, "+"), (-1, "-")):
        gaps = [(sign * (theta[i + 1] - theta[i])) % (2 * mp.pi) for i in range(len(theta) - 1)]
        total = mp.fsum(gaps)
        if limits and (total >= 2 * mp.pi or any((sign * (t - theta[0])) % (2 * mp.pi) <= total for t in limits)):
            continue
        ways += name
    return ways, "" if ways else "limit position"


def links(crank, rocker):
    (a1, b1, r1), (a2, b2, r2) = crank, rocker
    l3 = mp.sqrt((b2[0] - b1[0]) ** 2 + (b2[1] - b1[1]) ** 2)
    g = mp.sqrt((a1[0] - a2[0]) ** 2 + (a1[1] - a2[1]) ** 2)
    return g, r1, l3, r2


def as_f64(pose):
    return tuple(mp.mpf(float(v)) for v in pose)


# The four-bar of the coupler set: A = (0, 0), D = (80, 0), crank 20,
# rocker 75, the coupler's pivots at (-20, 25) and (35, 30) in the frame of
# its point P, branch +1, at five crank angles.
COUPLER = dict(A=(0, 0), D=(80, 0), l2=20, l4=75, b=(-20, 25), c=(35, 30))
CRANK = [4.3, 4.9, 5.5, 6.1, 6.7]
# General poses: (x, y, angle in rad) of no particular mechanism.
GENERAL = [(0.0, 0.0, 0.0), (10.0, 10.0, 0.29), (23.0, 17.0, 0.55), (35.0, 21.0, 0.77), (47.0, 24.0, 1.2)]


def main():
    sets = {}
    m = COUPLER
    sets["coupler"] = ([as_f64(fourbar_pose(m["A"], m["D"], m["l2"], m["l4"], m["b"], m["c"], mp.mpf(t)))
                        for t in CRANK], CRANK)
    sets["general"] = ([as_f64(p) for p in GENERAL], [None] * 5)

    rows = [["set", "pose", "theta2", "x", "y", "angle"]]
    for name, (poses, thetas) in sets.items():
        for i, (p, t) in enumerate(zip(poses, thetas)):
            rows.append([name, str(i), repr(t) if t is not None else "-"] + [repr(float(v)) for v in p])
    write("burmester_poses.csv", [
        "Poses (x, y of the moving plane's reference point, its angle in rad) for Burmester motion generation,",
        "as f64 (repr: these exact values are the poses of every computation). 'coupler': the coupler of the four-bar",
        "A = (0, 0), D = (80, 0), crank 20, rocker 75, the coupler's pivots at (-20, 25) and (35, 30) in the frame of",
        "its point P (the reference point), branch +1, at the crank angles theta2 (the closed form at 50 digits,",
        "rounded); 'general': poses of no particular mechanism. Four poses: the first four of a set.",
        f"Written by {SCRIPT} (mpmath, 50 digits).",
    ], rows)

    dyad_rows = [["set", "dyad", "ax", "ay", "bx", "by", "r", "spread"]]
    pair_rows = [["set", "crank", "rocker", "runs", "directions", "reason", "ground", "crank_length", "coupler", "rocker_length"]]
    notes = []
    for name, (poses, _) in sets.items():
        real, complex_ = burmester_points(poses)
        notes.append(f"{name}: {len(real)} real, {complex_} complex")
        # A stable order: by the circle point's x.
        real.sort(key=lambda d: d[1][0])
        for k, (a, b, r, spread) in enumerate(real):
            dyad_rows.append([name, str(k)] + [fmt(v) for v in (a[0], a[1], b[0], b[1], r)] + [mp.nstr(spread, 3)])
        dyads = [(a, b, r) for a, b, r, _ in real]
        for i, crank in enumerate(dyads):
            for j, rocker in enumerate(dyads):
                if i == j:
                    continue
                ways, why = runs(poses, crank, rocker)
                pair_rows.append([name, str(i), str(j), "1" if ways else "0", ways or "-", why or "-"]
                                 + [mp.nstr(v, 12) for v in links(crank, rocker)])
    write("burmester_dyads.csv", [
        "Every real Burmester dyad of the five poses of each set of burmester_poses.csv: centre point a (fixed plane),",
        "circle point b (moving plane's frame), radius r; spread = max - min of the five distances |w_i - a| (the check).",
        "All Burmester points found by a resultant (degree 7 in b_x: 4 Burmester points + 3 spurious zeros, classified),",
        "see the script's docstring for why none is missed. " + "; ".join(notes) + ".",
        f"Written by {SCRIPT} (mpmath, 50 digits, 100 for the resultant; 40 kept).",
    ], dyad_rows)
    write("burmester_pairs.csv", [
        "Ordered pairs of the dyads of burmester_dyads.csv as a four-bar: crank (driven, A = its centre) and rocker.",
        "runs = 1 if it runs the five poses in order on one branch, its crank turning one way ('directions': + or - or",
        "both, counterclockwise +) without a limit position; else the reason: 'branch' (the poses are on two assembly",
        "branches) or 'limit position' (the crank cannot turn from pose to pose either way). Link lengths to 12 digits.",
        f"Written by {SCRIPT} (mpmath; limit positions in closed form).",
    ], pair_rows)

    # Four poses: the curves, about the poses' centroid, scaled.
    curve_rows = [["set", "curve", "origin_x", "origin_y", "scale"]
                  + [f"c{i}{j}" for i, j in EXPONENTS]]
    sample_rows = [["set", "bx", "by", "ax", "ay", "r"]]
    for name, (poses, _) in sets.items():
        four = poses[:4]
        ox = mp.fsum(p[0] for p in four) / 4
        oy = mp.fsum(p[1] for p in four) / 4
        s = max(max(abs(p[0] - ox), abs(p[1] - oy)) for p in four)
        for curve, rows_of in (("circle", rows_n), ("centre", rows_m)):
            cubic = det3(rows_of(four, (ox, oy), s))
            big = max(abs(c) for c in cubic.values())
            curve_rows.append([name, curve, fmt(ox), fmt(oy), fmt(s)]
                              + [fmt(cubic.get(e, 0) / big) for e in EXPONENTS])
        # Dyads along the circle-point curve: b_x = -40, -35, ..., 80.
        N = rows_n(four)
        cubic = det3(N)
        for k in range(25):
            bx = mp.mpf(-40 + 5 * k)
            coeffs = [mp.fsum(a * bx ** i for (i, j), a in cubic.items() if j == p) for p in range(4)]
            for by in mp.polyroots(coeffs[::-1], maxsteps=400, extraprec=200):
                if abs(mp.im(by)) > mp.mpf(10) ** -30:
                    continue
                by = mp.re(by)
                a = null3(at(N, bx, by))
                dist = [mp.sqrt((w[0] - a[0]) ** 2 + (w[1] - a[1]) ** 2) for w in (world(p, (bx, by)) for p in four)]
                assert max(dist) - min(dist) < mp.mpf(10) ** -40 * max(dist)
                sample_rows.append([name, str(int(bx)), fmt(by), fmt(a[0]), fmt(a[1]), fmt(dist[0])])
    write("burmester_curves.csv", [
        "Four poses (the first four of each set of burmester_poses.csv): Burmester's circle-point curve (circle points",
        "b in the moving plane's frame) and centre-point curve (centre points a in the fixed plane), each the cubic",
        "sum c_ij X^i Y^j = 0 in X = (x - origin_x)/scale, Y = (y - origin_y)/scale, normalised to max |c_ij| = 1:",
        "det of the three conditions E_2, E_3, E_4 as linear in a (circle) or in b (centre).",
        f"Written by {SCRIPT} (mpmath, 50 digits; 40 kept).",
    ], curve_rows)
    write("burmester_samples.csv", [
        "Four poses: Burmester dyads sampled along the circle-point curve, b_x = -40, -35, ..., 80 (exact), b_y every real",
        "root of the cubic there, a the centre (null vector of the conditions), r = |w_1 - a|; the four distances checked",
        f"equal to 1e-40. Written by {SCRIPT} (mpmath, 50 digits; 40 kept).",
    ], sample_rows)


EXPONENTS = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3)]


if __name__ == "__main__":
    main()
