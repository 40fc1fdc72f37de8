"""Summarises the runs of benches/speed_tables.sh into docs/performance.md's speed
tables: the median of the runs and their spread (min–max), with the commit
and the date.

    python3 benches/speed_tables.py benches/results/runs COMMIT
"""
import csv
import datetime
import glob
import os
import statistics
import sys

RUNS, COMMIT = sys.argv[1], sys.argv[2]
DATE = datetime.date.today().isoformat()
DENSE = 1_008_000 // 10 + 1  # poses of the criterion dense sweep

# What each row does per sample, in plain words.
WHAT = {
    "generated (sweep API)": "`sweep_each`: lagged predictor, one fused evaluation (Ψ, Ψ_u⁻¹, u′, u″) with carried sines and cosines, chord correction, every check",
    "num-dual Jacobians (sweep API)": "`sweep_each` with Ψ_u, Ψ_v, γ by dual numbers",
    "finite differences (sweep API)": "`sweep_each` with Ψ_u, Ψ_v, γ by central differences",
    "closed form per sample (hand-written)": "one `sin_cos`, circle intersection, two `atan2`, ω and α from the links' directions",
    "closed form, sweep with trig carried (hand-written)": "the same with sines, cosines and angles carried from anchors: no transcendental per sample",
    "CasADi generated C as its users write it (sin/cos per sample)": "predictor, one Newton correction, analogs; `sin` and `cos` per sample",
    "CasADi generated C, sin/cos carried (its own predictor)": "the same kernel on carried sines and cosines",
    "CasADi generated C, sin/cos carried + linkage's lagged predictor and chord step": "linkage's sweep algorithm in a bare C loop, CasADi's kernel, no checks",
    "closed form in C, swept: sin/cos carried, sqrt, 2 reciprocals, angles followed by series": "the four-bar's closed form tuned by hand: L² from cos θ2, `sqrt`, one reciprocal of L and one of sin(θ3 − θ4), θ3 and θ4 followed by a division-free series, 16 samples side by side",
    "CasADi SX mapaccum in its VM": "the step function iterated in CasADi's virtual machine",
    "SymPy lambdify + NumPy Newton in a Python loop": "lambdified Ψ, Ψ_u, γ; Newton in Python",
}


def read(pattern):
    rows = []
    for path in sorted(glob.glob(os.path.join(RUNS, pattern))):
        with open(path) as f:
            rows.append([r for r in csv.reader(l for l in f if not l.startswith("#"))][1:])
    return rows


def spread(values):
    values = sorted(values)
    m = statistics.median(values)
    return m, f"{m:.1f} ({values[0]:.1f}–{values[-1]:.1f})"


def by_key(runs, key, value):
    out = {}
    for rows in runs:
        for r in rows:
            out.setdefault(key(r), []).append(value(r))
    return out


def speed_accuracy():
    ours = read("ours.*.csv")
    peers = read("peers.*.csv")
    # workload, method, ns, errors..., samples; a method may hold commas
    def parse(r):
        return r[0], ",".join(r[1:-5]), float(r[-5]), r[-4:-1]
    rows = {}
    for runs in (ours, peers):
        for run in runs:
            for r in run:
                w, m, ns, errs = parse(r)
                rows.setdefault((w, m), [[], errs])[0].append(ns)
    floor = statistics.median(rows[("four-bar", "closed form, sweep with trig carried (hand-written)")][0])
    print(f"Speed against accuracy, dense revolution (1 008 000 samples), ns per sample: median of {len(ours)} runs (min–max); commit {COMMIT}, {DATE}.\n")
    print("| workload | method | per sample | ns / sample | vs best closed form | positions | velocities | accelerations |")
    print("|---|---|---|---:|---:|---:|---:|---:|")
    for (w, m), (times, errs) in rows.items():
        med, text = spread(times)
        ratio = f"{med / floor:.2f}×" if w == "four-bar" else "—"
        print(f"| {w} | {m} | {WHAT.get(m, '')} | {text} | {ratio} | {float(errs[0]):.1e} | {float(errs[1]):.1e} | {float(errs[2]):.1e} |")


def single_pose():
    kernels = read("kernels.*.csv")
    casadi = read("casadi_pose.*.csv")
    k = by_key(kernels, lambda r: (r[0], r[1]), lambda r: float(r[2]))
    c = by_key(casadi, lambda r: r[0], lambda r: float(r[1]))
    print(f"\nOne pose (`analyze`: Newton, velocities, accelerations, every check), ns per call: median of {len(kernels)} runs (min–max); commit {COMMIT}, {DATE}.\n")
    print("| mechanism | job | linkage `analyze` | CasADi's generated C (no checks) | linkage / CasADi |")
    print("|---|---|---:|---:|---:|")
    for mech in ("four-bar", "slider-crank", "six-bar"):
        for job in ("warm", "cold"):
            times = k.get((mech, f"analyze {job}"))
            if not times:
                continue
            med, text = spread(times)
            if mech == "four-bar":
                cmed, ctext = spread(c[job])
                print(f"| {mech} | {job} | {text} | {ctext} | {med / cmed:.2f} |")
            else:
                print(f"| {mech} | {job} | {text} | — | — |")
    print(f"\nThe sweep API on the dense grid (criterion, {DENSE} poses), ns per pose:\n")
    print("| mechanism | ns / pose |")
    print("|---|---:|")
    for mech in ("four-bar", "slider-crank", "six-bar"):
        times = k.get((mech, "sweep dense"))
        if times:
            print(f"| {mech} | {spread([t / DENSE for t in times])[1]} |")


def batch():
    runs = read("batch.*.csv")
    b = by_key(runs, lambda r: r[0], lambda r: float(r[2]))
    print(f"\nBatch (2000 four-bar designs × 3601 poses), ns per pose: median of {len(runs)} runs (min–max); commit {COMMIT}, {DATE}.\n")
    print("| threads | ns / pose |")
    print("|---:|---:|")
    for threads, times in b.items():
        print(f"| {threads} | {spread(times)[1]} |")


speed_accuracy()
single_pose()
batch()
