"""The page in a real browser, driven as a person drives it: headless
Chromium (Debian's) through its DevTools protocol, the page served by
`linkage serve`. It opens the library's four-bar and holds its pose to
the Maple worksheet's numbers recomputed at 50 digits
(tests/data/sensitivities.csv); drags the driver with the mouse and steps
it with the keyboard, and holds each pose and its sensitivities to the
same engine's in Python (the package of linkage-python, in this
environment); edits a dimension, gives one that cannot be (NaN, a crank
too long to turn) and sees a message with the page alive; drags a ground
pivot; clicks target points onto the picture and runs a synthesis in the
page's worker (progress, designs used, a search stopped, targets
mistyped); reaches every control by the keyboard, a mistake's place
among them; opens a malformed file, imports, exports and links; compares
screenshots (the four-bar's picture, the page on a narrow screen) with
committed ones; and reports the engine's size.

    bash web/build.sh && python tests/web/check_page.py   # --update rewrites the screenshots
"""

import base64
import json
import math
import sys
import tempfile
import time
import urllib.parse
from pathlib import Path

from browser import ROOT, Server, Tab, differing_share

import linkage

EXPECTED = ROOT / "tests/web/expected"
#: The share of a screenshot's pixels that may differ from the committed
#: one (text drawn by another machine's fonts, anti-aliasing).
SCREENSHOT_TOLERANCE = 0.03


def reference():
    """θ3, ω3, α3 of the worksheet's four-bar at θ2 = 20°, 400 rpm: the
    50-digit values of tests/data/sensitivities.csv (rows `fourbar,theta3,-`)."""
    for line in (ROOT / "tests/data/sensitivities.csv").read_text().splitlines():
        if line.startswith("fourbar,theta3,-,"):
            return [float(x) for x in line.split(",")[3:6]]
    sys.exit("no reference for the four-bar's theta3")


def data(tab):
    return tab.evaluate("Object.assign({}, document.body.dataset)")


def close(ours, theirs, rel):
    return abs(ours - theirs) <= rel * max(abs(theirs), 1.0)


def selftest(tab, url):
    """The page's own checks, recorded in its body's data."""
    tab.open(url + "?selftest")
    d = data(tab)
    assert "error" not in d, d["error"]
    pose = json.loads(d["pose"])
    theta3, omega3, alpha3 = reference()
    assert pose["v"] == [math.radians(20)], pose["v"]
    for name, ours, exact, rel in [("theta3", pose["u"][0], theta3, 1e-15),
                                   ("omega3", pose["udot"][0], omega3, 1e-13),
                                   ("alpha3", pose["uddot"][0], alpha3, 1e-13)]:
        error = abs(ours - exact) / abs(exact)
        assert error <= rel, f"{name}: {ours} against {exact} ({error:.1e})"
    assert d["plotted"] == "361 0", d.get("plotted")  # the turn in 360 steps, no singular pose
    assert d["importedPyslvs"].startswith("theta_"), d["importedPyslvs"]
    assert d["importRefused"], "a malformed pyslvs expression shows why"
    assert int(d["dxfLayers"]) >= 4, d["dxfLayers"]  # joints and links drawn for CAD
    assert "joints and links" in d["dxfRefused"], d["dxfRefused"]
    assert d["csvRows"] == "362", d["csvRows"]  # a header and 361 poses
    # The smallest transmission angle over the turn, at θ2 = 0:
    # acos((l3² + l4² − (l1 − l2)²)/(2 l3 l4)), sampled each degree.
    smallest = math.degrees(math.acos((50**2 + 70**2 - 60**2) / (2 * 50 * 70)))
    assert abs(float(d["transmission"]) - smallest) < 1e-9, d["transmission"]
    assert d["mistakes"] == "0"
    assert int(d["brokenMistakes"]) >= 1 and "`l9`" in d["brokenMessage"], d
    # Underlined in the editor where it stands, and no longer once mended.
    assert "l9" in json.loads(d["brokenMarks"]), d["brokenMarks"]
    assert d["marksAfter"] == "0", d["marksAfter"]
    # The page's link opens the text it carries: here, the slider-crank.
    crank = (ROOT / "mechanisms/slider_crank.toml").read_text()
    link = d["link"].split("#")[0] + "#file=" + urllib.parse.quote(base64.b64encode(crank.encode()).decode())
    tab.open(link)
    assert data(tab).get("opened") == "SliderCrank", data(tab).get("opened")


