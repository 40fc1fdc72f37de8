#!/usr/bin/env python3
"""The DXF that `linkage dxf` writes, read by an independent reader.

For every topology file of mechanisms/joints/, the pose at `at` and the cut
sheet are written by the command-line tool and read back with ezdxf (a
well-kept DXF library for Python, from the Python package registry):

- ezdxf's audit() finds no error in either;
- the header's $INSUNITS is the file's length unit;
- the pose has a layer per link, and its holes' centres are the joints'
  positions that `linkage analyze -f json` prints, to 1e-9;
- the cut sheet has every moving link, labelled, its holes as far apart
  as in the pose (a link is laid flat, not reshaped), to 1e-9;
- a pin in a slot of a moving link has its slot cut in that link, in both.

    python3 -m venv target/dxf-venv && target/dxf-venv/bin/pip install ezdxf
    target/dxf-venv/bin/python tests/dxf/check_dxf.py target/debug/linkage

Exits 1, saying why, on the first failure.
"""

import itertools
import json
import math
import pathlib
import subprocess
import sys
import tempfile
import tomllib

import ezdxf

ROOT = pathlib.Path(__file__).resolve().parents[2]
UNITS = {"in": 1, "ft": 2, "mm": 4, "cm": 5, "m": 6}


def fail(why):
    print(f"check_dxf: {why}", file=sys.stderr)
    sys.exit(1)


def run(tool, *args):
    out = subprocess.run([tool, *args], capture_output=True, text=True)
    if out.returncode != 0:
        fail(f"linkage {' '.join(args)}: {out.stderr}")
    return out.stdout


def holes(doc):
    """The circles of each layer: {layer: [(x, y, r)]}."""
    found = {}
    for e in doc.modelspace().query("CIRCLE"):
        c = e.dxf.center
        found.setdefault(e.dxf.layer, []).append((c.x, c.y, e.dxf.radius))
    return found


def check(tool, path, work):
    topology = tomllib.loads(path.read_text())
    unit = topology.get("length_unit", "m")
    links = topology["links"]
    ground = topology.get("ground", "ground")
    pose_path, cut_path = work / f"{path.stem}.dxf", work / f"{path.stem}_cut.dxf"
    run(tool, "dxf", str(path), "-o", str(pose_path))
    run(tool, "dxf", str(path), "--cut-sheet", "-o", str(cut_path))
    for dxf in (pose_path, cut_path):
        doc = ezdxf.readfile(dxf)
        auditor = doc.audit()
        if auditor.has_errors:
            fail(f"{dxf.name}: ezdxf's audit finds {len(auditor.errors)} error(s): {auditor.errors[:3]}")
        if doc.header.get("$INSUNITS") != UNITS[unit]:
            fail(f"{dxf.name}: $INSUNITS {doc.header.get('$INSUNITS')}, the file's unit is {unit}")
    # The pose: a layer per link, holes at the joints.
    analysis = json.loads(run(tool, "analyze", str(path), "-f", "json"))
    positions = {}
    for name, row in zip(analysis["row_names"], analysis["rows"]):
        if name.endswith("]") and "." in name:
            joint, axis = name.split(" ")[0].rsplit(".", 1)
            positions.setdefault(joint, {})[axis] = row[0]
    for name, value in topology["joints"].items():
        at = value if isinstance(value, list) else value["at"]
        if name not in positions and all(isinstance(v, (int, float)) for v in at):
            positions[name] = {"x": float(at[0]), "y": float(at[1])}
    pose = ezdxf.readfile(pose_path)
    layers = {layer.dxf.name for layer in pose.layers}
    missing = set(links) - layers
    if missing:
        fail(f"{pose_path.name}: no layer for {sorted(missing)}")
    pose_holes = holes(pose)
    for link, joints in links.items():
        for (x, y, _) in pose_holes.get(link, []):
            near = min(
                (math.hypot(x - positions[j]["x"], y - positions[j]["y"]), j)
                for j in joints
                if j in positions
            )
            if near[0] > 1e-9:
                fail(f"{pose_path.name}: a hole of {link} at ({x}, {y}) is {near[0]:.2e} from its nearest joint {near[1]}")
    # The cut sheet: each moving link, its holes as far apart as posed.
    cut = ezdxf.readfile(cut_path)
    cut_holes = holes(cut)
    labels = {e.dxf.text for e in cut.modelspace().query("TEXT")}
    for link in links:
        if link == ground:
            continue
        if link not in labels:
            fail(f"{cut_path.name}: {link} is not labelled")
        posed, flat = pose_holes.get(link, []), cut_holes.get(link, [])
        if len(posed) != len(flat):
            fail(f"{cut_path.name}: {link} has {len(flat)} holes, {len(posed)} in the pose")
        distances = lambda hs: sorted(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in itertools.combinations(hs, 2))
        for d_pose, d_flat in zip(distances(posed), distances(flat)):
            if abs(d_pose - d_flat) > 1e-9 * max(1.0, d_pose):
                fail(f"{cut_path.name}: {link}'s holes are {d_flat} apart, {d_pose} in the pose")
    # A slot cut in each moving link that a pin runs in: a second closed
    # outline on its layer, around the pin as posed.
    for name, value in topology["joints"].items():
        if isinstance(value, dict) and "slot" in value and value.get("guide", ground) != ground:
            guide = value["guide"]
            for doc, what in ((pose, pose_path.name), (cut, cut_path.name)):
                closed = [e for e in doc.modelspace().query("POLYLINE") if e.dxf.layer == guide and e.is_closed]
                if len(closed) < 2:
                    fail(f"{what}: no slot for {name} in {guide}")
            slot = [e for e in pose.modelspace().query("POLYLINE") if e.dxf.layer == guide and e.is_closed][-1]
            xs = [v.dxf.location.x for v in slot.vertices]
            ys = [v.dxf.location.y for v in slot.vertices]
            p = positions[name]
            margin = 1e-9
            if not (min(xs) - margin <= p["x"] <= max(xs) + margin and min(ys) - margin <= p["y"] <= max(ys) + margin):
                fail(f"{pose_path.name}: the slot for {name} does not reach its pin")
    return len(pose_holes)


def main():
    tool = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target/debug/linkage")
    files = sorted((ROOT / "mechanisms/joints").glob("*.toml"))
    if not files:
        fail("no topology files")
    with tempfile.TemporaryDirectory() as work:
        for path in files:
            check(tool, path, pathlib.Path(work))
            print(f"check_dxf: {path.name}: pose and cut sheet read by ezdxf {ezdxf.__version__}, 0 errors")


if __name__ == "__main__":
    main()
