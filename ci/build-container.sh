#!/usr/bin/env bash
# Usage: ci/build-container.sh [IMAGE]     (default: localhost/hexray:latest)
#
# Builds hexray's container image from Debian 12 packages only and renders the demo inside it:
#  1. the base: Debian's own bookworm made by mmdebstrap (minbase) and imported into podman as
#     localhost/hexray-debian:bookworm; made once, kept (HEXRAY_REBUILD_BASE=1 makes it again);
#  2. the image, from ci/container/Containerfile, with the committed tree (git archive HEAD) as its
#     context: no build directories, and the revision --version names is the one it was built from;
#  3. `IMAGE render /scenes/lecture-demo.json -o /out/demo.png` with no network, and a check that the
#     PNG has the scene's size. The picture is left at $TMPDIR/hexray-container-demo.png.
# Needs root (or rootless podman set up), podman, mmdebstrap, git, python3 and Debian's mirror;
# takes minutes, so it is not part of CI. HEXRAY_DEBIAN_MIRROR and HEXRAY_DEBIAN_SECURITY_MIRROR
# name other mirrors. docs/install.md explains.
set -euo pipefail
cd "$(dirname "$0")/.."

image=${1:-localhost/hexray:latest}
base=localhost/hexray-debian:bookworm
mirror=${HEXRAY_DEBIAN_MIRROR:-http://deb.debian.org/debian}
security_mirror=${HEXRAY_DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security}
demo_out=${TMPDIR:-/tmp}/hexray-container-demo.png

for tool in podman mmdebstrap git python3; do
  command -v "$tool" >/dev/null || { echo "build-container.sh: $tool is missing (apt-get install $tool)" >&2; exit 2; }
done

# What podman needs where a sandbox denies what it assumes. Resource limits no higher than this
# shell's: without CAP_SYS_RESOURCE podman's defaults (nofile 1048576) cannot be set, and podman
# itself lowers nproc to 32768 before starting the runtime. runc where the cgroups are a v1/v2
# hybrid with controllers on v2, which crun refuses ("cgroups in hybrid mode not supported").
podman_options=(--ulimit "nofile=$(ulimit -Hn):$(ulimit -Hn)")
nproc=$(ulimit -Hu)
if [ "$nproc" = unlimited ] || [ "$nproc" -gt 32768 ]; then nproc=32768; fi
podman_options+=(--ulimit "nproc=$nproc:$nproc")
if [ -n "$(cat /sys/fs/cgroup/unified/cgroup.controllers 2>/dev/null)" ]; then  # cgroupfs files show size 0
  command -v runc >/dev/null || { echo "build-container.sh: hybrid cgroups need runc (apt-get install runc)" >&2; exit 2; }
  podman_options+=(--runtime runc)
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ -n "${HEXRAY_REBUILD_BASE:-}" ] || ! podman image exists "$base"; then
  echo "== base: mmdebstrap bookworm from $mirror"
  start=$SECONDS
  mmdebstrap --variant=minbase --format=tar bookworm "$work/base.tar" \
    "deb $mirror bookworm main" "deb $mirror bookworm-updates main" "deb $security_mirror bookworm-security main"
  podman import --quiet "$work/base.tar" "$base" >/dev/null
  rm "$work/base.tar"
  echo "== base: $base in $((SECONDS - start)) s"
fi

if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "build-container.sh: note: uncommitted changes are not in the image (it is built from HEAD)" >&2
fi
revision=$(git rev-parse --short=12 HEAD)
mkdir "$work/context"
git archive HEAD | tar -x -C "$work/context"

echo "== image: $image from $revision"
start=$SECONDS
podman build "${podman_options[@]}" --build-arg "BASE=$base" --build-arg "HEXRAY_SOURCE_REVISION=$revision" \
  --build-arg "JOBS=$(nproc)" -f ci/container/Containerfile -t "$image" "$work/context"
echo "== image: built in $((SECONDS - start)) s"

echo "== render: the demo inside $image"
mkdir "$work/out"
start=$SECONDS
podman run --rm "${podman_options[@]}" --network none -v "$PWD/scenes:/scenes:ro" -v "$work/out:/out" \
  "$image" render /scenes/lecture-demo.json -o /out/demo.png
echo "== render: $((SECONDS - start)) s from podman run to exit"

python3 - "$work/out/demo.png" scenes/lecture-demo.json <<'EOF'
import json, struct, sys
png, scene = sys.argv[1], json.load(open(sys.argv[2]))
with open(png, "rb") as f:
    header = f.read(24)
if header[:8] != b"\x89PNG\r\n\x1a\n" or header[12:16] != b"IHDR":
    sys.exit(f"build-container.sh: {png} is not a PNG")
size = struct.unpack(">II", header[16:24])
expected = (scene["image"]["width"], scene["image"]["height"])
if size != expected:
    sys.exit(f"build-container.sh: demo.png is {size[0]}x{size[1]}, the scene says {expected[0]}x{expected[1]}")
print(f"== demo.png: {size[0]}x{size[1]}, as the scene says")
EOF
cp "$work/out/demo.png" "$demo_out"
echo "== $image renders; the demo is at $demo_out"
