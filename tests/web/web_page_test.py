#!/usr/bin/env python3
"""`stochtex web`'s page in headless Chromium (WebGL 2 through ANGLE on Mesa's
llvmpipe),
driven through the DevTools protocol over a pipe (--remote-debugging-pipe:
no network, no extra package).

For each case the page is opened from disk (file://) with its view in the
address's fragment, and must
  * reach data-state="ready" (data decoded, program linked, a frame drawn);
  * match `render --gpu` of the same view, or `scene` of the same object
    (the canvas's pixels, as
    toDataURL gives them, against the PNG, in 8-bit sRGB codes): the page reads the export's 8-bit data,
    the render float data, so the bound is the 8-bit format's cost at these
    scales plus rounding, stated per case below;
  * log no console error or warning and throw no exception.
A real wheel event (Input.dispatchMouseEvent, as a mouse would send) over
the canvas must zoom in about the cursor: the scale shrinks, the texel under
the cursor stays, and the picture changes; a real drag turns a lit object.

Usage: web_page_test.py STOCHTEX_BINARY SOURCE_DIR. Exit 77 (ctest:
skipped) without Chromium.
"""
import base64
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

BIN, SOURCE = sys.argv[1], sys.argv[2]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
if not CHROMIUM:
    print("chromium not installed: skipped")
    sys.exit(77)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Browser:
    """Headless Chromium with one page, spoken to over the DevTools pipe."""

    def __init__(self, work):
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        # WebGL 2 through ANGLE on the machine's EGL (Mesa llvmpipe here;
        # blocklisted by default as a software device): SwiftShader works
        # too, but takes ~30 s to compile each of these programs.
        args = [CHROMIUM, "--headless", "--no-sandbox", "--remote-debugging-pipe", "--use-angle=gl-egl",
                "--ignore-gpu-blocklist", "--user-data-dir=" + os.path.join(work, "profile"),
                "--no-first-run", "--disable-extensions", "about:blank"]
        # Chromium reads commands on fd 3 and writes replies on fd 4.
        self.process = subprocess.Popen(
            ["bash", "-c", 'exec "$0" "$@" 3<&%d 4>&%d' % (to_chrome_r, from_chrome_w)] + args,
            pass_fds=(to_chrome_r, from_chrome_w), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.call(domain + ".enable", session=True)
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": 1000, "height": 700, "deviceScaleFactor": 1, "mobile": False}, session=True)

    def message(self, deadline):
        while b"\0" not in self.buffer:
            if time.time() > deadline:
                fail("Chromium did not answer in time")
            chunk = os.read(self.from_chrome, 1 << 20)
            if not chunk:
                fail("Chromium closed its pipe")
            self.buffer += chunk
        text, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(text)

    def call(self, method, params=None, session=False, timeout=90):
        self.next_id += 1
        command = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            command["sessionId"] = self.session
        os.write(self.to_chrome, json.dumps(command).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            reply = self.message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    fail("%s: %s" % (method, reply["error"]))
                return reply["result"]
            self.events.append(reply)

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session=True)
        if "exceptionDetails" in result:
            fail("evaluate %s: %s" % (expression, result["exceptionDetails"]))
        return result["result"].get("value")

    def wait_for(self, expression, timeout=90):
        deadline = time.time() + timeout
        while time.time() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(0.1)
        fail("timed out waiting for " + expression)

    def open(self, folder, fragment):
        """Opens index.html of `folder` (a new document) and waits until the
        page is ready or says what went wrong; returns its status."""
        self.call("Page.navigate", {"url": "file://%s/index.html#%s&size=%d,%d" % (folder, fragment, W, H)},
                  session=True)
        return self.wait_for("(() => { const s = document.getElementById('status');"
                             " return s && s.dataset.state !== 'loading' && s.dataset.state; })()")

    def frames(self):
        return self.evaluate("document.getElementById('status').dataset.frames")

    def canvas_pixels(self):
        """The canvas's pixels as drawn (it keeps its drawing buffer), RGB."""
        url = self.evaluate("document.getElementById('view').toDataURL('image/png')")
        png = base64.b64decode(url.split(",", 1)[1])
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.float64)

    def problems(self):
        """Console errors and warnings and exceptions seen so far."""
        out = []
        for event in self.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "warning", "assert"):
                out.append("console.%s: %s" % (params["type"], [a.get("value") for a in params.get("args", [])]))
            elif method == "Runtime.exceptionThrown":
                out.append("exception: %s" % params["exceptionDetails"].get("exception", {}).get("description"))
            elif method == "Log.entryAdded" and params["entry"]["level"] in ("error", "warning"):
                out.append("log %s: %s" % (params["entry"]["level"], params["entry"]["text"]))
        return out

    def close(self):
        self.process.kill()
        self.process.wait()


