#!/usr/bin/python3
"""Loads a `hexray compare --report DIR` page in headless chromium and checks it against the
--json document the same run wrote.

    check_report.py DIR RESULTS.json
    check_report.py --flip DIR

Prints one line, "images loaded=N failed=M; rows=R agree", or says what disagrees. With --flip,
hovers over, leaves, then clicks the first GPU render (in a copy of the page with a script
added) and prints the image it shows at each step: "flip gpu cpu gpu cpu". Exit code
0 when the page's image check ran and its summary rows equal the document's results (scene,
precision, outcome, 8-bit RMSE, ambiguous share), 1 when they do not, 2 when chromium cannot be run: CI installs
it (ci/install-deps.sh), so a missing browser is a failure, never a skip.
"""

import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

import lxml.html


def dump_dom(page):
    browser = shutil.which("chromium")
    if browser is None:
        print("chromium not found: install Debian's chromium package (ci/install-deps.sh does)")
        sys.exit(2)
    with tempfile.TemporaryDirectory() as profile:
        # --no-sandbox: the tests may run as root, where chromium's sandbox refuses to start.
        # The virtual time budget lets the page's load handler run before the DOM is dumped.
        run = subprocess.run(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--user-data-dir=" + profile,
             "--virtual-time-budget=5000", "--dump-dom", page.resolve().as_uri()],
            capture_output=True, text=True, timeout=120)
    if run.returncode != 0 or not run.stdout.strip():
        print("chromium failed (exit %d): %s" % (run.returncode, run.stderr[-2000:]))
        sys.exit(2)
    return lxml.html.fromstring(run.stdout)


def expected_rows(document):
    rows = []
    for result in document["results"]:
        rmse = result["encoded"]["rmse"] if "encoded" in result else None
        ambiguous = result["topology"]["ambiguous_share"] if "topology" in result else None
        rows.append((result["name"], result.get("precision", ""), result["outcome"], rmse, ambiguous))
    return rows


def page_rows(dom):
    rows = []
    for row in dom.xpath('//table[@id="summary"]/tbody/tr'):
        rmse, ambiguous = row.get("data-rmse"), row.get("data-ambiguous-share")
        rows.append((row.get("data-scene"), row.get("data-precision"), row.get("data-outcome"),
                     float(rmse) if rmse else None, float(ambiguous) if ambiguous else None))
    return rows


# Appended to a copy of the page: what the first GPU render shows before, while and after hovering,
# and after a click.
FLIP_SCRIPT = """<script>
window.addEventListener('load', () => {
  const img = document.querySelector('img.flip'), shown = [img.getAttribute('src')];
  for (const step of [() => img.dispatchEvent(new MouseEvent('mouseenter')),
                      () => img.dispatchEvent(new MouseEvent('mouseleave')), () => img.click()]) {
    step();
    shown.push(img.getAttribute('src'));
  }
  document.body.dataset.flip = shown.map(src => src.replace(/^.*-(\\w+)\\.png$/, '$1')).join(' ');
});
</script>"""


def check_flip(directory):
    page = directory / "flip-check.html"
    page.write_text((directory / "index.html").read_text().replace("</body>", FLIP_SCRIPT + "</body>"))
    print("flip " + dump_dom(page).xpath("//body")[0].get("data-flip", "(the script did not run)"))
    return 0


def main():
    if sys.argv[1] == "--flip":
        return check_flip(pathlib.Path(sys.argv[2]))
    directory, results = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    dom = dump_dom(directory / "index.html")
    check = dom.xpath('//output[@id="image-check"]')
    if len(check) != 1:
        print("no image check in the page")
        return 1
    loaded, failed = check[0].get("data-loaded"), check[0].get("data-failed")
    expected, shown = expected_rows(json.loads(results.read_text())), page_rows(dom)
    if shown != expected:
        print("images loaded=%s failed=%s; rows differ:\n page %r\n json %r" % (loaded, failed, shown, expected))
        return 1
    print("images loaded=%s failed=%s; rows=%d agree" % (loaded, failed, len(shown)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
