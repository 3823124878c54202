#!/usr/bin/python3
"""Runs every command of the ```sh code blocks of the README (and the other documents named) as
pasted, so that they cannot go stale.

Each document's commands run in order, in a scratch directory of their own that looks like the
repository's root after a build: a copy of scenes/, and build/hexray, a link to the executable
under test. A command passes when it exits with 0 and every output it names exists, written by
it. A block is skipped only when the line before it is an HTML comment starting with
"<!-- setup:" (the README's install-and-build commands); a document without a command to run
fails, so the test cannot pass by running nothing.

Usage: readme_commands_test.py --hexray PATH --source REPOSITORY DOCUMENT...
"""

import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

SKIP_MARKER = "<!-- setup:"
# Options whose value is a file or directory the command writes.
OUTPUT_OPTIONS = {"-o", "--diff", "--mask", "--json", "--junit", "--report", "--aov", "--csv", "--heatmap"}
SHELL_OPERATORS = {"&&", "||", ";", "|", "&"}


@dataclass
class Block:
    document: str
    line: int
    commands: list


def code_blocks(path):
    """(language, first line number, lines, skipped) of each fenced block of a Markdown file."""
    lines = path.read_text(encoding="utf-8").split("\n")
    blocks, index = [], 0
    while index < len(lines):
        fence = re.match(r"^```(\S*)", lines[index])
        if not fence:
            index += 1
            continue
        previous = next((line for line in reversed(lines[:index]) if line.strip()), "")
        end = next(i for i in range(index + 1, len(lines)) if lines[i].startswith("```"))
        blocks.append((fence.group(1), index + 2, lines[index + 1:end], previous.startswith(SKIP_MARKER)))
        index = end + 1
    return blocks


def commands_of(lines):
    """The commands of a shell block: one a line, a trailing backslash continuing it, comments dropped."""
    commands, pending = [], ""
    for line in lines:
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        command = (pending + line).strip()
        pending = ""
        if command and not command.startswith("#"):
            commands.append(command)
    return commands


def segments(command):
    """The simple commands of a command line, as word lists (shell operators split them)."""
    lexer = shlex.shlex(command, posix=True, punctuation_chars=True)
    lexer.whitespace_split = True
    lexer.commenters = "#"
    words, result = [], []
    for token in lexer:
        if token in SHELL_OPERATORS:
            result.append(words)
            words = []
        else:
            words.append(token)
    result.append(words)
    return [words for words in result if words]


def named_outputs(command):
    """The paths a hexray command line says it writes (those with shell expansions left out)."""
    outputs = []
    for words in segments(command):
        if not words[0].endswith("hexray"):
            continue
        subcommand = next((word for word in words[1:] if not word.startswith("-")), "")
        has_output_option = False
        for option, value in zip(words, words[1:]):
            if option in OUTPUT_OPTIONS:
                outputs.append(value)
                has_output_option = has_output_option or option == "-o"
        if subcommand == "merge":
            outputs.append(words[words.index("merge") + 1])
        elif subcommand == "render" and not has_output_option:
            outputs += [Path(word).stem + ".png" for word in words if word.endswith(".json")]
    return [output for output in outputs if output != "-" and not re.search(r"[$*?\[`]", output)]


def check_output(directory, output, started):
    """None when the output exists and was written after `started`, else what is wrong with it."""
    path = directory / output
    if not path.exists():
        return f"{output} does not exist"
    if path.is_dir():
        written = [entry for entry in path.rglob("*") if entry.is_file() and entry.stat().st_mtime >= started]
        return None if written else f"{output}/ holds no file the command wrote"
    return None if path.stat().st_mtime >= started else f"{output} was not written by the command"


def scratch_directory(source, hexray):
    directory = Path(tempfile.mkdtemp(prefix="hexray-readme-"))
    shutil.copytree(source / "scenes", directory / "scenes")
    (directory / "build").mkdir()
    (directory / "build" / "hexray").symlink_to(hexray)
    return directory


def run_document(source, hexray, document):
    """Runs the document's commands; returns (commands run, skipped blocks, failures)."""
    blocks = code_blocks(source / document)
    runnable = [Block(document, line, commands_of(lines)) for language, line, lines, skip in blocks
                if language == "sh" and not skip]
    skipped = sum(1 for language, _, _, skip in blocks if language == "sh" and skip)
    directory = scratch_directory(source, hexray)
    environment = dict(os.environ, XDG_CACHE_HOME=str(directory / ".cache"))
    ran, failures = 0, []
    try:
        for block in runnable:
            for command in block.commands:
                started = time.time() - 1  # file systems with a coarse clock stamp a little early
                result = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", command], cwd=directory,
                                        env=environment, capture_output=True, text=True, timeout=900)
                ran += 1
                place = f"{document}:{block.line}: {command}"
                print(f"ran (exit {result.returncode}): {place}", flush=True)
                if result.returncode != 0:
                    failures.append(f"{place}\n  exit {result.returncode}\n  stderr: {result.stderr[-2000:]}"
                                    f"\n  stdout: {result.stdout[-2000:]}")
                    continue
                for output in named_outputs(command):
                    problem = check_output(directory, output, started)
                    if problem:
                        failures.append(f"{place}\n  {problem}")
    finally:
        shutil.rmtree(directory, ignore_errors=True)
    if ran == 0:
        failures.append(f"{document}: no command to run (no ```sh block without a setup marker)")
    return ran, skipped, failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hexray", required=True, type=Path, help="the executable under test")
    parser.add_argument("--source", required=True, type=Path, help="the repository's root")
    parser.add_argument("documents", nargs="+", help="Markdown files, relative to the repository's root")
    arguments = parser.parse_args()
    hexray = arguments.hexray.resolve()
    if not os.access(hexray, os.X_OK):
        print(f"readme_commands_test: {hexray} is not an executable", file=sys.stderr)
        return 1
    all_failures = []
    for document in arguments.documents:
        ran, skipped, failures = run_document(arguments.source.resolve(), hexray, document)
        print(f"{document}: ran {ran} commands, {len(failures)} failed; {skipped} setup blocks not run")
        all_failures += failures
    for failure in all_failures:
        print(f"FAILED: {failure}", file=sys.stderr)
    return 1 if all_failures else 0


if __name__ == "__main__":
    sys.exit(main())