def same_as_python(tab, engine):
    """The page's pose and sensitivities at its driver, against the same
    engine's from Python (WebAssembly's sines are not glibc's: 1e-12)."""
    d = data(tab)
    pose = json.loads(d["pose"])
    v = pose["v"][0]
    ours = engine.analyze(v=[v])
    for k, (a, b) in enumerate(zip(pose["u"], ours.u)):
        assert close(a, b, 1e-12), f"u[{k}] at {v}: page {a}, Python {b}"
    for k, (a, b) in enumerate(zip(pose["udot"], ours.udot)):
        assert close(a, b, 1e-11), f"u'[{k}] at {v}: page {a}, Python {b}"
    page = json.loads(d["sensitivities"])
    exact = engine.sensitivities(v=[v]).u
    for i, row in enumerate(page):
        for j, x in enumerate(row):
            assert close(x, exact[i][j], 1e-10), f"du{i}/dp{j} at {v}: page {x}, Python {exact[i][j]}"
    return v


def drive_by_mouse_and_keyboard(tab, url):
    tab.open(url)
    engine = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    start = tab.centre("#driver", 0.1)
    end = tab.centre("#driver", 0.75)
    tab.drag(start, end)
    v = same_as_python(tab, engine)
    assert 3.5 < v < 5.2, f"the drag moved the driver to {v}"
    dead_centres(tab)
    cursor = tab.evaluate("document.getElementById('cursor').getAttribute('x1')")
    tab.evaluate("document.getElementById('driver').focus()")
    tab.key("ArrowRight", "ArrowRight", 39)
    stepped = same_as_python(tab, engine)
    assert stepped > v, f"ArrowRight moved the driver from {v} to {stepped}"
    assert tab.evaluate("document.getElementById('cursor').getAttribute('x1')") != cursor
    # A point's coordinate plotted: G3.y over the turn, its extremes those
    # of the engine's sweep in Python.
    tab.evaluate("(() => { const q = document.getElementById('quantity'); q.value = 'point:'"
                 " + (2 * linkagePage.info.pointNames.indexOf('G3') + 1); q.dispatchEvent(new Event('change')); })()")
    labels = tab.evaluate("[...document.querySelectorAll('#plot text')].map((t) => t.textContent)")
    assert "G3.y against theta2" in labels, labels
    swept = engine.sweep()["G3"][:, 1]
    shown = [float(t) for t in labels[2:4]]
    assert close(shown[0], max(swept), 1e-3) and close(shown[1], min(swept), 1e-3), (shown, max(swept), min(swept))
    return engine


def in_line(centres, a, l2, l3):
    """At each dead centre of a four-bar's rocker, the crank and the coupler
    are in line: the coupler's far end C is l3 + l2 or l3 - l2 from the
    crank's pivot A (B and C the first two points), to rounding."""
    reaches = sorted(math.dist(a, d["points"][1]) for d in centres)
    assert len(reaches) == 2, centres
    for reach, exact in zip(reaches, [l3 - l2, l3 + l2]):
        assert abs(reach - exact) < 1e-14 * exact, f"A to C at a dead centre: {reach}, in line {exact}"


def dead_centres(tab):
    """The four-bar's two dead centres, where the rocker comes to rest with
    the crank and the coupler in line: at θ2 = acos(4/7) and 240° (the
    worksheet's lengths), marked on the plot and the picture and listed."""
    found = tab.evaluate("linkagePage.deadCentres")
    at = [d["v"][0] for d in found]
    assert [d["what"] for d in found] == ["C–D", "C–D"], found
    # Within a few units in the last place (WebAssembly's sines are not glibc's).
    assert abs(at[0] - math.acos(4 / 7)) < 4e-15 and abs(at[1] - math.radians(240)) < 4e-15, at
    in_line(found, (0, 0), 20.0, 50.0)  # the page speaks mm, as the file
    assert tab.evaluate("document.querySelectorAll('#plot .dead-centre').length") == 2
    assert tab.evaluate("document.querySelectorAll('#picture .ghost').length") == 2
    legend = tab.evaluate("document.querySelector('#picture [data-for=ghosts]').textContent")
    assert "dead centres, faint" in legend, legend
    listed = tab.evaluate("[...document.querySelectorAll('#events li')].map((l) => l.textContent)")
    assert sum("dead centre: C–D at rest" in item for item in listed) == 2, listed


