#!/usr/bin/env python3
"""Reference solutions of every bundled pyslvs 22.7.0 example.

Run with the venv that has pyslvs 22.7.0 (benches/peers/pyslvs_install.sh
builds it: there is no wheel for Python 3.11, and the sdist needs Cython 3.0
betas with one directive):
    /tmp/pyslvs-venv/bin/python benches/peers/pyslvs_examples.py

Writes /tmp/pyslvs-work/pyslvs_examples.json and prints a summary;
tests/data/pyslvs_examples.json is that file with, for each case, the
inputs, pyslvs's own errors and each joint's position (the pin of a
slider) kept, made by the function `slim` below.

For every example (pyslvs.all_examples(), sorted by name) the positions are
solved with the same call sequence pyslvs' own test-suite uses:

    vpoints = parse_vpoints(expr)
    exprs   = t_config(vpoints, inputs)           # inputs: ((base, drive), ...)
    result  = expr_solving(exprs, vpoints, {(base, drive): angle_deg, ...})

The input angle is ABSOLUTE (angle of vector base->drive from the +x axis, in
degrees).  The examples carry no input angle, so the "default" is 0 deg (what
pyslvs' test_core.py uses); +30 and +60 deg are also solved.  Additionally the
"drawn" angle (the angle of base->drive in the expression's own coordinates,
i.e. the pose as drawn) and drawn+30 / drawn+60 are solved, since several
examples cannot be assembled at 0 deg.

Result format (JSON):
  revolute joint: {"type": "R", "x": .., "y": ..}
  slider joint (P/RP): {"type": "P"|"RP", "slot": [x, y], "pin": [x, y]}
     slot = point on the slot link (for triangular mode: the slider's
            expression coordinate, unchanged; for BFGS mode: solved slot base),
     pin  = solved pin position.
Floats are written with repr precision (json uses float.__repr__).
"""

import json
import os
import math
import sys

import pyslvs
from pyslvs import (
    all_examples, example_list, parse_vpoints, t_config, expr_solving,
    vpoint_dof, get_vlinks, VJoint,
)

OUT = "/tmp/pyslvs-work/pyslvs_examples.json"
os.makedirs(os.path.dirname(OUT), exist_ok=True)


def coverage_mode(exprs, n):
    """Replicates expr_solving's check: BFGS mode if the triangle stack
    does not touch every joint."""
    touched = set()
    for e in exprs.as_list():
        func, args = e[0], e[1:]
        for s in args:
            if s.startswith("P"):
                touched.add(int(s[1:]))
    return "triangular" if touched >= set(range(n)) else "bfgs"


def drawn_angle(vpoints, base, drive):
    b, d = vpoints[base], vpoints[drive]
    # use the pin coordinate (cx, cy) like the solver does
    return math.degrees(math.atan2(d.cy - b.cy, d.cx - b.cx))


def fmt_result(vpoints, result):
    out = []
    for vp, r in zip(vpoints, result):
        if vp.type == VJoint.R:
            out.append({"type": "R", "x": r[0], "y": r[1]})
        else:
            (sx, sy), (px, py) = r
            out.append({"type": vp.type_str, "slot": [sx, sy],
                        "pin": [px, py]})
    return out


def link_point(vp, r, link):
    """Coordinate of joint result `r` as seen from `link`."""
    if vp.type == VJoint.R:
        return r
    if link == vp.links[0] and tuple(r[0]) == tuple(r[1]) and \
            (vp.cx, vp.cy) != tuple(r[0]):
        # BFGS mode reports triangle-pre-solved sliders as (pin, pin):
        # the slot base is unknown, skip it.
        return None
    return r[0] if link == vp.links[0] else r[1]


def check(vpoints, res):
    """Max |distance change| over every joint pair sharing a link (incl.
    ground), and max distance of slider pins from their grounded slot line."""
    init = [vp.c[0, 0] for vp in vpoints]  # noqa (sliders: c[0]==c[1])
    err = 0.0
    links = {}
    for i, vp in enumerate(vpoints):
        for l in vp.links:
            links.setdefault(l, []).append(i)
    for l, idx in links.items():
        for a in range(len(idx)):
            for b in range(a + 1, len(idx)):
                i, j = idx[a], idx[b]
                pi = link_point(vpoints[i], res[i], l)
                pj = link_point(vpoints[j], res[j], l)
                if pi is None or pj is None:
                    continue
                d0 = math.hypot(vpoints[i].cx - vpoints[j].cx,
                                vpoints[i].cy - vpoints[j].cy)
                d1 = math.hypot(pi[0] - pj[0], pi[1] - pj[1])
                err = max(err, abs(d1 - d0))
    serr = 0.0
    for vp, r in zip(vpoints, res):
        if vp.is_slider() and vp.grounded():
            (sx, sy), (px, py) = r
            if (sx, sy) == (px, py):
                continue
            a = math.radians(vp.angle)
            serr = max(serr, abs(-(px - sx) * math.sin(a) + (py - sy) * math.cos(a)))
    return err, serr


