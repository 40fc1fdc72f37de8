"""The page in a real browser: headless Chromium (Debian's) opens
web/index.html from its folder (no server, no network), the engine
compiled to WebAssembly analyses the Maple worksheet's four-bar at its
drive, and the page's numbers are held to the worksheet's recomputed at
50 digits (tests/data/sensitivities.csv); a malformed file shows its
mistake and the page lives on. Prints the engine's size.

    bash web/build.sh && python3 tests/web/check_page.py
"""

import html
import json
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def reference():
    """θ3, ω3, α3 of the worksheet's four-bar at θ2 = 20°, 400 rpm: the
    50-digit values of tests/data/sensitivities.csv (rows `fourbar,theta3,-`)."""
    for line in (ROOT / "tests/data/sensitivities.csv").read_text().splitlines():
        if line.startswith("fourbar,theta3,-,"):
            return [float(x) for x in line.split(",")[3:6]]
    sys.exit("no reference for the four-bar's theta3")


def browser():
    for name in ("chromium", "chromium-headless-shell", "google-chrome"):
        if shutil.which(name):
            return name
    sys.exit("no Chromium: apt-get install chromium")


def body(url):
    dom = subprocess.run(
        [browser(), "--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files",
         "--virtual-time-budget=20000", "--dump-dom", url],
        capture_output=True, text=True, timeout=120, check=True).stdout
    tag = re.search(r"<body([^>]*)>", dom)
    assert tag, "the page has no body"
    return {k: html.unescape(v) for k, v in re.findall(r'data-([a-z-]+)="([^"]*)"', tag.group(1))}


def main():
    page = ROOT / "web" / "index.html"
    data = body(f"file://{page}?selftest")
    assert data.get("ready") == "yes", f"the page did not finish loading: {data}"
    assert "error" not in data, data["error"]
    pose = json.loads(data["pose"])
    theta3, omega3, alpha3 = reference()
    assert pose["v"] == [math.radians(20)], pose["v"]
    checks = [("theta3", pose["u"][0], theta3, 1e-15),
              ("omega3", pose["udot"][0], omega3, 1e-13),
              ("alpha3", pose["uddot"][0], alpha3, 1e-13)]
    for name, ours, exact, rel in checks:
        error = abs(ours - exact) / abs(exact)
        assert error <= rel, f"{name}: {ours} against {exact} ({error:.1e})"
    assert data["plotted"] == "361 0", data.get("plotted")  # the turn in 360 steps, no singular pose
    assert data["imported-pyslvs"].startswith("theta_"), data["imported-pyslvs"]  # joints and links, analysed
    assert data["import-refused"], "a malformed pyslvs expression shows why"
    assert data["csv-rows"] == "362", data["csv-rows"]  # a header and 361 poses
    # The worksheet's four-bar's smallest transmission angle over the turn,
    # at θ2 = 0: acos((l3² + l4² − (l1 − l2)²)/(2 l3 l4)), sampled each degree.
    smallest = math.degrees(math.acos((50**2 + 70**2 - 60**2) / (2 * 50 * 70)))
    assert abs(float(data["transmission"]) - smallest) < 1e-9, data["transmission"]
    # The page's link opens the text it carries: here, the slider-crank.
    link = data["link"]
    crank = (ROOT / "mechanisms/slider_crank.toml").read_text()
    import base64
    import urllib.parse
    shared = link.split("#")[0] + "#file=" + urllib.parse.quote(base64.b64encode(crank.encode()).decode())
    opened = body(shared)
    assert opened.get("opened") == "SliderCrank" and "error" not in opened, opened.get("opened")
    assert data["mistakes"] == "0"
    assert int(data["broken-mistakes"]) >= 1 and "`l9`" in data["broken-message"], data
    wasm = ROOT / "web/pkg/linkage_web_bg.wasm"
    js = ROOT / "web/pkg/linkage_web.js"
    print(f"check_page: the worksheet's four-bar in {browser()} to the 50-digit references; "
          f"a malformed file shows its mistake; engine {wasm.stat().st_size / 1e6:.1f} MB "
          f"(+ {js.stat().st_size / 1e3:.0f} kB of bindings)")


if __name__ == "__main__":
    main()