def dimensions(tab):
    """A dimension edited redraws; NaN and a crank that cannot turn say why
    and the page lives on."""
    before = json.loads(data(tab)["pose"])["u"]
    tab.evaluate("(() => { const e = document.getElementById('dim-1'); e.value = '21';"
                 " e.dispatchEvent(new Event('change')); })()")
    after = json.loads(data(tab)["pose"])["u"]
    assert after != before, "l2 = 21 moved nothing"
    python = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    python.set_parameter("l2", 21.0)
    same_as_python(tab, python)
    refused = tab.evaluate("(() => { linkagePage.setDimension('l2', NaN); return document.body.dataset.dimensionRefused; })()")
    assert refused and "finite" in refused, refused
    tab.evaluate("(() => { const e = document.getElementById('dim-1'); e.value = '300';"
                 " e.dispatchEvent(new Event('change')); })()")
    message = tab.evaluate("document.getElementById('status').textContent")
    assert "assemble" in message, message
    tab.evaluate("(() => { const e = document.getElementById('dim-1'); e.value = '20';"
                 " e.dispatchEvent(new Event('change')); })()")
    assert tab.evaluate("document.getElementById('status').className") == "", "l2 = 20 draws again"


def drag_a_pivot(tab, url):
    """The ground pivot D of the four-bar given by joints and links,
    dragged by the mouse 30 px right: x_D grows by 30 px of the drawing."""
    text = (ROOT / "mechanisms/joints/four_bar.toml").read_text()
    tab.open(url + "#file=" + urllib.parse.quote(base64.b64encode(text.encode()).decode()))
    info = tab.evaluate("(() => { const p = linkagePage;"
                        " return { names: p.info.parameterNames, values: p.info.parameters, placement: p.placement }; })()")
    names, values, placed = info["names"], info["values"], info["placement"]
    pivots = [n[2:] for n in names if n.startswith("x_") and f"y_{n[2:]}" in names]
    assert pivots, names
    joint = pivots[-1]
    x, y = values[names.index(f"x_{joint}")], values[names.index(f"y_{joint}")]
    # Where the page draws the pivot, in the viewport (the picture is
    # scaled to fit the page: the SVG's own map to the screen).
    sx, sy, ratio = tab.evaluate(
        f"(() => {{ const svg = document.querySelector('#picture svg'), m = svg.getScreenCTM();"
        f" const p = new DOMPoint({(x - placed['origin'][0]) * placed['scale']},"
        f" {placed['top'] + (placed['origin'][1] - y) * placed['scale']}).matrixTransform(m);"
        f" return [p.x, p.y, m.a]; }})()")
    tab.drag((sx, sy), (sx + 30, sy), steps=5)
    dragged = data(tab).get("dragged", "")
    assert dragged.startswith(joint), f"no pivot dragged: {dragged!r}"
    moved = float(dragged.split()[1]) - x
    expected = 30 / (placed["scale"] * ratio)
    assert abs(moved - expected) < 0.02 * expected, f"{joint} moved {moved}, the pointer {expected}"
    assert "error" not in data(tab), data(tab)["error"]
    # Let go, the rocker's dead centres are found where it now turns.
    info = tab.evaluate("(() => { const p = linkagePage.info; return { names: p.parameterNames, values: p.parameters }; })()")
    value = dict(zip(info["names"], info["values"]))
    found = tab.evaluate("linkagePage.deadCentres")
    in_line(found, (value["x_A"], value["y_A"]), value["l_A_B"], value["l_B_C"])