def solve_case(expr, inputs, angles):
    vpoints = parse_vpoints(expr)
    exprs = t_config(vpoints, inputs)
    ang = {tuple(p): a for p, a in zip(inputs, angles)}
    try:
        res = expr_solving(exprs, vpoints, ang)
    except Exception as err:  # noqa
        return {"ok": False, "error": f"{type(err).__name__}: {err}"}
    lerr, serr = check(vpoints, res)
    return {"ok": True, "max_link_length_error": lerr,
            "max_slider_line_error": serr,
            "joints": fmt_result(vpoints, res)}


def main():
    data = {"pyslvs_version": pyslvs.__version__, "examples": []}
    for name in all_examples():
        expr, inputs = example_list(name)
        inputs = [tuple(p) for p in inputs]
        vpoints = parse_vpoints(expr)
        exprs = t_config(vpoints, inputs)
        vlinks = get_vlinks(vpoints)
        drawn = [drawn_angle(vpoints, b, d) for b, d in inputs]
        entry = {
            "name": name,
            "expression": expr,
            "input_pairs": [list(p) for p in inputs],
            "dof": vpoint_dof(vpoints),
            "n_joints": len(vpoints),
            "links": sorted(v.name for v in vlinks),
            "n_links_incl_ground": len(vlinks),
            "joint_types": [vp.type_str for vp in vpoints],
            "slider_angles_deg": {str(i): vp.angle for i, vp in
                                  enumerate(vpoints) if vp.is_slider()},
            "initial_positions": [[vp.cx, vp.cy] for vp in vpoints],
            "t_config": [list(e) for e in exprs.as_list()],
            "solver_mode": coverage_mode(exprs, len(vpoints)),
            "drawn_input_angles_deg": drawn,
            "cases": [],
        }
        case_specs = [
            ("default_0deg", [0.0] * len(inputs)),
            ("plus30", [30.0] * len(inputs)),
            ("plus60", [60.0] * len(inputs)),
            ("drawn", list(drawn)),
            ("drawn_plus30", [a + 30.0 for a in drawn]),
            ("drawn_plus60", [a + 60.0 for a in drawn]),
        ]
        for label, angles in case_specs:
            c = solve_case(expr, inputs, angles)
            c = {"label": label,
                 "inputs": [{"pair": list(p), "angle_deg": a}
                            for p, a in zip(inputs, angles)],
                 **c}
            entry["cases"].append(c)
        data["examples"].append(entry)

    with open(OUT, "w") as f:
        json.dump(data, f, indent=1)

    # summary
    for e in data["examples"]:
        print(f"== {e['name']}: pairs={e['input_pairs']} dof={e['dof']} "
              f"joints={e['n_joints']} links(incl ground)="
              f"{e['n_links_incl_ground']} types={''.join(t[0] if t=='R' else '['+t+']' for t in e['joint_types'])} "
              f"mode={e['solver_mode']} drawn={[round(a, 6) for a in e['drawn_input_angles_deg']]}")
        for c in e["cases"]:
            angs = [round(i["angle_deg"], 6) for i in c["inputs"]]
            if c["ok"]:
                last = c["joints"][-1]
                print(f"   {c['label']:13s} {angs}: OK lenerr={c['max_link_length_error']:.1e} "
                      f"slidererr={c['max_slider_line_error']:.1e} last={last}")
            else:
                print(f"   {c['label']:13s} {angs}: FAIL {c['error']}")
    jn = next(e for e in data["examples"]
              if e["name"] == "Jansen's linkage (Single)")
    j7 = jn["cases"][0]["joints"][7]
    print("Jansen (Single) joint 7 @0deg:", j7["x"], j7["y"],
          "matches docs (-43.170055, -91.753226):",
          abs(j7["x"] + 43.170055) < 1e-6 and abs(j7["y"] + 91.753226) < 1e-6)
    print("wrote", OUT)


def slim(path_in="/tmp/pyslvs-work/pyslvs_examples.json", path_out="tests/data/pyslvs_examples.json"):
    """The committed reference: each case's inputs, pyslvs's own errors and
    each joint's position (a slider's pin)."""
    d = json.load(open(path_in))
    out = {"source": "pyslvs 22.7.0 (its 22 example mechanisms, pyslvs.example_list), solved by pyslvs itself with benches/peers/pyslvs_examples.py; positions as Python's repr of each float",
           "pyslvs_version": d["pyslvs_version"], "examples": []}
    for e in d["examples"]:
        cases = []
        for c in e["cases"]:
            cc = {"label": c["label"], "inputs": [[i["pair"][0], i["pair"][1], i["angle_deg"]] for i in c["inputs"]], "ok": c["ok"]}
            if c["ok"]:
                cc["max_link_length_error"] = c.get("max_link_length_error")
                cc["max_slider_line_error"] = c.get("max_slider_line_error")
                cc["joints"] = [[j["x"], j["y"]] if j["type"] == "R" else j["pin"] for j in c["joints"]]
            else:
                cc["error"] = c["error"]
            cases.append(cc)
        out["examples"].append({"name": e["name"], "expression": e["expression"], "inputs": e["input_pairs"],
                                "solver": e["solver_mode"], "drawn_input_angles_deg": e["drawn_input_angles_deg"], "cases": cases})
    open(path_out, "w").write(json.dumps(out, indent=1))


if __name__ == "__main__":
    code = main()
    slim()
    sys.exit(code)
