#!/usr/bin/env bash
# Installs the Debian 12 packages hexray needs.
#   (no argument)  everything to build, render and test
#   --render       only what building and running the `hexray` executable needs (ci/render-demo.sh)
#   --bench        everything, and what only tools/bench-report.sh and tools/scale-bench.sh use:
#                  Embree 3 (the bench's optional yardstick) and matplotlib (the plot)
# Idempotent: safe to run again; apt skips what is already installed.
set -euo pipefail

# Building and running hexray.
packages=(
  g++ make ninja-build cmake pkg-config  # Ninja: the presets' build tool
  libvulkan-dev mesa-vulkan-drivers glslang-tools
  glslang-dev spirv-tools  # glslang as a library: generated kernels are compiled at run time
  libglm-dev libstb-dev libspng-dev libopenexr-dev nlohmann-json3-dev libcli11-dev
  libxml2-dev  # compare --junit: the XML writer
  libssl-dev  # OpenSSL's libcrypto: SHA-256 of the kernel cache's files and the strips' pixels
  git  # the build records the revision it was configured from
)
# The tests and CI.
test_packages=(
  vulkan-validationlayers vulkan-tools libgtest-dev
  libmpfr-dev  # the tests' exact accuracy oracle (tests/oracle/)
  python3-lxml  # validates compare --junit output against tests/cli/junit.xsd; parses --report's page
  chromium  # the tests load compare --report's page in headless chromium (tests/cli/check_report.py)
  python3-jsonschema  # validates every command's --json output against docs/schemas/ in the tests
  python3-yaml  # the test that parses docs/scale-out.md's manifests (tests/cli/scale_out_commands.py)
  clang-14 libclang-rt-14-dev  # the fuzzers: clang with libFuzzer and its sanitizers
  clang-format-14 clang-tidy-14  # ci/lint.sh: the house style
  help2man  # `cmake --install`'s man page, made from hexray's own --help (cmake/man_page.cmake)
)
case "${1:-}" in
  --render) ;;
  --bench) packages+=("${test_packages[@]}" libembree-dev python3-matplotlib) ;;
  "") packages+=("${test_packages[@]}") ;;
  *) echo "usage: $0 [--render | --bench]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
