#!/usr/bin/env bash
# The house style, checked (CI runs it, after ci/build.sh): clang-format (.clang-format) over the
# C++ of host/ and tests/, no function in host/ over 60 lines (ci/function-size.py), and
# clang-tidy's short list of checks (.clang-tidy) over host/, one translation unit per layer
# (ci/tidy.py), from the compile commands of the build in build/. Any finding fails.
set -euo pipefail
cd "$(dirname "$0")/.."

git ls-files 'host/*.cpp' 'host/*.h' 'tests/*.cpp' 'tests/*.h' | xargs clang-format-14 --dry-run --Werror
python3 ci/function-size.py
python3 ci/tidy.py build
