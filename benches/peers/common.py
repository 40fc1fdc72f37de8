"""Shared by the peers: the worksheet's four-bar, the dense grid, the reference and
the error measure, exactly as the Rust benchmark defines them."""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

L1, L2, L3, L4 = 80.0, 20.0, 50.0, 70.0
OMEGA2 = 400.0 * (2 * math.pi) / 60.0
N = 1_008_000
STRIDE = 280
TAU = 2 * math.pi


def theta2(k):
    return (TAU * k) / N


def reference():
    """k -> (theta3, theta4, omega3, omega4, alpha3, alpha4)."""
    rows = {}
    with open(os.path.join(ROOT, "tests", "data", "bench_fourbar.csv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("k"):
                continue
            v = line.strip().split(",")
            rows[int(v[0])] = [float(x) for x in v[2:8]]
    return rows


def start():
    """The worksheet branch at theta2 = 0 (closed form)."""
    ref = reference()
    return ref[0][0], ref[0][1]


def errors(results):
    """results: k -> (theta3, theta4, omega3, omega4, alpha3, alpha4) at the
    reference samples. The worst normwise relative error of positions,
    velocities, accelerations, as in examples/speed_accuracy/workloads.rs."""
    ref = reference()
    keys = sorted(ref)
    missing = [k for k in keys if k not in results]
    assert not missing, f"{len(missing)} reference samples missing"
    out = []
    for kind in range(3):
        worst = 0.0
        for i in range(2):
            col = 2 * kind + i
            diff = 0.0
            size = 0.0
            for k in keys:
                r, o = ref[k][col], results[k][col]
                d = abs(o - r)
                if kind == 0:
                    d = (o - r) % TAU
                    d = min(d, TAU - d)
                diff = max(diff, d)
                size = max(size, abs(r))
            worst = max(worst, diff / size)
        out.append(worst)
    return out


def row(method, ns, errs, samples):
    return f"four-bar,{method},{ns:.2f},{errs[0]:.3e},{errs[1]:.3e},{errs[2]:.3e},{samples}"


def pose20():
    """The converged pose at theta2 = 20 degrees on the worksheet's branch
    (closed form), the warm start of the single-pose job."""
    t = math.radians(20.0)
    bx, by = L2 * math.cos(t), L2 * math.sin(t)
    dx, dy = L1 - bx, -by
    d = math.hypot(dx, dy)
    a = (L3 * L3 - L4 * L4 + d * d) / (2 * d)
    h = math.sqrt(L3 * L3 - a * a)
    ex, ey = dx / d, dy / d
    cx, cy = bx + ex * a - ey * h, by + ey * a + ex * h
    return math.atan2(cy - by, cx - bx), math.atan2(-cy, L1 - cx)
