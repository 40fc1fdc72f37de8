"""Headless Chromium driven through its DevTools protocol, for the page's
tests: the page served by `linkage serve`, a tab opened on it, scripts
evaluated in it (their promises awaited), mouse and keyboard events sent
as a person's would be, screenshots taken."""

import base64
import json
import os
import re
import shutil
import subprocess
import tempfile
import time
import urllib.request
from pathlib import Path

import websocket

ROOT = Path(__file__).resolve().parents[2]


def chromium():
    for name in ("chromium", "chromium-headless-shell", "google-chrome"):
        if shutil.which(name):
            return name
    raise SystemExit("no Chromium: apt-get install chromium")


class Server:
    """`linkage serve web --port 0`: the page on the loopback interface."""

    def __init__(self):
        tool = ROOT / "target/debug/linkage"
        command = [str(tool)] if tool.exists() else ["cargo", "run", "-q", "-p", "linkage-cli", "--"]
        self.process = subprocess.Popen(command + ["serve", str(ROOT / "web"), "--port", "0"],
                                        stderr=subprocess.PIPE, text=True, cwd=ROOT)
        line = self.process.stderr.readline()
        found = re.search(r"http://[0-9.:]+/", line)
        if not found:
            self.process.kill()
            raise SystemExit(f"linkage serve did not start: {line}")
        self.url = found.group(0)

    def close(self):
        self.process.kill()
        self.process.wait()


class Tab:
    """A tab of a headless Chromium of its own, `width` × `height` CSS
    pixels."""

    def __init__(self, width=1280, height=900):
        self.profile = tempfile.mkdtemp(prefix="linkage-chromium-")
        self.browser = subprocess.Popen(
            [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             "--remote-debugging-port=0", f"--user-data-dir={self.profile}",
             f"--window-size={width},{height}", "--force-device-scale-factor=1",
             "--font-render-hinting=none", "about:blank"],
            stderr=subprocess.PIPE, text=True)
        port = None
        for _ in range(200):
            line = self.browser.stderr.readline()
            found = re.search(r"DevTools listening on ws://127\.0\.0\.1:(\d+)/", line)
            if found:
                port = found.group(1)
                break
        if port is None:
            self.close()
            raise SystemExit("Chromium did not open its DevTools port")
        request = urllib.request.Request(f"http://127.0.0.1:{port}/json/new?about:blank", method="PUT")
        target = json.loads(urllib.request.urlopen(request, timeout=30).read())
        self.socket = websocket.create_connection(target["webSocketDebuggerUrl"], timeout=120,
                                                  suppress_origin=True)
        self.counter = 0
        self.messages = []
        self.call("Page.enable")
        self.call("Runtime.enable")
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
                  deviceScaleFactor=1, mobile=False)

    def call(self, method, **params):
        self.counter += 1
        ident = self.counter
        self.socket.send(json.dumps({"id": ident, "method": method, "params": params}))
        while True:
            message = json.loads(self.socket.recv())
            if message.get("id") == ident:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})
            if message.get("method") == "Runtime.consoleAPICalled":
                self.messages.append(" ".join(str(a.get("value", a.get("description", "")))
                                              for a in message["params"]["args"]))
            if message.get("method") == "Runtime.exceptionThrown":
                self.messages.append(message["params"]["exceptionDetails"].get("text", "")
                                     + str(message["params"]["exceptionDetails"].get("exception", {})
                                           .get("description", "")))

    def evaluate(self, expression):
        """The value of `expression` in the page (a promise awaited)."""
        result = self.call("Runtime.evaluate", expression=expression, awaitPromise=True,
                           returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def open(self, url):
        # Through a blank page: a link that differs only after its `#`
        # would not load the page again.
        self.call("Page.navigate", url="about:blank")
        self.wait("document.readyState === 'complete' && location.href === 'about:blank'")
        self.call("Page.navigate", url=url)
        self.wait("document.body && document.body.dataset.ready === 'yes'")

    def wait(self, condition, seconds=120):
        end = time.time() + seconds
        while time.time() < end:
            if self.evaluate(f"Boolean({condition})"):
                return
            time.sleep(0.05)
        raise TimeoutError(f"waited {seconds} s for {condition}; the page said {self.messages[-5:]}")

    def centre(self, selector, fraction=0.5):
        """The point at `fraction` of the width of the element, at its
        middle height (CSS pixels of the viewport), the element scrolled
        into view."""
        box = self.evaluate(
            f"(() => {{ const e = document.querySelector({json.dumps(selector)});"
            " e.scrollIntoView({ block: 'center', inline: 'center' });"
            " const r = e.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; })()")
        return box[0] + fraction * box[2], box[1] + box[3] / 2

    def mouse(self, kind, x, y, buttons=1):
        self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                  buttons=buttons if kind != "mouseReleased" else 0, clickCount=1)

    def drag(self, start, end, steps=10):
        self.mouse("mousePressed", *start)
        for k in range(1, steps + 1):
            t = k / steps
            self.mouse("mouseMoved", start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
        self.mouse("mouseReleased", *end)

    def key(self, key, code, key_code):
        for kind in ("keyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=code,
                      windowsVirtualKeyCode=key_code)

    def screenshot(self, path, selector=None):
        """A PNG of the viewport, or of the element `selector` only."""
        params = {"format": "png"}
        if selector:
            box = self.evaluate(
                f"(() => {{ const r = document.querySelector({json.dumps(selector)}).getBoundingClientRect();"
                " return [r.left + scrollX, r.top + scrollY, r.width, r.height]; })()")
            params["clip"] = {"x": box[0], "y": box[1], "width": box[2], "height": box[3], "scale": 1}
            params["captureBeyondViewport"] = True
        data = self.call("Page.captureScreenshot", **params)["data"]
        Path(path).write_bytes(base64.b64decode(data))

    def close(self):
        try:
            self.socket.close()
        except Exception:
            pass
        self.browser.kill()
        self.browser.wait()
        shutil.rmtree(self.profile, ignore_errors=True)


def differing_share(ours, committed):
    """The share of pixels of two pictures of the same size that differ by
    more than a sixteenth of full scale in a channel (1.0 if their sizes
    differ)."""
    import numpy as np
    from PIL import Image
    a = np.asarray(Image.open(ours).convert("RGB"), dtype=np.int16)
    b = np.asarray(Image.open(committed).convert("RGB"), dtype=np.int16)
    if a.shape != b.shape:
        return 1.0
    return float((np.abs(a - b).max(axis=2) > 16).mean())


os.environ.setdefault("PYTHONUNBUFFERED", "1")
