#!/usr/bin/env python3
"""The real suite's report as a person sees it: report.html of `usvid compare --suite real
--quick` opened in headless Chromium (Debian's, installed by `tools/install-deps.sh --test`).

Every plot of every track's report (the <details> of every method opened too) must lay out at
its size, draw something (a series or a heat map's cell with an extent), and carry its axis
labels (`class="axis-label"`, plot/svg_text.h). Each held-out turning circle has a plan view,
north against east, with the marks of the advance and the tactical diameter; each held-out
zig-zag its heading and rudder with the base course +-B. The layout is the browser's: an SVG
that did not parse, or a figure left at zero size, fails here and not in a string check.

Usage: report_render_test.py USVID SHARED_DATA_DIR WORK_DIR [SCREENSHOT.png]
Exit 77 (skipped) without Chromium or without the shared data; 1 on a failure.
"""
import html
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77

# Run in the page once it has loaded: opens every <details>, measures every figure's SVG and
# writes what it found into the page, which --dump-dom prints.
CHECK_SCRIPT = """
<script>
window.addEventListener('load', () => {
  document.querySelectorAll('details').forEach(d => { d.open = true; });
  const found = [];
  document.querySelectorAll('figure.plot > svg').forEach(svg => {
    const box = svg.getBoundingClientRect();
    let drawn = 0;
    svg.querySelectorAll('g.series path, g.series polyline, g.cell rect').forEach(p => {
      const b = p.getBBox();
      if (b.width > 0 || b.height > 0) drawn++;
    });
    const title = svg.querySelector('text[font-weight="bold"]');
    found.push({
      title: title ? title.textContent : '',
      width: box.width, height: box.height, drawn: drawn,
      labels: [...svg.querySelectorAll('text.axis-label')].map(t => t.textContent),
      texts: [...svg.querySelectorAll('text')].map(t => t.textContent),
    });
  });
  const out = document.createElement('pre');
  out.id = 'render-check';
  out.textContent = JSON.stringify(found);
  document.body.appendChild(out);
});
</script>
"""


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def chromium_args(browser):
    # --no-sandbox: CI runs as root, where Chromium's sandbox refuses to start.
    return [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
            "--virtual-time-budget=10000"]


def check_track(browser, track_dir, failures):
    report = os.path.join(track_dir, "report.html")
    with open(report, encoding="utf-8") as f:
        page = f.read()
    expected = page.count('<figure class="plot">')
    checked = os.path.join(track_dir, "report_render_check.html")
    with open(checked, "w", encoding="utf-8") as f:
        f.write(page.replace("</body>", CHECK_SCRIPT + "</body>"))
    dom = subprocess.run(chromium_args(browser) + ["--dump-dom", "file://" + checked],
                         capture_output=True, text=True, timeout=300)
    match = re.search(r'<pre id="render-check">(.*?)</pre>', dom.stdout, re.S)
    name = os.path.basename(track_dir)
    if not match:
        failures.append(f"{name}: Chromium gave no measurement (exit {dom.returncode}): "
                        f"{dom.stderr.strip()[-300:]}")
        return []
    figures = json.loads(html.unescape(match.group(1)))
    if len(figures) != expected:
        failures.append(f"{name}: {len(figures)} figures laid out, the page holds {expected}")
    for i, fig in enumerate(figures):
        what = f"{name}, figure {i + 1} ({fig['title'] or 'untitled'})"
        if fig["width"] < 100 or fig["height"] < 100:
            failures.append(f"{what}: laid out at {fig['width']:.0f} x {fig['height']:.0f} px")
        if fig["drawn"] == 0:
            failures.append(f"{what}: blank (no series or cell with an extent)")
        if not fig["labels"]:
            failures.append(f"{what}: no axis label")
    return figures


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    usvid, data, work = sys.argv[1:4]
    screenshot = sys.argv[4] if len(sys.argv) > 4 else None
    browser = find_chromium()
    if not browser:
        print("skipped: no Chromium (install it with tools/install-deps.sh --test)")
        return SKIP
    if not os.path.isdir(data):
        print(f"skipped: shared data absent: {data}")
        return SKIP
    shutil.rmtree(work, ignore_errors=True)
    out = os.path.join(work, "real")
    run = subprocess.run([usvid, "compare", "--suite", "real", "--quick", "--data-dir", data,
                          "--threads", "2", "--out", out], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"usvid compare failed ({run.returncode}):\n{run.stderr[-2000:]}")
        return 1
    failures = []
    plans = []
    tracks = sorted(d for d in os.listdir(out) if os.path.isfile(os.path.join(out, d, "report.html")))
    if not tracks:
        failures.append("no track wrote a report.html")
    for track in tracks:
        for fig in check_track(browser, os.path.join(out, track), failures):
            if "plan" in fig["title"] or "heading and rudder" in fig["title"]:
                plans.append((track, fig))
    # The plan views: north against east with the criteria's marks on a circle, heading and
    # rudder with the base course +-B on a zig-zag.
    circles = [(t, f) for t, f in plans if "turning" in f["title"] and "plan" in f["title"]]
    zigzags = [(t, f) for t, f in plans if "heading and rudder" in f["title"]]
    if not circles or not zigzags:
        failures.append(f"{len(circles)} plan views of turning circles and {len(zigzags)} "
                        "heading figures of zig-zags: both expected")
    for track, fig in circles:
        if sorted(fig["labels"]) != ["east [m]", "north [m]"]:
            failures.append(f"{track}, {fig['title']}: axes {fig['labels']}, not east and north")
        for mark in ("the advance", "the tactical diameter"):
            if not any(mark in t for t in fig["texts"]):
                failures.append(f"{track}, {fig['title']}: no mark of {mark}")
    for track, fig in zigzags:
        if not any(t.startswith("base course +-") for t in fig["texts"]):
            failures.append(f"{track}, {fig['title']}: no base course +-B")
    if screenshot and tracks:
        esso = os.path.join(out, "esso-osaka", "report.html")
        page = esso if os.path.isfile(esso) else os.path.join(out, tracks[0], "report.html")
        subprocess.run(chromium_args(browser) + ["--window-size=1100,3000",
                       "--screenshot=" + os.path.abspath(screenshot), "file://" + page],
                       capture_output=True, timeout=300)
    for f in failures:
        print("FAIL:", f)
    print(f"{len(tracks)} reports, {len(plans)} plan and heading figures checked in {browser}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