def keyboard(tab, url):
    """Every control named for a screen reader and reached by Tab in the
    page's order; a mistake, reached by Tab, selects its place in the editor
    with Enter; the vectors chosen with the arrow keys."""
    tab.open(url)
    unnamed = tab.evaluate(
        "[...document.querySelectorAll('input, select, textarea, button')]"
        ".filter((e) => !(e.labels?.length || e.getAttribute('aria-label') || e.textContent.trim()))"
        ".map((e) => e.id || e.outerHTML)")
    assert unnamed == [], f"controls without a name: {unnamed}"
    tab.evaluate("document.activeElement.blur()")
    reached = []
    for _ in range(80):
        tab.key("Tab", "Tab", 9)
        reached.append(tab.evaluate("document.activeElement.id"))
    order = ["library", "driver", "vectors", "quantity", "save-svg", "share", "editor", "design-run"]
    places = [reached.index(name) if name in reached else None for name in order]
    assert None not in places and places == sorted(places), f"Tab reached {reached}"
    # A mistake: Tab from the editor to the list, Enter selects it there.
    tab.evaluate("(() => { const e = document.getElementById('editor');"
                 " e.value = e.value.replace('closure = [', 'closure = [ l9 +');"
                 " e.dispatchEvent(new Event('input')); })()")
    tab.wait("document.querySelectorAll('#mistakes li').length > 0", 5)
    tab.evaluate("document.getElementById('editor').focus()")
    tab.key("Tab", "Tab", 9)
    assert tab.evaluate("document.activeElement.parentElement.id") == "mistakes"
    tab.key("Enter", "Enter", 13)
    selected = tab.evaluate("(() => { const e = document.activeElement;"
                            " return [e.id, e.value.slice(e.selectionStart, e.selectionEnd)]; })()")
    assert selected == ["editor", "l9"], selected
    # The vectors, by the arrow keys: a mechanism given by joints and links
    # shows its points' velocities, then their accelerations too.
    text = (ROOT / "mechanisms/joints/four_bar.toml").read_text()
    tab.open(url + "#file=" + urllib.parse.quote(base64.b64encode(text.encode()).decode()))
    count = ("[...document.querySelectorAll('#picture .arrow')]"
             ".map((a) => a.getAttribute('class')).join(' ')")
    points = len(tab.evaluate("linkagePage.info.pointNames"))
    shown = tab.evaluate(count)
    assert tab.evaluate("document.getElementById('vectors').value") == "velocities"
    assert shown.count("velocity") == points and "acceleration" not in shown, shown
    tab.evaluate("document.getElementById('vectors').focus()")
    tab.key("ArrowDown", "ArrowDown", 40)
    shown = tab.evaluate(count)
    assert shown.count("acceleration") == points, shown


def design(tab, url):
    """Targets clicked and typed, a synthesis in the worker, a design used;
    a long search stopped; mistyped targets refused."""
    tab.open(url)
    targets = tab.evaluate(
        "(() => { const { info, sweep } = linkagePage;"
        " const g = info.pointNames.indexOf('G3'), p = info.pointNames.length;"
        " return [0, 72, 144, 216, 288].map((k) => [sweep.points[k * 2 * p + 2 * g],"
        " sweep.points[k * 2 * p + 2 * g + 1]]); })()")
    # A click on the picture places a target where the picture shows it.
    tab.mouse("mousePressed", *tab.centre("#picture svg", 0.5))
    tab.mouse("mouseReleased", *tab.centre("#picture svg", 0.5))
    clicked = tab.evaluate("document.getElementById('design-targets').value")
    assert len(clicked.strip().split("\n")) == 1 and "," in clicked, clicked
    assert tab.evaluate("document.querySelectorAll('#picture svg text').length") > 0
    tab.evaluate("(() => { document.getElementById('design-targets').value = "
                 + json.dumps("\n".join(f"{x!r}, {y!r}" for x, y in targets))
                 + "; document.getElementById('design-point').value = 'G3'; linkagePage.freeBounds();"
                 " document.getElementById('design-starts').value = '12';"
                 " linkagePage.draw(linkagePage.current); })()")
    tab.evaluate("(() => { window.progressSeen = [];"
                 " new MutationObserver(() => progressSeen.push(document.getElementById('design-status').textContent))"
                 ".observe(document.getElementById('design-status'), { childList: true, characterData: true, subtree: true }); })()")
    tab.mouse("mousePressed", *tab.centre("#design-run"))
    tab.mouse("mouseReleased", *tab.centre("#design-run"))
    tab.wait("document.body.dataset.designDone", 120)
    done = data(tab)["designDone"]
    assert done.startswith("done: 12 of 12 starts"), done
    progress = tab.evaluate("progressSeen")
    assert len([p for p in progress if " of 12 starts" in p]) >= 2, progress
    times = tab.evaluate("linkagePage.progressTimes")
    gaps = [b - a for a, b in zip(times, times[1:])]
    # Progress at least every 100 ms (pieces of starts of about 40 ms).
    assert gaps and max(gaps) <= 100, f"the search's reports came {gaps} ms apart"
    found = tab.evaluate("linkagePage.found")
    assert found["designs"], done
    for d in found["designs"]:
        assert d["largestError"] < 1e-6 and d["certificate"]["transmission"] >= 40, d
    # Each design drawn small: its path of G3 passes through the five
    # targets (within a pixel and a half of a vertex of the drawn path).
    misses = tab.evaluate(
        "[...document.querySelectorAll('#designs svg.design-path')].map((svg) => {"
        " const xy = svg.querySelector('path').getAttribute('d').slice(1).split(/[ML]/).map((q) => q.split(',').map(Number));"
        " return [...svg.querySelectorAll('circle')].map((c) => Math.min(...xy.map(([x, y]) =>"
        " Math.hypot(x - c.cx.baseVal.value, y - c.cy.baseVal.value)))); })")
    assert len(misses) == min(len(found["designs"]), 12), misses
    assert all(len(m) == 5 and max(m) < 1.5 for m in misses), misses
    tab.evaluate("document.querySelector('#designs button[data-design]').click()")
    used = json.loads(data(tab)["used"])
    assert used == found["designs"][0]["parameters"], used
    # The editor's text now holds the design, to the bit (read by Python).
    text = tab.evaluate("document.getElementById('editor').value")
    assert linkage.Mechanism.from_toml(text).parameters == used, text
    assert "error" not in data(tab)
    # A long search stopped: the page answers at once, what was found kept.
    tab.evaluate("(() => { delete document.body.dataset.designDone;"
                 " document.getElementById('design-starts').value = '1024';"
                 " document.getElementById('design-run').click(); })()")
    time.sleep(0.5)
    began = time.time()
    tab.evaluate("document.getElementById('design-stop').click()")
    tab.wait("document.body.dataset.designDone", 5)
    assert time.time() - began < 2, "the stop took more than 2 s"
    stopped = data(tab)["designDone"]
    assert stopped.startswith("stopped"), stopped
    # Mistyped targets: said, no search.
    tab.evaluate("(() => { document.getElementById('design-targets').value = '1, 2\\nthree, 4';"
                 " document.getElementById('design-run').click(); })()")
    said = tab.evaluate("document.getElementById('design-status').textContent")
    assert "target line 2" in said, said
    # Targets no design within the bounds reaches: none found, and why.
    tab.evaluate("(() => { delete document.body.dataset.designDone;"
                 " document.getElementById('design-targets').value = '0, 0\\n900, 0\\n0, 900\\n900, 900\\n450, 2000';"
                 " document.getElementById('design-starts').value = '8';"
                 " document.getElementById('design-run').click(); })()")
    tab.wait("document.body.dataset.designDone", 60)
    none = data(tab)["designDone"]
    assert none.startswith("done: 8 of 8 starts, 0 certified designs") and "(" in none, none
    assert "error" not in data(tab), data(tab)["error"]


