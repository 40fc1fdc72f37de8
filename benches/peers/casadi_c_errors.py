"""Turns a C harness's output (analogs at the reference samples) and its
timing into a results row; with --max, fails if a worst relative error is
above its bound.

    python casadi_c_errors.py OUT.csv NS [METHOD] [--max POS,VEL,ACC]
"""
import argparse
import sys

from common import OMEGA2, errors, row

parser = argparse.ArgumentParser()
parser.add_argument("path")
parser.add_argument("ns", type=float)
parser.add_argument("method", nargs="?", default="CasADi generated C (gcc -O3) in a C harness")
parser.add_argument("--max", help="bounds of the worst relative errors: positions,velocities,accelerations")
args = parser.parse_args()
results = {}
with open(args.path) as f:
    for line in f:
        v = [float(x) for x in line.split(",")]
        results[int(v[0])] = (v[1], v[2], v[3] * OMEGA2, v[4] * OMEGA2, v[5] * OMEGA2 ** 2, v[6] * OMEGA2 ** 2)
errs = errors(results)
print(row(args.method, args.ns, errs, 1_008_000))
if args.max:
    bounds = [float(x) for x in args.max.split(",")]
    over = [(kind, e, b) for kind, e, b in zip(("positions", "velocities", "accelerations"), errs, bounds) if not e <= b]
    for kind, e, b in over:
        print(f"{args.method}: worst relative error of the {kind} {e:.3e} > {b:.1e}", file=sys.stderr)
    if over:
        sys.exit(1)
