#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and render the reference gallery
# (every milestone's demo scenes, drawn by the reference solution) into gallery/, printing
# each scene's error against its expected image and its render time. It also builds the
# interactive viewer (build/tools/viewer/viewer), where SDL2 is installed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
bash "$root/tools/install-deps.sh"  # first, so that SDL2 is there to be found
targets=(reference_tool)
if pkg-config --exists sdl2 2>/dev/null; then targets+=(viewer); fi
BUILD_DIR=$build bash "$root/tools/build.sh" --target "${targets[@]}"
"$build/checkpoints/reference_tool" gallery "$root/gallery"