def run(args, what):
    result = subprocess.run([BIN] + args, capture_output=True, text=True)
    if result.returncode != 0:
        fail("%s: %s" % (what, result.stderr.strip()))


# (name, pattern source flags, the reference command (render --gpu or
# scene) with its view flags, fragment, largest mean and 99th
# percentile |Δ| in 8-bit codes: the CPU/GPU parity bound of 0.5/255 on the
# mean; the 8-bit data moves a few pixels on a colormap's steepest edges)
W, H = 256, 192
CASES = [
    ("camouflage zoom smooth", ["--preset", "camouflage"], ["render", "--gpu", "--scale", "4", "--filter", "smooth"],
     "view=zoom&scale=4&x=0&y=0&filter=smooth", 0.5, 2),
    ("marble plane paper", ["--preset", "marble"],
     ["render", "--gpu", "--scale", "2", "--offset", "40,-30", "--view", "plane", "--tilt", "60", "--filter", "paper"],
     "view=plane&scale=2&x=40&y=-30&tilt=60&filter=paper", 0.5, 3),
    ("phasor-stripes zoom none", ["--preset", "phasor-stripes"],
     ["render", "--gpu", "--scale", "1.5", "--filter", "none"], "view=zoom&scale=1.5&x=0&y=0&filter=none", 0.5, 1),
    ("lean-ridges plane (lean response)", ["--preset", "lean-ridges", "--response", "lean"],
     ["render", "--gpu", "--view", "plane", "--tilt", "65", "--filter", "smooth"],
     "view=plane&scale=1&x=0&y=0&tilt=65&filter=smooth", 0.5, 3),
    ("graph with a field table, plane smooth", ["GRAPH"],
     ["render", "--gpu", "--scale", "3", "--view", "plane", "--tilt", "50", "--filter", "smooth"],
     "view=plane&scale=3&x=0&y=0&tilt=50&filter=smooth", 0.5, 2),
    # The lit objects against `scene` (its camera, light and tiling by default).
    ("camouflage on a lit sphere, uv", ["--preset", "camouflage"],
     ["scene", "--object", "sphere", "--filter", "smooth"], "view=sphere&mapping=uv&filter=smooth", 0.5, 2),
    ("marble on a lit torus, triplanar", ["--preset", "marble"],
     ["scene", "--object", "torus", "--mapping", "triplanar", "--filter", "paper"],
     "view=torus&mapping=triplanar&filter=paper", 0.5, 3),
]

# A small graph whose first table is read as a field (its (g, g²) table
# travels as 16-bit PNG codes).
GRAPH = """{"name": "field-cascade", "seed": 3, "offsets": "shared", "nodes": {
  "h": {"type": "spectral_noise", "size": 64, "components": [{"shape": "lowpass", "cutoff": 6}]},
  "f": {"type": "colormap_field", "x": "h", "y": "h", "channel": "red",
        "colormap": {"type": "phasor", "profile": "sine", "transfer": "linear", "resolution": 64}},
  "c": {"type": "colormap", "x": "f", "y": "h", "colormap": {"type": "gaussian", "resolution": 64}}},
 "output": "c"}"""

