#!/usr/bin/env bash
# Quick start, command 2: the project's full test suite. Builds everything it needs, then:
# the common library's unit tests; every checkpoint passes on the reference; every checkpoint
# fails on the generated skeleton; every deliberate bug is caught by the checkpoints it names;
# every correct variant passes; the skeletons and expected images match the solutions.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
BUILD_DIR=$build bash "$root/tools/build.sh" --target all project-tests
# No test is retried: one that fails only when other tests run beside it is a defect to fix.
ctest --test-dir "$build" -L project --output-on-failure --parallel "$(nproc)"
