"""The Python binding's cost over the Rust API: the same mechanism file
swept through 10⁴ steps of its drive range from Python (`Mechanism.sweep`,
NumPy arrays out) and from Rust (examples/sweep_timing.rs: `Loaded::swept`
and `Linkage::sweep`), A/B interleaved in rounds; each side's median per
round, the ratio of the medians. Both sides start from the file's
assembly at its `at`, carried to `from`, so they do the same work; the
mechanism is the worksheet's four-bar without named points (the Rust
side's sweep returns poses, not points).

    cargo build --release --example sweep_timing
    pip install ./linkage-python      # the release wheel, in the environment that runs this
    python benches/peers/python_overhead.py
"""

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import linkage

ROOT = Path(__file__).resolve().parents[2]
STEPS, ROUNDS, REPEATS = 10_000, 7, 5


def without_points(text):
    """The four-bar's file without its named points and its drawing."""
    head, equations_and_rest = text.split("equations = '''", 1)
    equations, rest = equations_and_rest.split("'''", 1)
    closure = equations[equations.index("closure"):]
    body = "u = [theta3, theta4],\nv = [theta2],\n" + closure
    rest = rest.split("[drawing]")[0]
    return head + "equations = '''\n" + body + "'''" + rest


def main():
    text = without_points((ROOT / "mechanisms/four_bar.toml").read_text())
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write(text)
        path = f.name
    bar = linkage.Mechanism.from_file(path)
    assert bar.point_names == []
    binary = ROOT / "target/release/examples/sweep_timing"
    python, rust = [], []
    for _ in range(ROUNDS):
        times = []
        for _ in range(REPEATS):
            start = time.perf_counter()
            sweep = bar.sweep(steps=STEPS)
            times.append(time.perf_counter() - start)
        assert len(sweep) == STEPS + 1
        python.append(statistics.median(times))
        out = subprocess.run([binary, path, str(STEPS), str(REPEATS)], capture_output=True,
                             text=True, check=True).stdout
        rust.append(statistics.median(float(x) for x in out.split()))
    p, r = statistics.median(python), statistics.median(rust)
    print(f"sweep of {STEPS} steps: Python {p * 1e3:.2f} ms ({min(python) * 1e3:.2f}–{max(python) * 1e3:.2f}), "
          f"Rust {r * 1e3:.2f} ms ({min(rust) * 1e3:.2f}–{max(rust) * 1e3:.2f}); "
          f"Python / Rust {p / r:.3f}× (round by round {min(a / b for a, b in zip(python, rust)):.3f}–"
          f"{max(a / b for a, b in zip(python, rust)):.3f}×)")


if __name__ == "__main__":
    sys.exit(main())