work = tempfile.mkdtemp()
browser = None
try:
    graph = os.path.join(work, "field-cascade.json")
    with open(graph, "w") as f:
        f.write(GRAPH)
    CASES = [(n, [graph if a == "GRAPH" else a for a in src], v, h, m, p) for n, src, v, h, m, p in CASES]
    browser = Browser(work)
    for case, (name, source, view, fragment, mean_bound, p99_bound) in enumerate(CASES):
        started = time.time()
        folder = os.path.join(work, "page%d" % case)  # a new document each (not a change of fragment)
        run(["web"] + source + ["--size", "%d,%d" % (W, H), "-o", folder], "web " + name)
        reference = os.path.join(work, "reference.png")
        run(view[:1] + source + view[1:] + ["--size", "%d,%d" % (W, H), "-o", reference], view[0] + " " + name)
        browser.events.clear()
        state = browser.open(folder, fragment)
        if state != "ready":
            fail("%s: the page says %s" % (name, browser.evaluate("document.getElementById('status').textContent")))
        got = browser.canvas_pixels()
        expected = np.asarray(Image.open(reference).convert("RGB"), dtype=np.float64)
        diff = np.abs(got - expected)
        mean, p99, flipped = diff.mean(), np.percentile(diff, 99), np.abs(got[::-1] - expected).mean()
        print("[ info ] %s (%.0f s): page vs %s, mean %.3f/255, 99%% %.1f/255, max %.0f/255 (upside down: %.1f)"
              % (name, time.time() - started, view[0], mean, p99, diff.max(), flipped))
        if mean > mean_bound or p99 > p99_bound:
            shot = os.path.join(os.getcwd(), "web-page-failure.png")
            Image.fromarray(got.astype(np.uint8)).save(shot)
            fail("%s: the page differs from its reference: mean %.3f > %.1f or 99%% %.1f > %.0f (its canvas: %s)"
                 % (name, mean, mean_bound, p99, p99_bound, shot))
        if flipped < 4 * mean + 1:
            fail("%s: the page matches its own upside-down image as well: orientation is not tested" % name)
        problems = browser.problems()
        if problems:
            fail("%s: the console has problems: %s" % (name, problems))

    # A real wheel event (one notch away from the user: zoom in) at a point
    # of the first case's canvas (a zoom view at scale 4), opened anew.
    browser.open(os.path.join(work, "page0"), CASES[0][3])
    before = browser.evaluate("JSON.stringify(window.stochtex.state)")
    frames = browser.frames()
    picture = browser.canvas_pixels()
    px, py = 64, 48
    browser.call("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": px, "y": py}, session=True)
    browser.call("Input.dispatchMouseEvent",
                 {"type": "mouseWheel", "x": px, "y": py, "deltaX": 0, "deltaY": -400}, session=True)
    browser.wait_for("document.getElementById('status').dataset.frames !== '%s'" % frames)
    after = json.loads(browser.evaluate("JSON.stringify(window.stochtex.state)"))
    before = json.loads(before)
    if not after["scale"] < 0.75 * before["scale"]:
        fail("the wheel did not zoom in: scale %g → %g" % (before["scale"], after["scale"]))
    # The texel under the cursor (offset + p·scale, p the pixel position) stays.
    for axis, p in (("x", px), ("y", py)):
        t0, t1 = before[axis] + p * before["scale"], after[axis] + p * after["scale"]
        if abs(t1 - t0) > 0.01 * before["scale"]:
            fail("zooming moved the texel under the cursor along %s: %g → %g" % (axis, t0, t1))
    if not "scale=" in browser.evaluate("location.hash"):
        fail("the view is not in the address after zooming")
    changed = np.abs(browser.canvas_pixels() - picture).mean()
    if changed < 2:
        fail("the picture did not change after zooming (mean |Δ| %.2f/255)" % changed)
    print("[ info ] wheel: scale %g → %g about (%d, %d), picture changed by %.1f/255"
          % (before["scale"], after["scale"], px, py, changed))
    # A real drag (press, move, release) on the lit sphere turns it.
    browser.open(os.path.join(work, "page5"), CASES[5][3])
    yaw = browser.evaluate("window.stochtex.state.yaw")
    frames = browser.frames()
    picture = browser.canvas_pixels()
    for kind, x in (("mousePressed", 100), ("mouseMoved", 140), ("mouseReleased", 140)):
        browser.call("Input.dispatchMouseEvent",
                     {"type": kind, "x": x, "y": 90, "button": "left", "buttons": 1 if kind != "mouseReleased" else 0,
                      "clickCount": 1}, session=True)
    browser.wait_for("document.getElementById('status').dataset.frames !== '%s'" % frames)
    turned = browser.evaluate("window.stochtex.state.yaw")
    changed = np.abs(browser.canvas_pixels() - picture).mean()
    if not abs(turned - (yaw - 0.4)) < 1e-6 or changed < 1:
        fail("a 40-pixel drag did not turn the sphere by 0.4 rad: yaw %g → %g, picture changed by %.2f/255"
             % (yaw, turned, changed))
    print("[ info ] drag: yaw %g → %g, picture changed by %.1f/255" % (yaw, turned, changed))
    problems = browser.problems()
    if problems:
        fail("the console has problems after zooming and dragging: %s" % problems)
    print("web page: %d views match render --gpu and scene, the wheel zooms, a drag turns" % len(CASES))
finally:
    if browser:
        browser.close()
    shutil.rmtree(work, ignore_errors=True)
