#!/usr/bin/env bash
# The grader's look at a student's code (tools/grading/check-submission) on everything that is
# legitimate: the reference, the skeleton, every deliberate bug and every correct variant of
# every milestone (srctool mutate), each preprocessed and compiled as the grader does it, must
# be accepted; and a few small attacks must be refused, each with the reason named.
#
#   check_submission_test.sh <build-dir>
set -euo pipefail
build=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
check="$root/tools/grading/check-submission"
work=$(mktemp -d /tmp/check-submission-test.XXXXXX)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

[ -f "$build/grading/kit.sh" ] || fail "no $build/grading/kit.sh (build the target grading)"
# shellcheck source=/dev/null
source "$build/grading/kit.sh"
srctool=$(find "$build/tools" -maxdepth 2 -type f -name srctool -perm -u+x | head -n 1)
[ -n "$srctool" ] || fail "no srctool in $build/tools (build the target srctool)"

# The kit's include folder, as the grader builds it.
kit=$work/kit; mkdir -p "$kit/include"
cp -R "$root/common/include/." "$kit/include/"
for d in milestone1_lines milestone2_triangles milestone3_transforms milestone4_depth_lighting milestone5_textures_shadows; do cp "$root/$d"/*.h "$kit/include/"; done
mapfile -t system_includes < <(# shellcheck disable=SC2086
  $KIT_CXX $KIT_CXXFLAGS -x c++ -E -v /dev/null 2>&1 >/dev/null |
  sed -n '/^#include <...> search starts here:/,/^End of search list\./{s/^ //p}')

# try <name> <source> [extra compiler flags]: prints the refusals; exit 1 when refused.
# With $prebuilt naming a static library of the build that holds exactly this source's object
# (the checkpoint programs' own, built with the same flags), its object is checked instead of
# compiling the source again (the suite builds them anyway; compiling ~90 sources is slow).
prebuilt=""
try() {
  local name=$1 src=$2; shift 2
  local w=$work/$name file o
  file=$(basename "$src")
  mkdir -p "$w"; cp "$src" "$w/$file"
  # shellcheck disable=SC2086
  (cd "$w" && $KIT_CXX $KIT_CXXFLAGS "$@" -I"$kit/include" -E -dD -o "$file.ii" "$file") || { echo "does not preprocess"; return 1; }
  "$check" preprocessed "$w/$file.ii" "$w" "$kit/include" "${system_includes[@]}" || return 1
  local fresh=0 dep
  if [ -n "$prebuilt" ] && [ -f "$prebuilt" ]; then
    fresh=1
    for dep in "${prebuilt_deps[@]}"; do [ "$prebuilt" -nt "$dep" ] || fresh=0; done
  fi
  if [ "$fresh" = 1 ]; then
    mkdir "$w/ar" && (cd "$w/ar" && ar x "$prebuilt")
    for o in "$w/ar"/*.o; do "$check" object "$o" || return 1; done
    prebuilt_used=$((prebuilt_used + 1))
    return 0
  fi
  # shellcheck disable=SC2086
  (cd "$w" && $KIT_CXX $KIT_CXXFLAGS "$@" -w -I"$kit/include" -c -o "$file.o" "$file") || { echo "does not compile"; return 1; }
  "$check" object "$w/$file.o" || return 1
}
prebuilt_used=0 prebuilt_deps=()

checked=0
declare -A solution=([m1]=milestone1_lines/lines.cpp [m2]=milestone2_triangles/triangles.cpp
                     [m3]=milestone3_transforms/transforms.cpp [m4]=milestone4_depth_lighting/depth_lighting.cpp
                     [m5]=milestone5_textures_shadows/textures_shadows.cpp)
for m in m1 m2 m3 m4 m5; do
  src=${solution[$m]}
  prebuilt=$build/checkpoints/lib${m}_reference.a prebuilt_deps=("$root/solutions/$src")
  try "$m-reference" "$root/solutions/$src" || fail "the reference of $m is refused (above)"
  prebuilt=$build/checkpoints/lib${m}_impl_student.a prebuilt_deps=("$root/$src")
  try "$m-skeleton" "$root/$src" -Wno-unused-parameter || fail "the skeleton of $m is refused (above)"
  checked=$((checked + 2))
  for mutation in "$root/checkpoints/$m/bugs/"*.bug "$root/checkpoints/$m/variants/"*.variant; do
    [ -f "$mutation" ] || continue
    name=$m-$(basename "$mutation")
    mkdir -p "$work/gen/$name"
    "$srctool" mutate "$root/solutions/$src" "$mutation" "$work/gen/$name/$(basename "$src")" >/dev/null ||
      fail "srctool mutate failed for $mutation"
    flags=$(sed -n 's/^flags:[ ]*//p' "$mutation")
    kind=variant; [[ "$mutation" == *.bug ]] && kind=bug
    prebuilt=$build/checkpoints/lib${m}_impl_${kind}_$(basename "${mutation%.*}").a
    prebuilt_deps=("$root/solutions/$src" "$mutation")
    # shellcheck disable=SC2086
    try "$name" "$work/gen/$name/$(basename "$src")" $flags || fail "$mutation is refused (above)"
    checked=$((checked + 1))
  done
done
echo "accepted: $checked legitimate sources ($prebuilt_used objects from the build, the others compiled here)"
prebuilt=""

