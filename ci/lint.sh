#!/usr/bin/env bash
# The house style, checked (CI runs it): clang-format (.clang-format) over the C++ of host/ and
# tests/, and no function in host/ over 60 lines (ci/function-size.py). Any finding fails.
#
# bash ci/lint.sh --tidy adds clang-tidy (.clang-tidy, a short list of checks) over host/, from
# the compile commands of the build in build/. It is not part of CI: it reads every file with
# Vulkan-Hpp's headers and took over 7 minutes on 2 cores, more than CI's time allows.
set -euo pipefail
cd "$(dirname "$0")/.."

git ls-files 'host/*.cpp' 'host/*.h' 'tests/*.cpp' 'tests/*.h' | xargs clang-format-14 --dry-run --Werror
python3 ci/function-size.py

if [ "${1:-}" = --tidy ]; then
  # CMake's precompiled headers are GCC's: clang-tidy reads the sources without them.
  mkdir -p build/tidy
  sed -e 's/ -include [^ ]*cmake_pch\.hxx//g' -e 's/ -Winvalid-pch//g' build/compile_commands.json \
    > build/tidy/compile_commands.json
  # Only the files this build compiles (Embree's only where it was found).
  files=$(git ls-files 'host/*.cpp' | while read -r f; do grep -q "\"file\": \"$PWD/$f\"" build/tidy/compile_commands.json && echo "$f"; done)
  echo "$files" | xargs -P "$(nproc)" -n 4 clang-tidy-14 -p build/tidy --quiet
fi
