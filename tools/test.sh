#!/usr/bin/env bash
# Quick start, command 2: the project's full test suite. Builds everything it needs, then:
# the common library's unit tests; every checkpoint passes on the reference; every checkpoint
# fails on the generated skeleton; every deliberate bug is caught by the checkpoints it names;
# every correct variant passes; the skeletons and expected images match the solutions.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
BUILD_DIR=$build bash "$root/tools/build.sh" --target all project-tests
if ! ctest --test-dir "$build" -L project --output-on-failure --parallel "$(nproc)"; then
  # The grader's end-to-end tests run sandboxes with wall-clock limits; on a small machine
  # running two tests at a time they can starve. Every failed test runs again, alone, with its
  # output printed here at the end; the suite passes only if each passes then.
  echo "== the tests that failed, again, one at a time"
  ctest --test-dir "$build" --rerun-failed --output-on-failure
  echo "(they failed with other tests running and passed alone: see their first output above)"
fi