# Attacks, each refused for its reason.
ref=$root/solutions/milestone1_lines/lines.cpp
attack() {  # name expected-words -- code appended to the reference (or, with a leading !, put before it)
  local name=$1 expect=$2 code=$3 out
  mkdir -p "$work/attack-$name"
  if [[ "$code" == '!'* ]]; then { printf '%s\n' "${code:1}"; cat "$ref"; } >"$work/attack-$name/lines.cpp"
  else { cat "$ref"; printf '%s\n' "$code"; } >"$work/attack-$name/lines.cpp"; fi
  if out=$(try "a-$name" "$work/attack-$name/lines.cpp" 2>&1); then fail "attack $name was accepted"; fi
  grep -q -- "$expect" <<<"$out" || fail "attack $name: refused, but not for '$expect': $out"
  echo "refused ($name): $(head -n 1 <<<"$out")"
}
attack ofstream 'file access' '#include <fstream>
struct Later { ~Later() { std::ofstream("values.txt") << "stray_writes 0\n"; } } later;'
attack fopen 'fopen' '#include <cstdio>
void sneaky() { std::FILE* f = std::fopen("x", "w"); if (f) std::fclose(f); }'
# make check's note (tools/code-check --advice, the same object step): the fopen object above
# gets it, naming the call; the reference's gets none; neither fails the build.
bash "$root/tools/code-check" --advice milestone1_lines/lines.cpp "$work/a-fopen/lines.cpp.o" "$work/note.txt" ||
  fail "code-check --advice failed on a refused object"
note=$(cat "$work/note.txt" 2>/dev/null)
grep -q "Note: the grader would refuse milestone1_lines/lines.cpp" <<<"$note" && grep -q "fopen (file access)" <<<"$note" ||
  fail "make check's note does not name the refused call: $note"
bash "$root/tools/code-check" --advice milestone1_lines/lines.cpp "$build/checkpoints/libm1_reference.a" "$work/note.txt" ||
  fail "code-check --advice failed on the reference"
[ ! -e "$work/note.txt" ] || fail "make check's note speaks of the reference: $(cat "$work/note.txt")"
echo "make check's note names the refused call, and says nothing of the reference"
attack system 'processes' '#include <cstdlib>
void sneaky() { (void)std::system("true"); }'
attack syscall 'raw system calls' '#include <unistd.h>
#include <sys/syscall.h>
long sneaky() { return syscall(39); }'
attack asm 'inline assembly' 'long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }'
attack section '__attribute__' '__attribute__((section(".text"))) const unsigned char code[] = {0xc3};'
attack passwd '/etc/passwd' '#include "/etc/passwd"'
attack dotdot 'include of' '#include "../../../../../../etc/hostname"'
attack line_rename '#line' '#line 1 "/usr/include/stdio.h"
long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }'
attack macro_header 'changes that header' '!#define count_stray_write() count_nothing()'
# A GCC line marker written by hand would make the lines after it pass for a system header's
# (flag 3), where nothing is checked; so would one spliced, after a comment, or as a digraph.
attack line_marker 'line directive' '# 1 "/usr/include/stdio.h" 1 3 4
__attribute__((constructor)) static void before_main() {}
# 400 "lines.cpp" 2'
attack line_marker_spliced 'line directive' '#\
 1 "/usr/include/stdio.h" 1 3 4
long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }'
attack line_marker_comment 'line directive' '%:/*
*/ 1 "/usr/include/stdio.h" 1 3 4
long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }'
attack line_same_file 'line directive' '#line 1'
# A line inside a raw string that looks like a marker is a string to the compiler: the
# preprocessed file's lines after it are still the student's and still checked.
attack raw_string_marker 'inline assembly' 'const char* text = R"(
# 1 "/usr/include/stdio.h" 1 3 4
)";
long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }'
# Checked as tokens, not lines: split across lines, or spelled with digraphs.
attack split_attribute 'gnu::' '[[
gnu::constructor
]] static void before_main() {}'
attack digraph_attribute 'gnu::' '<:<:gnu::constructor:>:> static void before_main() {}'
attack split_namespace 'namespace' 'namespace
std { inline int mine = 1; }'
attack private_public 'changes that header' '!#define private public'
attack raster_namespace 'namespace' 'namespace raster { long my_strays() { return 0; } }'
attack stray_total 'harness' 'long sneaky() { return raster::Image::total_stray_writes(); }'
# The render half's own code (m1cp::student::render saves the artifacts), and the program's
# allocator, even as an inline (weak) definition.
attack harness_render 'the harness' 'namespace m1cp { namespace student { int render(const std::string&) { return 0; } } }'
attack inline_new 'allocator' '#include <cstdlib>
inline void* operator new(std::size_t n) { return std::malloc(n ? n : 1); }
void* (*sneaky)(std::size_t) = ::operator new;  // its address: the inline one is emitted (weak)'
attack interpose 'defines write' 'extern "C" long write(int, const void*, unsigned long) { return 0; }'
attack thread 'threads' '#include <thread>
void sneaky() { std::thread([] {}).detach(); }'
attack dlopen 'loading code' '#include <dlfcn.h>
void* sneaky() { return dlopen("libc.so.6", 0); }'
attack mprotect 'memory mapping' '#include <sys/mman.h>
int sneaky(void* p) { return mprotect(p, 4096, 7); }'
attack png 'file access' '#include "raster/io.h"
void sneaky(const raster::Image& img) { raster::write_png("x.png", img); }'
# A header beside the source with a % in its name is still the student's own: its lines are
# checked like the source's (the grader takes only the rubric's files; check-submission does not
# rely on that). The header is put where try() compiles the source.
mkdir -p "$work/a-percent"
printf '%s\n' 'long sneaky() { long r; asm volatile("syscall" : "=a"(r) : "a"(39)); return r; }' >"$work/a-percent/a%b.h"
attack percent 'inline assembly' '#include "a%b.h"'
echo "ok"
