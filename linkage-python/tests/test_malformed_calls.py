"""A campaign of malformed calls: every method given garbage (wrong types,
shapes, NaN and infinities, unknown names, texts of the library's files
mutated at random). Each call must return finite numbers or raise a typed
exception — a `LinkageError`, or Python's own `TypeError`, `ValueError`,
`KeyError`, `OverflowError` — and never crash the interpreter, panic (pyo3
turns a Rust panic into `PanicException`, which is no `Exception`) or
hang."""

import json
import math
import random

import numpy as np

import linkage
from conftest import ROOT

CALLS = 10_000
ACCEPTED = (linkage.LinkageError, TypeError, ValueError, KeyError, OverflowError)

GARBAGE = [
    None, 0, -1, 1, 3, 2**70, -(2**70), 1e308, -1e308, math.nan, math.inf, -math.inf, 0.5,
    -0.0, 5e-324, "", "x", "theta2", b"\x00", [], [math.nan], [1.0, 2.0, 3.0], [[1.0]],
    np.zeros((2, 2)), np.array(["a"]), np.array([1 + 2j]), {}, {"l1": math.nan}, object(),
    (1, 2), [None], True, np.float32(1.5), np.int64(3), np.empty(0), [0.3], [1e200],
    np.array([np.inf]), [1.2, -0.9], "l2", "C", "theta3", 1e-300,
]
TOKENS = ["[", "]", "=", "'''", "nan", "1e999", "-", "\x00", "é", "\n", ",", "(", ")", "\"",
          "mm", "deg", "rpm", "0", "theta2", "l2", ".sin()", "*", "[drive.x]", "{", "}"]


def texts():
    """The valid texts the mutations start from, by the constructor that
    reads each."""
    pyslvs = json.loads((ROOT / "tests/data/pyslvs_examples.json").read_text())["examples"]
    return [
        ("from_toml", (ROOT / "mechanisms/four_bar.toml").read_text()),
        ("from_toml", (ROOT / "mechanisms/slider_crank.toml").read_text()),
        ("from_topology", (ROOT / "mechanisms/joints/four_bar.toml").read_text()),
        ("from_topology", (ROOT / "mechanisms/joints/quick_return.toml").read_text()),
        ("from_pyslvs", pyslvs[3]["expression"]),
        ("from_pylinkage", (ROOT / "tests/data/pylinkage/hoeken.json").read_text()),
    ]


def mutate(rng, text):
    for _ in range(rng.randint(1, 4)):
        k = rng.randrange(len(text) + 1)
        kind = rng.random()
        if kind < 0.3:
            text = text[:k] + text[k + rng.randint(1, 12):]
        elif kind < 0.6:
            text = text[:k] + rng.choice(TOKENS) + text[k:]
        elif kind < 0.8:
            j = rng.randrange(len(text) + 1)
            text = text[:k] + text[min(k, j):max(k, j)][:40] + text[k:]
        else:
            text = "".join(rng.choice("0123456789.e-") if c.isdigit() and rng.random() < 0.3 else c
                           for c in text)
    return text


def finite(result):
    """Whether every number a call returned is finite."""
    if isinstance(result, (linkage.Pose, linkage.Sweep)):
        arrays = [result.u, result.v, result.udot, result.uddot, result.points]
        return all(np.isfinite(a).all() for a in arrays)
    if isinstance(result, np.ndarray):
        return bool(np.isfinite(result).all())
    return True


