"""A sharded synthesis on Dask's distributed engine, one worker against
two (local clusters on this machine, loopback only, one thread and one
rayon thread per worker process): the wall time of the same search, A/B
interleaved, and the cost of one start, from which docs/distributed.md
sizes a search of 10⁸ designs.

The search: the 9-point path task of docs/performance.md (the worksheet's
coupler curve, every dimension of the four-bar free, precision points),
128 starts in 8 shards of 16.

    target/py-venv/bin/python benches/peers/shards_scaling.py   # about a minute
"""

import os
import platform
import statistics
import sys
import time
from importlib.metadata import version
from pathlib import Path

import distributed

from linkage import shards

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "linkage-python" / "tests"))
from test_synthesis import COUPLER_FOUR_BAR, WORKSHEET, path_bounds, path_targets  # noqa: E402

ROUNDS = 3
STARTS, PER_SHARD = 128, 16


def main():
    targets = path_targets(9)
    spec = {"equations": COUPLER_FOUR_BAR, "parameters": WORKSHEET, "name": "CouplerFourBar"}
    task = {"path": "P", "targets": targets.tolist(), "free": path_bounds(targets),
            "precision_points": True, "at": 0.0}
    pieces = shards.split(spec, task, starts=STARTS, per_shard=PER_SHARD, random_state=1)
    times = {1: [], 2: []}
    rows = None
    for _ in range(ROUNDS):
        for workers in (1, 2):
            with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                          host="127.0.0.1", dashboard_address=None,
                                          env={"RAYON_NUM_THREADS": "1"}) as cluster:
                with distributed.Client(cluster) as client:
                    # Each worker imports the package and makes the mechanism once.
                    client.gather(client.map(shards.run_shard, [
                        shards.Shard(spec, task, 99, k, 1) for k in range(workers)]))
                    start = time.perf_counter()
                    table = shards.search(pieces, client)
                    times[workers].append(time.perf_counter() - start)
            assert rows is None or table.equals(rows), "the same rows on one worker and two"
            rows = table
    one, two = statistics.median(times[1]), statistics.median(times[2])
    print(f"# Sharded synthesis on Dask {version('distributed')}, {time.strftime('%Y-%m-%d', time.gmtime())}: "
          f"{platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"benches/peers/shards_scaling.py\n")
    print(f"{STARTS} starts in {len(pieces)} shards of {PER_SHARD}; {rows.num_rows} certified designs "
          f"(the same rows in every run); {ROUNDS} rounds, one worker and two alternating.\n")
    print("| workers | wall time, median (min–max) | starts / s | speed-up |")
    print("|---:|---:|---:|---:|")
    for workers, median in [(1, one), (2, two)]:
        spread = f"{min(times[workers]):.2f}–{max(times[workers]):.2f} s"
        print(f"| {workers} | {median:.2f} s ({spread}) | {STARTS / median:.0f} | {one / median:.2f}× |")
    print(f"\nOne start on one core: {one / STARTS * 1e3:.1f} ms; "
          f"{rows.num_rows / STARTS:.3f} certified designs per start.")


if __name__ == "__main__":
    main()
