"""Turns the C harness's output (analogs at the reference samples) and its
timing into a results row."""
import sys

from common import OMEGA2, errors, row

path, ns = sys.argv[1], float(sys.argv[2])
method = sys.argv[3] if len(sys.argv) > 3 else "CasADi generated C (gcc -O3) in a C harness"
results = {}
with open(path) as f:
    for line in f:
        v = [float(x) for x in line.split(",")]
        results[int(v[0])] = (v[1], v[2], v[3] * OMEGA2, v[4] * OMEGA2, v[5] * OMEGA2 ** 2, v[6] * OMEGA2 ** 2)
print(row(method, ns, errors(results), 1_008_000))