def screenshots(url, update):
    """The four-bar's picture, and the page on a narrow screen, against the
    committed screenshots; no sideways scrolling on the narrow one."""
    EXPECTED.mkdir(parents=True, exist_ok=True)
    shares = {}
    for name, width, height, selector in [("four_bar_picture", 1280, 900, "#picture"),
                                          ("narrow_page", 400, 900, None)]:
        tab = Tab(width, height)
        try:
            tab.open(url)
            if selector is None:
                wide = tab.evaluate("document.documentElement.scrollWidth")
                assert wide <= width, f"the page is {wide} px wide on a {width} px screen"
            with tempfile.TemporaryDirectory() as folder:
                shot = Path(folder) / f"{name}.png"
                tab.screenshot(shot, selector)
                committed = EXPECTED / f"{name}.png"
                if update or not committed.exists():
                    committed.write_bytes(shot.read_bytes())
                shares[name] = differing_share(shot, committed)
                assert shares[name] <= SCREENSHOT_TOLERANCE, \
                    f"{name}: {shares[name]:.1%} of the pixels differ from {committed}"
        finally:
            tab.close()
    return shares


def main():
    update = "--update" in sys.argv
    server = Server()
    tab = Tab()
    try:
        selftest(tab, server.url)
        drive_by_mouse_and_keyboard(tab, server.url)
        dimensions(tab)
        drag_a_pivot(tab, server.url)
        keyboard(tab, server.url)
        design(tab, server.url)
        tab.close()
        shares = screenshots(server.url, update)
    except BaseException:
        print("the page said:", *tab.messages[-10:], sep="\n  ", file=sys.stderr)
        raise
    finally:
        tab.close()
        server.close()
    wasm = ROOT / "web/pkg/linkage_web_bg.wasm"
    js = ROOT / "web/pkg/linkage_web.js"
    print(f"check_page: in Chromium through `linkage serve`: the worksheet's four-bar to the 50-digit "
          f"references; dragged and stepped poses and sensitivities equal to Python's; dimensions, a pivot "
          f"dragged, a synthesis in the worker; screenshots within "
          f"{', '.join(f'{k} {v:.2%}' for k, v in shares.items())} of the committed; "
          f"engine {wasm.stat().st_size / 1e6:.1f} MB (+ {js.stat().st_size / 1e3:.0f} kB of bindings)")


if __name__ == "__main__":
    main()
