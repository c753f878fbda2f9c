#!/usr/bin/env bash
# The student handout (tools/export-handout) end to end: it holds no solution, bug, variant or
# grader; it builds from scratch; `make check` runs every checkpoint (all failing on the
# skeleton); and with a milestone's model answer dropped in, that milestone's checkpoints pass.
set -euo pipefail
# Any step that fails says which: a bare `set -e` exit would leave the suite's log without a cause.
trap 'echo "handout test: line $LINENO failed (exit $?): $BASH_COMMAND" >&2' ERR
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$1
work=$(mktemp -d /tmp/handout-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
# The reference archives come as `make all` left them: the suite runs other tests from this build
# folder meanwhile, so this test never builds in it (the archives' recipe is checked by CI's build).
bash "$root/tools/export-handout" "$work/handout" --build "$build" --no-build
h=$work/handout
for gone in solutions tools/grading checkpoints/grader.cpp checkpoints/m1/bugs checkpoints/m1/variants \
           checkpoints/m3/judge.cpp checkpoints/m5/judge.cpp checkpoints/m5/bench.cpp checkpoints/bench_reference.cpp \
           checkpoints/m5/oracle_tests.cpp tools/test.sh; do
  [ ! -e "$h/$gone" ] || { echo "the handout has $gone"; exit 1; }
done
[ -z "$(find "$h" -name '*.bug' -o -name '*.variant' -o -name 'hidden.json')" ] || { echo "the handout has bugs, variants or hidden checkpoints"; exit 1; }
# The judges come compiled: no judge's source, every judge's archive.
[ -z "$(find "$h" -name 'judge.cpp' -o -name 'bench*.cpp')" ] || { echo "the handout has a judge's or a benchmark's source"; exit 1; }
for m in m1 m2 m3 m4 m5; do
  [ -f "$h/checkpoints/prebuilt/lib${m}_judge.a" ] || { echo "the handout has no prebuilt judge of $m"; exit 1; }
done
# Its README is the students' part of the course's: no sections for instructors or maintainers.
grep -q "students' copy" "$h/README.md" || { echo "the handout's README does not say what it is"; exit 1; }
grep -q "## For students" "$h/README.md" || { echo "the handout's README lost its section for students"; exit 1; }
! grep -qE "^## For (instructors|maintainers)" "$h/README.md" || { echo "the handout's README keeps a section for instructors or maintainers"; exit 1; }
# No file of the handout is a solution file, under any name.
for s in "$root"/solutions/*/*.cpp; do
  sum=$(sha256sum <"$s")
  while IFS= read -r -d '' f; do
    [ "$(sha256sum <"$f")" != "$sum" ] || { echo "$f is the solution $s"; exit 1; }
  done < <(find "$h" -type f -name '*.cpp' -print0)
done
# The default build's code (-O2) without debug information, which makes the build take half as
# long again; CI's Debian 13 stage builds a handout in the default configuration.
cmake -S "$h" -B "$h/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$h/build" -j2 >"$work/build.log" 2>&1 || { tail -n 40 "$work/build.log"; exit 1; }
if make -C "$h/build" check >"$work/check.log" 2>&1; then echo "make check passed on the skeleton"; exit 1; fi
# Every checkpoint of every milestone ran (the trusted list of the handout's own build).
total=0
for m in $(cd "$h" && ls -d milestone*_* | sed 's/^milestone\([0-9]*\)_.*/m\1/'); do
  total=$((total + $("$h/build/checkpoints/checkpoint_ids" "$m" | grep -c .)))
done
[ "$total" -gt 100 ] || { echo "only $total checkpoints listed"; exit 1; }
grep -q "0 passed, $total failed" "$work/check.log" || { tail -n 20 "$work/check.log"; echo "make check did not run every checkpoint ($total)"; exit 1; }
cp "$root/solutions/milestone1_lines/lines.cpp" "$h/milestone1_lines/lines.cpp"
make -C "$h/build" check-m1 >"$work/check-m1.log" 2>&1 || { tail -n 30 "$work/check-m1.log"; exit 1; }
grep -q "All checkpoints pass" "$work/check-m1.log" || { tail -n 20 "$work/check-m1.log"; exit 1; }
# `make bench` says where it lives rather than failing.
make -C "$h/build" bench >"$work/bench.log" 2>&1 || { cat "$work/bench.log"; echo "make bench failed in the handout"; exit 1; }
grep -q "belongs to the instructor's repository" "$work/bench.log" || { cat "$work/bench.log"; echo "make bench in the handout does not say where it lives"; exit 1; }
# Where SDL2 is installed, the viewer is built in the handout too, and its start-up check finds
# the student's milestone 1 (the solution copied above, rebuilt) and the reference for the rest.
if pkg-config --exists sdl2 2>/dev/null; then
  cmake --build "$h/build" --target viewer >"$work/viewer-build.log" 2>&1 || { tail -n 30 "$work/viewer-build.log"; exit 1; }
  SDL_VIDEODRIVER=dummy timeout 60 "$h/build/tools/viewer/viewer" --probe >"$work/probe.log" 2>&1 ||
    { cat "$work/probe.log"; echo "the handout's viewer failed its start-up check"; exit 1; }
  grep -q "m1 lines: yours" "$work/probe.log" || { cat "$work/probe.log"; echo "the handout's viewer did not find milestone 1"; exit 1; }
  grep -q "m2 triangles: reference" "$work/probe.log" || { cat "$work/probe.log"; echo "the handout's viewer took the skeleton of milestone 2"; exit 1; }
fi
echo "the handout builds, and make check works in it"
