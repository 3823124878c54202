#!/usr/bin/python3
"""Validates a hexray --json document against docs/schemas/hexray-results.schema.json.

usage: validate_json.py SCHEMA DOCUMENT
Exit 0 and no output when it is valid; exit 1 and every violation (path and message) when not.
Run by /usr/bin/python3: python3-jsonschema is a Debian package of the system interpreter.
"""
import json
import sys

import jsonschema


def main():
    schema_path, document_path = sys.argv[1:3]
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    with open(document_path, encoding="utf-8") as f:
        document = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path))
    for error in errors:
        where = "/".join(str(part) for part in error.absolute_path) or "(document)"
        print(f"{document_path}: {where}: {error.message}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
