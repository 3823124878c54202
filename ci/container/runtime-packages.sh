#!/usr/bin/env bash
# Usage: runtime-packages.sh BINARY
# Prints, one a line, the Debian packages owning the shared libraries BINARY links (as ldd finds
# them): what a runtime image must install for it. Fails naming any library not found or not
# owned by a package.
set -euo pipefail
binary=$1

owner() {  # bookworm's merged /usr: dpkg may know a library by /lib or by /usr/lib
  local path=$1 candidate
  for candidate in "$path" "$(realpath "$path")" "/usr$path" "${path#/usr}"; do
    dpkg-query -S "$candidate" 2>/dev/null | head -n 1 | cut -d: -f1 && return 0
  done
  echo "runtime-packages.sh: no package owns $path, which $binary links" >&2
  return 1
}

libraries=$(ldd "$binary")
if grep -q 'not found' <<<"$libraries"; then
  echo "runtime-packages.sh: $binary links libraries that are not installed:" >&2
  grep 'not found' <<<"$libraries" >&2
  exit 1
fi
awk '$2 == "=>" && $3 ~ /^\// { print $3 }' <<<"$libraries" | while read -r library; do
  owner "$library" || exit 1
done | sort -u
