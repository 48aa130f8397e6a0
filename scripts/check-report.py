#!/usr/bin/env python3
"""Opens a littermap report in headless Chromium and checks what a reader would get.

    scripts/check-report.py REPORT_DIR [--screenshots DIR] [--chromium PATH]

Drives Chromium over the DevTools protocol on a pipe (no network port, no extra packages) and
fails (exit 1, reasons on stderr) unless:
  - the page loads without console errors or uncaught exceptions;
  - it makes no network request (everything is inline; file: and data: URLs only);
  - the hotspot table has one row per hotspot of REPORT_DIR/report.json, every image decoded;
  - the key figures agree with report.json;
  - on a 390 px wide phone screen no element, tables included, is wider than the screen (tables
    become cards there);
  - the hotspot numbers on the map (their boxes, in the map image's data-label-boxes) cover
    none of each other;
  - it prints on A4 pages, none of them less than a quarter full (pages rendered by poppler's
    pdftoppm, the rows that hold ink counted).
Writes desktop.png (the whole page, 1280 px wide), phone.png and report.pdf into --screenshots
(default REPORT_DIR) and prints a one-line summary.
"""

import argparse
import base64
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time


class Browser:
    """A headless Chromium driven over --remote-debugging-pipe (fd 3 in, fd 4 out)."""

    def __init__(self, executable):
        self.profile = tempfile.mkdtemp(prefix="littermap-chromium-")
        to_browser_read, self.to_browser = os.pipe()
        self.from_browser, from_browser_write = os.pipe()

        def child_fds():
            os.dup2(to_browser_read, 3)
            os.dup2(from_browser_write, 4)

        self.process = subprocess.Popen(
            [executable, "--headless=new", "--no-sandbox", "--disable-gpu",
             "--remote-debugging-pipe", "--no-first-run", "--no-default-browser-check",
             "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--disable-extensions", "--mute-audio",
             "--user-data-dir=" + self.profile, "about:blank"],
            # fds 3 and 4 are set up by child_fds, which runs before the child closes the fds
            # not kept.
            pass_fds=(3, 4), preexec_fn=child_fds,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_browser_read)
        os.close(from_browser_write)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def close(self):
        try:
            self.send("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("Chromium did not answer in time")
            chunk = os.read(self.from_browser, 1 << 20)
            if not chunk:
                raise RuntimeError("Chromium closed the DevTools pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def wait_for(self, method, timeout=60):
        deadline = time.monotonic() + timeout
        for event in self.events:
            if event.get("method") == method:
                return event
        while True:
            event = self._read_message(deadline)
            self.events.append(event)
            if event.get("method") == method:
                return event


PAGE_FACTS = """(() => {
  const rows = document.querySelectorAll('#hotspot-table tbody tr').length;
  const images = [...document.images];
  const broken = images.filter(i => !i.complete || i.naturalWidth === 0).length;
  const cards = {};
  for (const card of document.querySelectorAll('.card')) {
    cards[card.querySelector('span').textContent] = card.querySelector('b').textContent;
  }
  // Inside a closed <details> nothing is laid out; everything else must fit the screen.
  const wide = [...document.querySelectorAll('body *')].filter(e => {
    const box = e.getBoundingClientRect();
    return box.width > 0 && box.right > window.innerWidth + 1;
  }).map(e => e.tagName + (e.className ? '.' + e.className : '') + (e.id ? '#' + e.id : ''));
  if (document.documentElement.scrollWidth > window.innerWidth + 1) wide.unshift('the page');
  const map = document.querySelector('img.map');
  const labels = map && map.dataset.labelBoxes ? map.dataset.labelBoxes.split(';')
      .filter(b => b).map(b => b.split(',').map(Number)) : [];
  return JSON.stringify({rows, images: images.length, broken, cards, labels,
                         sections: [...document.querySelectorAll('h2')].map(h => h.textContent),
                         wide: wide.slice(0, 5), height: document.documentElement.scrollHeight});
})()"""


def page_facts(browser, session):
    result = browser.send("Runtime.evaluate", {"expression": PAGE_FACTS, "returnByValue": True},
                          session)
    return json.loads(result["result"]["value"])


def set_viewport(browser, session, width, height, mobile):
    browser.send("Emulation.setDeviceMetricsOverride",
                 {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": mobile},
                 session)


def screenshot(browser, session, file, width):
    facts = page_facts(browser, session)
    result = browser.send("Page.captureScreenshot", {
        "format": "png", "captureBeyondViewport": True,
        "clip": {"x": 0, "y": 0, "width": width, "height": facts["height"], "scale": 1}},
        session)
    file.write_bytes(base64.b64decode(result["data"]))


def page_fill(pdf):
    """Per page, the share of the page's height between its first and last row of ink."""
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run(["pdftoppm", "-r", "24", "-gray", str(pdf), folder + "/page"], check=True)
        fills = []
        for page in sorted(pathlib.Path(folder).glob("page-*.pgm")):
            data = page.read_bytes()
            # binary PGM: "P5\n<w> <h>\n255\n" then the pixels
            header = data.split(b"\n", 3)
            width, height = map(int, header[1].split())
            pixels = header[3]
            inked = [r for r in range(height)
                     if min(pixels[r * width:(r + 1) * width]) < 200]
            fills.append((inked[-1] - inked[0] + 1) / height if inked else 0.0)
        return fills


def number(text):
    return float("".join(c for c in text if c.isdigit() or c == "."))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report_dir", type=pathlib.Path)
    parser.add_argument("--screenshots", type=pathlib.Path)
    parser.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    args = parser.parse_args()
    index = args.report_dir / "index.html"
    expected = json.loads((args.report_dir / "report.json").read_text())
    out = args.screenshots or args.report_dir
    out.mkdir(parents=True, exist_ok=True)

    failures = []
    browser = Browser(args.chromium)
    try:
        target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = browser.send("Target.attachToTarget",
                               {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            browser.send(domain + ".enable", session=session)
        set_viewport(browser, session, 1280, 900, False)
        browser.events.clear()
        browser.send("Page.navigate", {"url": index.resolve().as_uri()}, session)
        browser.wait_for("Page.loadEventFired")
        time.sleep(0.5)  # late console messages

        facts = page_facts(browser, session)
        screenshot(browser, session, out / "desktop.png", 1280)
        set_viewport(browser, session, 390, 844, True)
        phone = page_facts(browser, session)
        screenshot(browser, session, out / "phone.png", 390)
        set_viewport(browser, session, 1280, 900, False)
        pdf = base64.b64decode(browser.send("Page.printToPDF", {"preferCSSPageSize": True},
                                            session)["data"])
        (out / "report.pdf").write_bytes(pdf)

        requests = []
        for event in browser.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                failures.append("console error: " + " ".join(
                    str(a.get("value", a.get("description", ""))) for a in params["args"]))
            elif method == "Runtime.exceptionThrown":
                failures.append("uncaught exception: " +
                                params["exceptionDetails"].get("text", ""))
            elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
                failures.append("browser error: " + params["entry"]["text"])
            elif method == "Network.requestWillBeSent":
                url = params["request"]["url"]
                if not url.startswith(("data:", "file:")):
                    requests.append(url)
        failures += ["network request: " + url for url in requests]

        hotspots = len(expected["hotspots"])
        if facts["rows"] != hotspots:
            failures.append(f"hotspot table has {facts['rows']} rows, report.json {hotspots}")
        if facts["broken"] or facts["images"] < 1 + hotspots:
            failures.append(f"{facts['images']} images ({facts['broken']} not decoded), "
                            f"expected the map and {hotspots} close-ups")
        hotspot_label = "hotspot" if hotspots == 1 else "hotspots"
        for label, key in (("litter items found", "items"), (hotspot_label, None)):
            shown = facts["cards"].get(label)
            want = hotspots if key is None else expected["totals"][key]
            if shown is None or number(shown) != want:
                failures.append(f"key figure '{label}' shows {shown}, report.json {want}")
        for section in ("Site map", "Where to clean first", "What litter", "Change over time",
                        "Survey quality"):
            if section not in facts["sections"]:
                failures.append(f"section '{section}' missing")
        if phone["wide"]:
            failures.append("wider than a phone screen: " + ", ".join(phone["wide"]))
        pages = pdf.count(b"/Type /Page") - pdf.count(b"/Type /Pages")
        boxes = re.findall(rb"/MediaBox \[0 0 ([\d.]+) ([\d.]+)\]", pdf)
        if not boxes or any(abs(float(w) - 595.3) > 1 or abs(float(h) - 841.9) > 1
                            for w, h in boxes):
            failures.append("printed pages are not A4 (595 x 842 pt)")
        if not 1 <= pages <= 12:
            failures.append(f"prints on {pages} pages")
        labels = facts["labels"]
        if len(labels) != hotspots:
            failures.append(f"{len(labels)} hotspot numbers on the map, {hotspots} hotspots")
        for i, (ax, ay, aw, ah) in enumerate(labels):
            for j, (bx, by, bw, bh) in enumerate(labels[:i]):
                if ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah:
                    failures.append(f"hotspot numbers {j + 1} and {i + 1} cover each other")
        fills = page_fill(out / "report.pdf")
        for page, fill in enumerate(fills, 1):
            if fill < 0.25:
                failures.append(f"printed page {page} of {len(fills)} is {fill:.0%} full")
    finally:
        browser.close()

    for failure in failures:
        print("check-report: " + failure, file=sys.stderr)
    print(f"check-report: {index}: {facts['rows']} hotspot rows, {facts['images']} images, "
          f"{len(requests)} network requests, {pages} A4 pages (filled "
          f"{', '.join(f'{f:.0%}' for f in fills)}); screenshots in {out}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
