"""Fails when a function defined in host/ is longer than 60 lines, signature to closing brace.

A definition is what starts at column 0 (namespaces are not indented in hexray) and opens a body:
free functions and member functions defined out of their class. Functions defined inside a class
body are short accessors by the house style and are not measured. Usage: function-size.py [FILES]
(default: every tracked .cpp and .h under host/).
"""
import re
import subprocess
import sys

LIMIT = 60
NOT_FUNCTIONS = re.compile(r"^(namespace|struct|class|enum|union|extern|template\s*<[^>]*>\s*(struct|class))\b")


def functions(path):
    """(first line, its number, line count) of every column-0 definition in `path`."""
    lines = open(path, encoding="utf-8").read().split("\n")
    start = None
    opened = False
    for number, line in enumerate(lines, 1):
        if start is None:
            if line[:1].isalpha() and not NOT_FUNCTIONS.match(line) and "(" in line:
                start, opened = number, False
            else:
                continue
        if not opened:
            if "{" in line:
                opened = True
            elif line.rstrip().endswith(";"):
                start = None  # a declaration, not a definition
                continue
        if opened and line.startswith("}"):
            yield lines[start - 1].strip(), start, number - start + 1
            start = None


def main():
    files = sys.argv[1:] or subprocess.run(
        ["git", "ls-files", "host/*.cpp", "host/*.h"], capture_output=True, text=True, check=True
    ).stdout.split()
    long = [(path, line, count, name) for path in files for name, line, count in functions(path) if count > LIMIT]
    for path, line, count, name in long:
        print(f"{path}:{line}: {count} lines (at most {LIMIT}): {name}")
    return 1 if long else 0


if __name__ == "__main__":
    sys.exit(main())
