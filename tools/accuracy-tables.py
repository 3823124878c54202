#!/usr/bin/python3
"""The tables of docs/accuracy.md, as Markdown, from data: `hexray compare --json` and `hexray
render --json` documents, and the properties the accuracy tests record (GoogleTest's
`--gtest_output=json`). tools/accuracy-report.sh runs the commands and tests and calls this.

Usage: tools/accuracy-tables.py device COMPARE.json
       tools/accuracy-tables.py compare COMPARE.json
       tools/accuracy-tables.py shares MARGINS.json
       tools/accuracy-tables.py hard HARD_CASES.json
       tools/accuracy-tables.py oracle ORACLE.json
       tools/accuracy-tables.py cost RENDER.json...
"""
import json
import statistics
import sys


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def tests(path):
    """Every test of a --gtest_output=json file that ran, as (suite, test) pairs; a failed or
    skipped test stops the report (its figures would be wrong or missing)."""
    found = []
    for suite in load(path)["testsuites"]:
        for test in suite["testsuite"]:
            if test.get("result") != "COMPLETED" or test.get("failures"):
                sys.exit(f"{path}: {suite['name']}.{test['name']} did not pass")
            found.append((suite["name"], test))
    if not found:
        sys.exit(f"{path}: no test ran")
    return found


def device(path):
    d = load(path)["device"]
    print(f"{d['name']} — {d['type']}, Vulkan {d['api']}, {d['driver']}")


def verdict(result):
    """compare's verdict column (host/cli/compare_command.cpp, verdictText)."""
    checks = result["checks"]
    only_ambiguous = not checks["ambiguous_share"] and all(
        checks[k] for k in ("topology_mismatches", "bad_pixels", "rmse", "invalid_colours"))
    passed = result["passed_tolerance"]
    outcome = result["outcome"]
    if outcome == "not_judged":
        return "(pass)" if passed else "(fail, not judged)"
    if outcome == "passed":
        return "pass"
    if outcome == "expected":
        return "expected (too ambiguous)" if only_ambiguous else "expected (fail)"
    if passed:
        return f"FAIL (passed; expected {result['expectation']['expect']})"
    return "FAIL (too ambiguous)" if only_ambiguous else "FAIL"


def compare(path):
    document = load(path)
    print("| scene | precision | auto | topology mismatches | ambiguous | excused | max abs (levels) "
          "| RMSE (levels) | mean FLIP | > 1 level | GPU ms | verdict |")
    print("|---|---|:-:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for r in document["results"]:
        if "error" in r:
            print(f"| {r['name']} | – | | – | – | – | – | – | – | – | – "
                  f"| FAIL (cannot load: {r['error']}) |")
            continue
        t, e = r["topology"], r["encoded"]
        flip = "–" if r["flip_mean"] is None else f"{r['flip_mean']:.5f}"
        print(f"| {r['name']} | {r['precision']} | {'✓' if r['chosen_by_auto'] else ''} | {t['mismatches']} "
              f"| {100 * t['ambiguous_share']:.3f}% | {100 * t['excused_share']:.3f}% | {e['max_abs']:.0f} "
              f"| {e['rmse']:.3f} | {flip} | {100 * e['share_over_one_level']:.3f}% "
              f"| {r['timings_ms']['gpu_render']:.2f} | {verdict(r)} |")
    s = document["summary"]
    print()
    print(f"`compare`'s count line: {'PASS' if s['gate'] == 'pass' else 'FAIL'}: {s['passed']} passed, "
          f"{s['expected']} expected, {s['failed']} failed ({s['not_judged']} shown, not judged).")


def percent(properties, key):
    if key not in properties:
        sys.exit(f"no test recorded {key}")
    return f"{100 * float(properties[key]):.3f}"


def shares(path):
    """The issue-12 table's 'after' column: ShippedSceneMargins and RandomSpheresMargins."""
    properties = {}
    for _, test in tests(path):
        if "scene" in test:
            properties[test["scene"]] = test["ambiguous_share"]
        properties.update({k: v for k, v in test.items() if k.startswith("ambiguous_share_")})
    print(f"| lecture-demo (f32 by auto) | 2.149 % | {percent(properties, 'lecture-demo.json')} % "
          "(f64: see the table above) |")
    for spp, before in ((1, "1.358"), (4, "4.309")):
        f32 = percent(properties, f"ambiguous_share_{spp}spp_f32")
        f64 = percent(properties, f"ambiguous_share_{spp}spp_f64")
        print(f"| 3000 random spheres, {spp} spp | {before} % | {f32} %, {f64} % |")


def hard(path):
    """Violations per hard scene and precision: HardCaseTest (f32, f64) and HardCaseNaiveTest."""
    violations = {}
    for _, test in tests(path):
        if "violations" in test:
            violations[(test["scene"], test["precision"])] = test["violations"]
        for key, value in test.items():
            if key.startswith("violations."):
                violations[(key[len("violations."):], "f32-naive")] = value
    for scene in sorted({scene for scene, _ in violations}):
        cells = [violations.get((scene, p), "") for p in ("f32-naive", "f32", "f64")]
        print(f"| {scene} | {' | '.join(cells)} |")


def oracle(path):
    """OracleSuiteTest's table, from its row<i>.<field> properties, in its order."""
    for _, test in tests(path):
        row = 0
        while f"row{row}.family" in test:
            p = {k[len(f"row{row}."):]: v for k, v in test.items() if k.startswith(f"row{row}.")}
            print(f"| {p['family']} | {p['renderer']} | {p['rays']} | {p['right_decisions']}/{p['decisions']} "
                  f"| {p['distances']} | {float(p['max_distance_ulps']):.2f} | {p['values']} "
                  f"| {float(p['max_value_units']):.2f} |")
            row += 1


def cost(paths):
    """Median and every run of each precision's render time, from `hexray render --json`."""
    runs = {}
    for path in paths:
        scene = load(path)["scenes"][0]
        runs.setdefault(scene["precision"], []).append(scene["timings_ms"]["render"])
    for precision in sorted(runs):
        times = runs[precision]
        listed = " ".join(f"{t:.2f}" for t in times)
        print(f"| {precision} | {statistics.median_low(times):.2f} | {listed} |")


def main(args):
    commands = {"device": device, "compare": compare, "shares": shares, "hard": hard, "oracle": oracle}
    if len(args) >= 2 and args[0] == "cost":
        cost(args[1:])
    elif len(args) == 2 and args[0] in commands:
        commands[args[0]](args[1])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
