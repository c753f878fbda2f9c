#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and render the reference gallery
# (every milestone's demo scenes, drawn by the reference solution) into gallery/, printing
# each scene's error against its expected image and its render time.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
BUILD_DIR=$build bash "$root/tools/build.sh" --target reference_tool
"$build/checkpoints/reference_tool" gallery "$root/gallery"
