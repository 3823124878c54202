#!/usr/bin/env bash
# cmake --preset PRESET [ARGS...], in the preset's build directory (CMakePresets.json: build/ for
# release, build-PRESET/ for the others). A directory configured with another generator (Make,
# before the presets named Ninja) has its cache forgotten first: CMake refuses to switch.
set -euo pipefail
cd "$(dirname "$0")/.."

preset=$1
directory=build
[ "$preset" = release ] || directory=build-$preset
if [ -f "$directory/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$directory/CMakeCache.txt"; then
  rm -rf "$directory/CMakeCache.txt" "$directory/CMakeFiles"
fi
cmake --preset "$@"
