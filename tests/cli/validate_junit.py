#!/usr/bin/python3
"""Checks `hexray compare --junit` output: valid against tests/cli/junit.xsd, and every suite's
tests/failures/errors/skipped attributes equal to what its test cases hold.

usage: validate_junit.py SCHEMA DOCUMENT
Exit 0 and no output when it is valid; exit 1 and each problem when not. Run by /usr/bin/python3
(python3-lxml is a Debian package of the system interpreter).
"""
import sys

from lxml import etree


def count_problems(suite):
    cases = suite.findall(".//testcase")
    found = {
        "tests": len(cases),
        "failures": sum(1 for c in cases if c.find("failure") is not None),
        "errors": sum(1 for c in cases if c.find("error") is not None),
        "skipped": sum(1 for c in cases if c.find("skipped") is not None),
    }
    return [f"<{suite.tag} name={suite.get('name')!r}>: {key}={suite.get(key)} but its test cases hold {value}"
            for key, value in found.items() if int(suite.get(key)) != value]


def main():
    schema = etree.XMLSchema(etree.parse(sys.argv[1]))
    document = etree.parse(sys.argv[2], etree.XMLParser(resolve_entities=False, no_network=True))
    problems = [f"{sys.argv[2]}:{e.line}: {e.message}" for e in schema.error_log] if not schema.validate(document) else []
    if not problems:
        root = document.getroot()
        for suite in [root] + root.findall("testsuite"):
            problems += count_problems(suite)
    for problem in problems:
        print(problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
