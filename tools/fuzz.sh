#!/usr/bin/env bash
# Fuzzes the milestones' code with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
# (clang), each milestone for a given time, and stops at the first crash, undefined behaviour,
# write outside an image, broken promise of a header, or input slower than 500 ms.
#
#   bash tools/fuzz.sh [--seconds N] [--student] [--build DIR] [m1 m2 m3 m4 m5]
#
# --seconds N: per milestone (default: $FUZZ_SECONDS, else 60). --student: fuzz your own code
# (milestone folders) instead of the reference (or FUZZ_STUDENT=1). --build DIR: the clang
# build folder (default build-fuzz). `make fuzz` and `make fuzz-m4` in a build folder run this.
# New interesting inputs go to DIR/corpus/<m>; a failing input is saved under
# DIR/artifacts/<m>/ and named at the end. Keep it: copy it into tools/fuzz/regressions/<m>/
# once the bug is fixed, and the test suite replays it for ever.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${FUZZ_SECONDS:-60}
student=${FUZZ_STUDENT:-0}
build="$root/build-fuzz"
milestones=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --student) student=1; shift ;;
    --build) build=$2; shift 2 ;;
    m1|m2|m3|m4|m5) milestones+=("$1"); shift ;;
    -h|--help) sed -n 2,15p "$0"; exit 0 ;;
    *) echo "fuzz.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ ${#milestones[@]} -gt 0 ] || milestones=(m1 m2 m3 m4 m5)
case "$seconds" in ''|*[!0-9]*) echo "fuzz.sh: --seconds wants a whole number, not '$seconds'" >&2; exit 2 ;; esac

if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ is missing. Run \`bash tools/install-deps.sh clang\` (or: sudo apt-get install clang libclang-rt-dev)" >&2
  exit 1
fi
runtime="$(clang++ -print-resource-dir)/lib/linux/libclang_rt.fuzzer-$(uname -m).a"
if [ ! -f "$runtime" ]; then
  echo "fuzz.sh: clang's libFuzzer runtime ($runtime) is missing. Run \`bash tools/install-deps.sh clang\`" >&2
  echo "         (or: sudo apt-get install libclang-rt-dev, or libclang-rt-<version>-dev)" >&2
  exit 1
fi

suffix=""
[ "$student" = 1 ] && suffix="_student"
targets=()
for m in "${milestones[@]}"; do targets+=("fuzz_${m}${suffix}"); done
if [ ! -f "$build/CMakeCache.txt" ]; then
  mkdir -p "$build"
  cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DRASTER_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    >"$build/configure.log" 2>&1 || { cat "$build/configure.log" >&2; exit 1; }
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}" || exit 1

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
summary=()
for m in "${milestones[@]}"; do
  exe="$build/tools/fuzz/fuzz_${m}${suffix}"
  work="$build/corpus/${m}${suffix}" artifacts="$build/artifacts/${m}${suffix}" log="$build/logs/${m}${suffix}.log"
  mkdir -p "$work" "$artifacts" "$(dirname "$log")"
  echo "== fuzzing $m ($([ "$student" = 1 ] && echo "your code" || echo reference)) for $seconds s; log: $log"
  # -timeout (wall clock): a hang; the harness itself stops any input that takes more than
  # 500 ms of CPU time.
  "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=512 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$work" "$root/tools/fuzz/corpus/$m" >"$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  if [ $rc -eq 0 ]; then
    summary+=("$m: ${execs:-?} inputs, coverage ${cov:-?} edges, ${ft:-?} features: nothing found")
  else
    status=1
    found=$(ls -t "$artifacts" 2>/dev/null | head -1)
    grep -m 5 -E 'runtime error|ERROR: AddressSanitizer|fuzz: |^  look at: |deadly signal|timeout' "$log"
    summary+=("$m: FAILED after ${execs:-?} inputs; input: $artifacts/${found:-?} (replay: $exe $artifacts/${found:-?})")
  fi
done
echo "== fuzzing summary"
printf '%s\n' "${summary[@]}"
exit $status