def test_ten_thousand_malformed_calls_raise_typed_exceptions():
    rng = random.Random(20261128)
    bar = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    pose = bar.analyze()
    swept = bar.sweep(steps=40)
    sources = texts()
    numeric = [
        x for x in GARBAGE
        if (isinstance(x, (int, float)) and not isinstance(x, bool))
        or (isinstance(x, list) and all(isinstance(y, float) for y in x))
        or (isinstance(x, np.ndarray) and x.dtype.kind == "f")
    ]
    g = lambda: rng.choice(numeric if rng.random() < 0.7 else GARBAGE)  # noqa: E731
    small = lambda: rng.choice([None, 1, 7, 40, 0, -3, 2**70, 1e9, "9", math.nan])  # noqa: E731

    names = ["theta2", "theta3", "C", "B", "l2", "zz", "", "θ", "l1 ", "theta3\x00"]
    name = lambda: rng.choice(names) if rng.random() < 0.8 else g()  # noqa: E731
    equations = "u = [x], v = [t], points = [P = (x, r * t.sin())], closure = [x - r * t.cos()]"

    def kwargs(names):
        return {n: g() for n in names if rng.random() < 0.5}

    calls = [
        lambda: bar.analyze(**kwargs(["v", "vdot", "vddot", "u"])),
        lambda: bar.sweep(steps=small(), **kwargs(["start", "stop", "rate", "u"])),
        lambda: bar.assemble(g()),
        lambda: bar.with_parameters(**{rng.choice(["l1", "l2", "l3", "l4", "x"]): g()}).analyze(),
        lambda: bar.svg(width=g()) if rng.random() < 0.05 else bar.set_parameter(name(), g()),
        lambda: pose[name()],
        lambda: swept[name()],
        lambda: linkage.Mechanism.from_text(
            mutate(rng, equations), {rng.choice(["r", "s", "x"]): g()}, rng.choice(["M", "1x", g()])
        ).sweep(start=g(), stop=g(), steps=small()),
        lambda: linkage.Mechanism.from_file(g()),
        lambda: linkage.Mechanism.from_pyslvs(
            sources[4][1], rng.choice([[(0, 1)], [(0, 9)], [(1, 0)], [], [(0, 1), (0, 2)], g()])
        ),
        lambda: bar.extremes(rng.choice([None, ["theta4"], ["C.x'"], ["C.path"], ["zz"], [g()], g()]),
                             zeros=rng.random() < 0.5, steps=rng.choice([12, 36, small()]),
                             **kwargs(["start", "stop", "rate"])),
        lambda: bar.tolerance({rng.choice(["l2", "l3", "zz", g()]): rng.choice(
                                  [0.05, -1.0, ("normal", 0.01), ("x", 0.1), g()])},
                              quantities=rng.choice([None, ["theta4"], ["C.path"], [g()]]),
                              samples=rng.choice([0, 0, 20, g()]), steps=rng.choice([12, small()])),
        lambda: bar.sensitivities(**kwargs(["v", "vdot", "u"]),
                                  params=rng.choice([None, ["l2"], ["zz"], [], "l2", [g()], g()])),
        lambda: bar.synthesize(
            **{rng.choice(["path", "function"]): rng.choice(["C", "theta4", "zz", g()])},
            targets=rng.choice([[[30.0, 40.0], [20.0, 50.0]], [[0.1, 1.0]], g(), [[g(), g()]]]),
            free=rng.choice([{"l2": (15.0, 25.0)}, {"l2": (g(), g())}, {g(): (1.0, 2.0)}, {}, g()]),
            timing=rng.choice(["free", "prescribed", "relative", "x", g()]),
            drivers=rng.choice([None, [0.1, 0.2], g()]),
            starts=rng.choice([0, 1, 2, g()]), none_is_error=rng.random() < 0.5,
        ),
    ]

    def from_mutated():
        constructor, text = rng.choice(sources)
        text = mutate(rng, text)
        made = (linkage.Mechanism.from_pyslvs(text, [(0, 1)]) if constructor == "from_pyslvs"
                else getattr(linkage.Mechanism, constructor)(text))
        result = made.analyze(v=rng.choice([None, 0.3])) if made.drive or rng.random() < 0.5 \
            else made.analyze(v=[0.3] * made.f)
        assert finite(result)
        return made.sweep(steps=rng.choice([1, 12]), start=[0.3] * made.f, stop=[0.6] * made.f)

    outcomes = {}
    for _ in range(CALLS):
        call = from_mutated if rng.random() < 0.3 else rng.choice(calls)
        try:
            result = call()
            outcome = "returned"
            assert finite(result), "non-finite numbers returned"
        except ACCEPTED as raised:
            outcome = type(raised).__name__
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
    print("outcomes:", sorted(outcomes.items(), key=lambda kv: -kv[1]))
    assert sum(outcomes.values()) == CALLS
    # The campaign reaches both sides: calls that succeed and every kind
    # of refusal.
    assert outcomes["returned"] > CALLS // 20
    for kind in ["MistakesError", "BadInputError", "TypeError", "FormatError", "KeyError"]:
        assert outcomes.get(kind, 0) > 10, kind
