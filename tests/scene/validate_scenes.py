#!/usr/bin/python3
"""Checks scene files against docs/schemas/hexray-scene.schema.json.

usage: validate_scenes.py SCHEMA PLAIN_SCENE_JSON [--valid PATH...] [--invalid FILE...]

--valid: every scene file (PATH, or the *.json under a directory PATH, except
hexray-expectations.json) must satisfy the schema; for a fuzz regression (NAME.json beside
NAME.expected), only those whose pinned verdict is "accepted".
--invalid: every FILE must violate it (scenes the loader rejects, e.g. for an unknown key).
Comments are dropped by PLAIN_SCENE_JSON (tests/scene/plain_scene_json.cpp), which uses the
loader's own parser settings. Exit 0 when all hold; 1, with each failure on stdout, when not.
Run by /usr/bin/python3: python3-jsonschema is a Debian package of the system interpreter.
"""
import json
import pathlib
import subprocess
import sys

import jsonschema


def scene_files(path):
    path = pathlib.Path(path)
    if path.is_file():
        return [path]
    found = sorted(p for p in path.rglob("*") if p.suffix.lower() == ".json" and p.name != "hexray-expectations.json")
    return [p for p in found if loader_accepts(p)]


def loader_accepts(path):
    """A fuzz regression is a valid scene only when its pinned verdict says so."""
    expected = path.with_suffix(".expected")
    return not expected.exists() or expected.read_text(encoding="utf-8").strip() == "accepted"


def plain_document(stripper, path):
    result = subprocess.run([stripper, str(path)], capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise ValueError(result.stderr.strip())
    return json.loads(result.stdout)


def violations(validator, stripper, path):
    try:
        document = plain_document(stripper, path)
    except ValueError as error:
        return [str(error)]
    errors = sorted(validator.iter_errors(document), key=lambda e: list(map(str, e.absolute_path)))
    return [f"{path}: {'/'.join(str(p) for p in e.absolute_path) or '(root)'}: {e.message}" for e in errors]


def main():
    schema_path, stripper = sys.argv[1:3]
    valid, invalid, target = [], [], None
    for argument in sys.argv[3:]:
        if argument in ("--valid", "--invalid"):
            target = valid if argument == "--valid" else invalid
        else:
            target.append(argument)
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures, checked = [], 0
    for path in [p for given in valid for p in scene_files(given)]:
        failures += violations(validator, stripper, path)
        checked += 1
    for path in invalid:
        if not violations(validator, stripper, path):
            failures.append(f"{path}: the schema accepts it, but the loader rejects it")
        checked += 1
    for failure in failures:
        print(failure)
    print(f"{checked} scene files checked, {len(failures)} failures")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
