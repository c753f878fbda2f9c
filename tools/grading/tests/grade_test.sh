#!/usr/bin/env bash
# The grader's own tests (CTest label `project`): tools/grading/grade on the reference, the
# skeleton, a compile error, a sample of the deliberate bugs, and hostile submissions.
#
#   grade_test.sh <case> <build-dir> <uid>
#
# Each case grades into a fresh folder with its own sandbox uid and its own temporary root
# (RASTER_GRADE_TMP), so cases can run in parallel; afterwards no process of that uid and no
# file in that root may be left, and the expected images and the judge must be unchanged.
# Exit 0: the case holds; 77: skipped (no sandbox here); anything else: a failure, explained.
# The whole script is one block, read before any of it runs: bash reads a script as it goes, so
# editing this file in place while it runs would otherwise change (or break) a run in progress.
{
set -euo pipefail
case_name=$1 build=$2 uid=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
grade="$root/tools/grading/grade"
work=$(mktemp -d /tmp/grade-test.XXXXXX)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
chmod 711 "$work"
export RASTER_GRADE_TMP=$work/tmp
mkdir -m 711 "$RASTER_GRADE_TMP"
fail() {
  echo "FAIL ($case_name): $*" >&2
  # The grader's own log, when this case kept one, says why.
  if [ -f "$work/log" ]; then echo "--- the grader's log (last 40 lines):" >&2; tail -n 40 "$work/log" >&2; fi
  exit 1
}

if [ "$(id -u)" != 0 ]; then echo "skipped: the grader's tests need root (a sandbox uid)"; exit 77; fi

# A submission folder with each milestone's file: from solutions/, the skeleton, or given.
make_submission() {  # dir [m1-file] [m2-file] [m3-file] [m4-file] [m5-file]
  local dir=$1
  mkdir -p "$dir/milestone1_lines" "$dir/milestone2_triangles" "$dir/milestone3_transforms" "$dir/milestone4_depth_lighting" \
    "$dir/milestone5_textures_shadows"
  cp "${2:-$root/solutions/milestone1_lines/lines.cpp}" "$dir/milestone1_lines/lines.cpp"
  cp "${3:-$root/solutions/milestone2_triangles/triangles.cpp}" "$dir/milestone2_triangles/triangles.cpp"
  cp "${4:-$root/solutions/milestone3_transforms/transforms.cpp}" "$dir/milestone3_transforms/transforms.cpp"
  cp "${5:-$root/solutions/milestone4_depth_lighting/depth_lighting.cpp}" "$dir/milestone4_depth_lighting/depth_lighting.cpp"
  cp "${6:-$root/solutions/milestone5_textures_shadows/textures_shadows.cpp}" "$dir/milestone5_textures_shadows/textures_shadows.cpp"
}
# score <results.json> [test-name-prefix]: the points earned (of tests with that prefix).
score() { python3 -c "
import json,sys
r=json.load(open(sys.argv[1])); p=sys.argv[2] if len(sys.argv)>2 else ''
s=sum(t['score'] for t in r['tests'] if t['name'].startswith(p)); print(int(s) if s==int(s) else s)" "$@"; }
max_score() { python3 -c "
import json,sys
r=json.load(open(sys.argv[1])); p=sys.argv[2] if len(sys.argv)>2 else ''
s=sum(t['max_score'] for t in r['tests'] if t['name'].startswith(p)); print(int(s) if s==int(s) else s)" "$@"; }

# The command-line marker of the hostile children this test starts (outliving_children.cpp): its
# own, since another test's children may be alive while this one looks for survivors.
marker=raster-hostile-marker-$uid

fingerprint() {
  (cd "$root/checkpoints/expected" && find . -type f -print0 | sort -z | xargs -0 sha256sum)
  sha256sum "$build/checkpoints/raster_grade" "$root/tools/grading/grade" "$root/tools/grading/sandbox-run"
}
before=$(fingerprint)
check_clean() {
  if pgrep -u "$uid" >/dev/null 2>&1; then fail "processes of the sandbox uid $uid are left: $(pgrep -u "$uid" -a)"; fi
  if pgrep -f "$marker" >/dev/null 2>&1; then fail "a hostile child survived: $(pgrep -af "$marker")"; fi
  [ -z "$(ls -A "$RASTER_GRADE_TMP")" ] || fail "files left in the grader's temporary root: $(ls -A "$RASTER_GRADE_TMP")"
  local places=(/tmp /var/tmp /dev/shm /run/lock /var/lock /dev/mqueue) left
  left=$(find "${places[@]}" -xdev -user "$uid" 2>/dev/null | head -n 3 || true)
  [ -z "$left" ] || fail "files of the sandbox uid left: $left"
  left=$(ipcs -m -q -s 2>/dev/null | awk -v u="$uid" '$3 == u' || true)
  [ -z "$left" ] || fail "System V IPC objects of the sandbox uid left: $left"
  [ "$before" = "$(fingerprint)" ] || fail "the expected images, the judge or the grader changed"
}

# with_private_tree CMD...: CMD in a mount namespace of its own in which the repository and the
# build folder are root's only (mode 0700), as the instructor must keep them where the sandbox
# hides files by permissions only (unshare, plain); the real folders are left as they are. In
# that namespace each folder is an empty 0700 tmpfs holding binds of its real entries.
with_private_tree() {
  local hidden=("$root")
  case "$build/" in "$root"/*) ;; *) hidden+=("$build") ;; esac
  mkdir -m 700 "$work/hold"
  unshare --mount --propagation private -- bash -c '
    set -e; hold=$1; n=$2; shift 2
    for ((i = 0; i < n; i++)); do
      d=$1; shift
      mkdir "$hold/$i"; mount --bind "$d" "$hold/$i"
      mount -t tmpfs -o mode=0700 tmpfs "$d"
      for e in "$hold/$i"/* "$hold/$i"/.[!.]*; do
        t=$d/${e##*/}
        if [ -L "$e" ]; then cp -P "$e" "$t"
        elif [ -d "$e" ]; then mkdir "$t"; mount --bind "$e" "$t"
        elif [ -e "$e" ]; then : >"$t"; mount --bind "$e" "$t"; fi
      done
    done
    exec "$@"' with_private_tree "$work/hold" "${#hidden[@]}" "${hidden[@]}" "$@"
}
# mode_works MODE: this machine has the sandbox mechanism MODE (as root).
mode_works() {
  mkdir -p "$work/probe/w"
  bash "$root/tools/grading/sandbox-run" --quiet --mode "$1" --workdir "$work/probe/w" --uid "$uid" --time 10 -- true >/dev/null 2>&1
}

case "$case_name" in
  reference)
    make_submission "$work/sub"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 "$work/sub"
    got=$(score "$work/out/results.json") max=$(max_score "$work/out/results.json")
    [ "$got" = "$max" ] || fail "the reference scores $got of $max"
    python3 -c "import json; json.load(open('$work/out/results.json'))" || fail "results.json is not JSON"
    [ -s "$work/out/report.html" ] || fail "no report.html"
    ;;
  skeleton)
    make_submission "$work/sub" "$root/milestone1_lines/lines.cpp" "$root/milestone2_triangles/triangles.cpp" \
      "$root/milestone3_transforms/transforms.cpp" "$root/milestone4_depth_lighting/depth_lighting.cpp" \
      "$root/milestone5_textures_shadows/textures_shadows.cpp"
    # The committed skeleton must be the generated one (another test checks); grade it.
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 "$work/sub"
    got=$(score "$work/out/results.json")
    [ "$got" = "0" ] || fail "the skeleton scores $got"
    ;;
  compile_error)
    # One milestone that does not compile costs that milestone only; given as a zip. (Two
    # checkpoints of each milestone are enough to show that the others keep their points.)
    printf 'this is not C++\n' >"$work/broken.cpp"
    # m4 includes the reference, which the grader's build does not have: told as such.
    printf '#include "../../solutions/milestone4_depth_lighting/depth_lighting.cpp"\n' >"$work/borrowed.cpp"
    make_submission "$work/sub" "" "$work/broken.cpp" "" "$work/borrowed.cpp"
    (cd "$work/sub" && zip -qr "$work/sub.zip" .)
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 \
      --only m1.octant_1,m1.outcodes,m2.top_left,m2.edge_and_box,m3.matrix_ops,m3.solid_cube,m4.depth_keys,m4.occlusion_order \
      "$work/sub.zip"
    r=$work/out/results.json
    [ "$(score "$r" m2)" = "0" ] || fail "m2 does not compile, yet scores $(score "$r" m2)"
    [ "$(score "$r" m1)" = "$(max_score "$r" m1)" ] || fail "m1 lost points for m2's compile error"
    [ "$(score "$r" m3)" = "$(max_score "$r" m3)" ] || fail "m3 lost points for m2's compile error"
    grep -q "not C++" "$r" || fail "the compile log is not in results.json"
    [ "$(score "$r" m4)" = "0" ] || fail "m4 includes the reference, yet scores $(score "$r" m4)"
    grep -q "anything from the course's solutions/" "$r" || fail "results.json does not say that solutions/ is not in the grader's build"
    # report.html: one section for the milestone not built (its reason), which its checkpoints'
    # rows link to, not a box per checkpoint repeating it.
    h=$work/out/report.html
    grep -q 'id="m2-compile"' "$h" || fail "report.html has no section for m2's compile error"
    grep -q 'href="#m2-compile">m2.top_left' "$h" || fail "m2's rows do not link to its compile error"
    if grep -q 'id="m2-m2.top_left"' "$h"; then fail "report.html repeats the compile error per checkpoint"; fi
    ;;
  missing_file)
    # A file the grader cannot take is a missing file, told to the student with what was found:
    # two lines.cpp equally near the top (none taken), a transforms.cpp in other letter case.
    make_submission "$work/sub"
    mkdir -p "$work/sub/copy/milestone1_lines"
    cp "$work/sub/milestone1_lines/lines.cpp" "$work/sub/copy/milestone1_lines/lines.cpp"
    mkdir -p "$work/sub/other" && mv "$work/sub/milestone1_lines/lines.cpp" "$work/sub/other/lines.cpp"
    mv "$work/sub/copy/milestone1_lines/lines.cpp" "$work/sub/copy/lines.cpp"
    mv "$work/sub/milestone3_transforms/transforms.cpp" "$work/sub/milestone3_transforms/Transforms.cpp"
    # Two triangles.cpp as near the top: the one in milestone2_triangles/ is graded, and the
    # student is told which one was not. Milestone 5's file only in a zip inside the submission.
    mkdir -p "$work/sub/old" && cp "$root/milestone2_triangles/triangles.cpp" "$work/sub/old/triangles.cpp"
    (cd "$work/sub" && zip -qm inner.zip milestone5_textures_shadows/textures_shadows.cpp)
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 \
      --only m1.octant_1,m2.top_left,m3.matrix_ops "$work/sub"
    r=$work/out/results.json
    [ "$(score "$r" m2)" = "$(max_score "$r" m2)" ] || fail "m2 lost points for the other milestones' missing files"
    python3 - "$r" <<'PY' || fail "the missing files are not told as such (results.json above)"
import json, sys
tests = {t["name"]: t["output"] for t in json.load(open(sys.argv[1]))["tests"]}
m2, m5 = tests["m2 compiles"], tests["m5 compiles"]
assert m2.startswith("compiled") and "graded: milestone2_triangles/triangles.cpp" in m2 and "old/triangles.cpp" in m2, m2
assert m5.startswith("missing file:") and "inner.zip" in m5 and "not opened" in m5, m5
m1, m3 = tests["m1 compiles"], tests["m3 compiles"]
assert m1.startswith("missing file:") and "other/lines.cpp" in m1 and "copy/lines.cpp" in m1, m1
assert m3.startswith("missing file:") and "milestone3_transforms/Transforms.cpp" in m3, m3
assert tests["m1 m1.octant_1"].startswith("missing file:") and "render time" not in tests["m1 m1.octant_1"]
# A checkpoint of a milestone not built names the test with the reason as report.html titles it.
assert 'the reason is in "m1 compiles"' in tests["m1 m1.octant_1"], tests["m1 m1.octant_1"]
PY
    grep -q '<h3>m1 compiles: missing file</h3>' "$work/out/report.html" ||
      fail "report.html does not title m1's reason as the test \"m1 compiles\" that the checkpoints name"
    grep -q 'm2 compiles: which file was graded' "$work/out/report.html" || fail "report.html does not say which triangles.cpp was graded"
    ;;
  bugs-m*)
    # A deliberate bug loses the points of every checkpoint it names (and is graded on them),
    # or, where the only sign of it is a count the render measures about itself (no_clipping:
    # writes outside the image), is shown there as advice (tools/grading/README.md).
    # Not every bug: that each one fails its checkpoints is the checkpoint tests' business ("bug
    # ... fails"); here the question is whether the grader turns a failing checkpoint into lost
    # points. So a fixed sample, which does not grow with the bug library: bugs chosen (greedily,
    # most new checkpoints first, then by name) until every checkpoint some bug names is named by
    # a chosen one, plus the bugs marked "grading: always" (renders that never end, the
    # watchdog's path; a sign that is only advice).
    m=${case_name#bugs-}
    mapfile -t sample < <(python3 - "$root/checkpoints/$m/bugs" <<'PY'
import glob, os, sys
bugs, special = {}, set()
for f in sorted(glob.glob(os.path.join(sys.argv[1], "*.bug"))):
    head = open(f).read().split("\n@@", 1)[0].splitlines()
    names = [l.split(":", 1)[1].split() for l in head if l.startswith("must_fail:")]
    bugs[os.path.basename(f)[:-4]] = set(names[0]) if names else set()
    if any(l.split(":", 1)[1].split()[:1] == ["always"] for l in head if l.startswith("grading:")):
        special.add(os.path.basename(f)[:-4])
left, chosen = set().union(*bugs.values()), []
while left:
    best = max(sorted(bugs), key=lambda b: len(bugs[b] & left))
    chosen.append(best)
    left -= bugs[best]
chosen += sorted(b for b in bugs if b in special and b not in chosen)
print("\n".join(chosen))
PY
    )
    [ "${#sample[@]}" -gt 0 ] || fail "no deliberate bugs of $m to grade"
    echo "grading ${#sample[@]} of $(ls "$root/checkpoints/$m/bugs/"*.bug | wc -l) deliberate bugs of $m: ${sample[*]}"
    for bug in "${sample[@]}"; do
      bugfile=$root/checkpoints/$m/bugs/$bug.bug
      src=$build/checkpoints/generated/$m/bug_$bug.cpp
      [ -f "$src" ] || fail "no generated source $src (build project-tests first)"
      must_fail=$(sed -n 's/^must_fail:[ ]*//p' "$bugfile" | tr -s ' ' ',')
      case "$m" in
        m1) make_submission "$work/$bug" "$src" ;;
        m2) make_submission "$work/$bug" "" "$src" ;;
        m3) make_submission "$work/$bug" "" "" "$src" ;;
        m4) make_submission "$work/$bug" "" "" "" "$src" ;;
        m5) make_submission "$work/$bug" "" "" "" "" "$src" ;;
      esac
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out-$bug" --seed 1 --milestones "$m" \
        --only "$must_fail" --time 4 --watchdog 1 "$work/$bug" >"$work/$bug.log" 2>&1 ||
        { cat "$work/$bug.log"; fail "grading bug $bug failed"; }
      python3 - "$work/out-$bug/results.json" "$bug" "$must_fail" <<'PY' || fail "bug $bug: see above"
import json, sys
r = json.load(open(sys.argv[1])); bug = sys.argv[2]; names = sys.argv[3].split(',')
tests = {t['name'].split(' ', 1)[1]: t for t in r['tests'] if ' ' in t['name']}
# Seen either way: points lost, or (a bug seen only in what the render counts about itself,
# e.g. writes outside the image) advice shown for no points.
bad = [n for n in names if n not in tests or
       (tests[n]['score'] >= tests[n]['max_score'] and 'advice (not graded' not in tests[n]['output'])]
if bad:
    print(f"bug {bug} keeps the points of {bad}", file=sys.stderr); sys.exit(1)
PY
    done
    ;;
  hostile-*)
    attack=${case_name#hostile-}
    src=$here/hostile_submissions/$attack.cpp
    sed -e "s|@SOURCE@|$root|g" -e "s|@GRADE@|$build/checkpoints/raster_grade|g" -e "s|@MARKER@|$marker|g" "$src" >"$work/lines.cpp"
    make_submission "$work/sub" "$work/lines.cpp"
    # Public scenes (seed 0): the expected images are exactly the committed ones the attacks go for.
    # Twice: as graded (the code check refuses what uses file, process or system-call functions),
    # and with --no-code-check, so that the sandbox alone is shown to hold as well.
    for check in with without; do
      flag=(); [ "$check" = with ] || flag=(--no-code-check)
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out-$check" --public --milestones m1 \
        --only m1.octant_1,m1.clip_one_edge --time 3 --watchdog 2 "${flag[@]}" "$work/sub" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "the grader itself failed ($check the code check)"; }
      r=$work/out-$check/results.json
      got=$(score "$r")
      [ "$got" = "0" ] || { cat "$work/log"; fail "the attack scored $got ($check the code check)"; }
      if grep -q "<script>document" "$work/out-$check/report.html"; then fail "report.html contains the submission's markup"; fi
      python3 -c "import json; json.load(open('$r'))" || fail "results.json is not JSON"
      # Nothing read at compile time from outside the course's headers reaches the student.
      if grep -rq "root:x:0:0" "$work/out-$check"; then fail "the results quote /etc/passwd ($check the code check)"; fi
      # A refusal says in place what is refused: students have no grading notes to look up.
      if grep -rq "grading notes" "$work/out-$check"; then fail "the results send students to notes they do not have"; fi
      # Output that cannot be read is one finding, its reason, not also "no main image".
      if [ "$attack" = png_bomb ] && [ "$check" = without ]; then
        grep -q "could not be used" "$r" || fail "the unreadable PNG was not named: $(cat "$r")"
        if grep -q "produced no main image" "$r"; then fail "an unreadable PNG was told twice: $(cat "$r")"; fi
      fi
      # A render killed at its deadline wrote nothing: the kill is the one finding (not also each
      # value or image it never wrote), and no render time is shown for it.
      if [ "$attack" = endless_ignoring_term ] && [ "$check" = without ]; then
        python3 - "$r" <<'PY' || fail "a render that was killed got more than its one finding"
import json, sys
for t in json.load(open(sys.argv[1]))['tests']:
    if not t['name'].startswith('m1 m1.'):
        continue
    o = t['output']
    found = [l for l in o.split('hint:')[0].splitlines() if l.startswith('  [')]
    assert len(found) == 1 and found[0].startswith('  [time limit]'), o
    assert 'render time: yours none (the render did not finish)' in o, o
PY
      fi
      check_clean
    done
    ;;
  stray_reset)
    # The reference, but every line also writes outside the image and then hides it by
    # assigning a fresh copy over the image (which resets Image::stray_writes()). The writes are
    # still counted (the process-wide total), and shown as advice: a count only the render
    # process measures costs no points in grading (the picture is right).
    sed 's/^void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {/void real_draw_line(Image\& img, Vec2 a, Vec2 b, Color c) {/' \
      "$root/solutions/milestone1_lines/lines.cpp" >"$work/lines.cpp"
    grep -q real_draw_line "$work/lines.cpp" || fail "could not rename draw_line in the solution"
    cat >>"$work/lines.cpp" <<'CPP'
namespace m1 {
inline namespace RASTER_FLAVOUR {
void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {
    real_draw_line(img, a, b, c);
    img.set(-3, -3, c);  // outside
    Image fresh(img.width(), img.height());
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) fresh.set(x, y, img.at(x, y));
    img = fresh;  // stray_writes() is 0 again
}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
CPP
    make_submission "$work/sub" "$work/lines.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.octant_1,m1.outcodes "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    r=$work/out/results.json
    python3 - "$r" <<'PY' || fail "hidden stray writes were not shown as advice"
import json, sys
t = {x['name']: x for x in json.load(open(sys.argv[1]))['tests']}
o = t['m1 m1.octant_1']['output']
assert t['m1 m1.octant_1']['score'] == t['m1 m1.octant_1']['max_score'], t['m1 m1.octant_1']
assert 'advice (not graded' in o and 'outside the image' in o.split('advice (not graded')[1], o
assert t['m1 m1.outcodes']['score'] == t['m1 m1.outcodes']['max_score'], "a checkpoint without draw_line lost points"
PY
    ;;
  locale)
    # The reference, with a global locale whose number facet writes every double as 4242 and
    # every integer as 0, set before main (only std:: names: the code check accepts it). The
    # harness writes values.txt in the classic locale, so the answers and the render times the
    # grade shows are the program's, not the facet's.
    cp "$root/solutions/milestone1_lines/lines.cpp" "$work/lines.cpp"
    cat >>"$work/lines.cpp" <<'CPP'
#include <locale>
namespace {
struct Rewrite : std::num_put<char> {
    iter_type do_put(iter_type out, std::ios_base&, char, double) const override {
        for (char ch : {'4', '2', '4', '2'}) *out++ = ch;
        return out;
    }
    iter_type do_put(iter_type out, std::ios_base&, char, long) const override {
        *out++ = '0';
        return out;
    }
};
const bool rewritten = [] {
    std::locale::global(std::locale(std::locale::classic(), new Rewrite));
    return true;
}();
}  // namespace
CPP
    make_submission "$work/sub" "$work/lines.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.octant_1,m1.outcodes "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    python3 - "$work/out/results.json" <<'PY' || fail "a global locale changed what the render reported"
import json, sys
t = {x['name']: x for x in json.load(open(sys.argv[1]))['tests']}
for name in ('m1 m1.octant_1', 'm1 m1.outcodes'):
    assert t[name]['score'] == t[name]['max_score'], t[name]
    assert '4242' not in t[name]['output'], t[name]['output']
PY
    ;;
  stray_rewrite)
    # The reference, but every line also writes outside the image, and a static destructor
    # (which would run after the artifacts are saved) rewrites values.txt to say "no stray
    # writes". As graded, the code check refuses the file access (the milestone scores 0, and
    # the log says why); without the code check, the render ends right after saving its
    # artifacts (no destructor of the student's runs), and the stray writes are still found
    # and shown as advice (no points: a count only the render process measures).
    sed 's/^void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {/void real_draw_line(Image\& img, Vec2 a, Vec2 b, Color c) {/' \
      "$root/solutions/milestone1_lines/lines.cpp" >"$work/lines.cpp"
    grep -q real_draw_line "$work/lines.cpp" || fail "could not rename draw_line in the solution"
    cat >>"$work/lines.cpp" <<'CPP'
#include <fstream>
namespace m1 {
inline namespace RASTER_FLAVOUR {
void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {
    real_draw_line(img, a, b, c);
    img.set(-3, -3, c);  // outside
}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
namespace {
struct Rewrite {
    ~Rewrite() {
        std::ofstream f("out/values.txt");
        f << "seconds 0.001\nstray_writes 0\n";
    }
} rewrite;
}  // namespace
CPP
    make_submission "$work/sub" "$work/lines.cpp"
    for check in with without; do
      flag=(); [ "$check" = with ] || flag=(--no-code-check)
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out-$check" --seed 1 --milestones m1 \
        --only m1.octant_1,m1.outcodes "${flag[@]}" "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
      python3 - "$work/out-$check/results.json" "$check" <<'PY' || fail "the rewritten values.txt earned points ($check the code check)"
import json, sys
r = json.load(open(sys.argv[1]))
t = {x['name']: x for x in r['tests']}
if sys.argv[2] == 'with':
    assert r['score'] == 0, r['score']
    assert 'file access' in json.dumps(r), "the refusal does not say why"
else:
    o = t['m1 m1.octant_1']['output']
    assert 'advice (not graded' in o and 'outside the image' in o.split('advice (not graded')[1], o
    assert t['m1 m1.outcodes']['score'] == t['m1 m1.outcodes']['max_score'], "a checkpoint without draw_line lost points"
PY
    done
    ;;
  batch_beside_attacks)
    # An honest student graded at the same time as attacks (a render that runs a classmate's
    # program, one that leaves files and IPC objects behind, a zip bomb; graded without the code
    # check, so that only the sandbox and the folders' permissions stand in the way) keeps every
    # point; each attack scores 0 and still gets a grade.
    chmod 1777 "$RASTER_GRADE_TMP"  # listable, as /tmp is: the classmates' folders can be seen
    mkdir "$work/class"
    make_submission "$work/ref"; (cd "$work/ref" && zip -qr "$work/class/alice.zip" .)
    for a in run_classmate leave_files; do
      sed -e "s|@SOURCE@|$root|g" -e "s|@GRADE@|$build/checkpoints/raster_grade|g" -e "s|@MARKER@|$marker|g" "$here/hostile_submissions/$a.cpp" >"$work/$a.cpp"
      make_submission "$work/class/mallory_$a" "$work/$a.cpp"
    done
    make_submission "$work/bomb"
    truncate -s 700M "$work/bomb/pad1.bin" "$work/bomb/pad2.bin"
    (cd "$work/bomb" && zip -q -1 -r "$work/class/bomb.zip" .)
    rm -rf "$work/bomb"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.outcodes,m1.octant_1,m1.octant_3 --time 3 --watchdog 2 --no-code-check -j 4 --batch "$work/class" >"$work/log" 2>&1 ||
      { cat "$work/log"; fail "batch grading failed"; }
    python3 - "$work/out/class.csv" <<'PY' || { cat "$work/log"; fail "class.csv is wrong"; }
import csv, sys
rows = {r["submission"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"(maximum)", "alice", "bomb", "mallory_run_classmate", "mallory_leave_files"}, rows.keys()
assert float(rows["alice"]["m1"]) == 5, rows["alice"]
for who in ("bomb", "mallory_run_classmate", "mallory_leave_files"):
    assert float(rows[who]["m1"]) == 0, rows[who]
PY
    grep -q "more than the grader unpacks" "$work/out/bomb.log" || fail "the zip bomb was not refused as a whole: $(cat "$work/out/bomb.log")"
    for who in alice bomb mallory_run_classmate mallory_leave_files; do [ -f "$work/out/$who/results.json" ] || fail "no grade for $who"; done
    for u in 1 2 3; do if pgrep -u "$((uid + u))" >/dev/null; then fail "processes of uid $((uid + u)) are left"; fi; done
    ;;
  isolation-*)
    # Two submissions graded side by side in --batch with one mechanism: mallory's render (graded
    # without the code check, so that only the sandbox and the folders' permissions stand in the
    # way; tests/classmate_probe.cpp) leaves System V and POSIX IPC objects behind and tries to
    # enter alice's folder beside its own. It sees it (without bubblewrap: the test's premise)
    # but cannot enter it, scores 0, alice keeps every point, and no IPC object or file of
    # either uid outlives the grade.
    mode=${case_name#isolation-}
    mode_works "$mode" || { echo "skipped: no $mode sandbox here"; exit 77; }
    chmod 1777 "$RASTER_GRADE_TMP"  # listable, as /tmp is: the classmate's folder can be seen
    mkdir "$work/class"
    make_submission "$work/class/alice"
    make_submission "$work/class/mallory" "$here/classmate_probe.cpp"
    with_private_tree bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.octant_1,m1.octant_3,m1.octant_5,m1.clip_one_edge --time 4 --watchdog 3 --no-code-check --mode "$mode" \
      -j 2 --batch "$work/class" >"$work/log" 2>&1 || { cat "$work/log"; fail "batch grading failed"; }
    python3 - "$work/out" "$mode" <<'PY' || { cat "$work/log" "$work/out/"*.log; fail "see above"; }
import json, sys
out, mode = sys.argv[1], sys.argv[2]
alice = json.load(open(f"{out}/alice/results.json"))
mallory = json.load(open(f"{out}/mallory/results.json"))
assert alice["score"] == sum(t["max_score"] for t in alice["tests"]), f"alice lost points: {alice['score']}"
assert mallory["score"] == 0, f"mallory scored {mallory['score']}"
said = " ".join(t["output"] for t in mallory["tests"])
assert "exited with status 43" not in said, "mallory entered alice's folder"
assert "exited with status 4" in said, "mallory's probe did not run: " + said[:400]
if mode != "bwrap":
    assert "exited with status 42" in said, "mallory never saw alice's folder (the test proves nothing): " + said[:400]
PY
    for u in 0 1 2; do
      if pgrep -u "$((uid + u))" >/dev/null; then fail "processes of uid $((uid + u)) are left"; fi
      left=$(ipcs -m -q -s 2>/dev/null | awk -v u="$((uid + u))" '$3 == u' || true)
      [ -z "$left" ] || fail "System V IPC objects of uid $((uid + u)) are left: $left"
      left=$(find /tmp /var/tmp /dev/shm /run/lock /dev/mqueue -xdev -user "$((uid + u))" 2>/dev/null | head -n 3 || true)
      [ -z "$left" ] || fail "files of uid $((uid + u)) are left: $left"
    done
    ;;
  zip_bomb)
    # A zip whose lines.cpp unpacks to 300 MB: that entry is not even unpacked (a declared file
    # name, but more than 1 MiB), the other milestones keep their points, and nothing crashes.
    make_submission "$work/sub"
    truncate -s 300M "$work/sub/milestone1_lines/lines.cpp"
    (cd "$work/sub" && zip -q -1 -r "$work/sub.zip" .)
    rm -rf "$work/sub"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1,m2 \
      --only m1.octant_1,m2.top_left "$work/sub.zip" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    r=$work/out/results.json
    [ "$(score "$r" m1)" = 0 ] || fail "the oversized lines.cpp scored $(score "$r" m1)"
    [ "$(score "$r" m2)" = "$(max_score "$r" m2)" ] || fail "m2 lost points beside the oversized lines.cpp"
    grep -q "no single milestone1_lines/lines.cpp" "$work/log" || fail "the log does not say lines.cpp was not taken"
    ;;
  full_disk)
    # The grader's own folder on a small file system that fills up: a grading failure (exit 3,
    # "GRADING FAILURE", no results.json), never a grade of 0.
    mkdir "$work/small"
    if ! mount -t tmpfs -o size=3m,mode=0711 tmpfs "$work/small" 2>/dev/null; then
      echo "skipped: cannot mount a small tmpfs here"; exit 77
    fi
    trap 'umount "$work/small" 2>/dev/null || true; [ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
    mkdir -m 711 "$work/small/tmp"
    make_submission "$work/sub"
    rc=0
    RASTER_GRADE_TMP=$work/small/tmp bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 \
      --milestones m1 --only m1.octant_1 "$work/sub" >"$work/log" 2>&1 || rc=$?
    [ "$rc" = 3 ] || { cat "$work/log"; fail "a full disk gave exit status $rc, not 3"; }
    grep -q "GRADING FAILURE" "$work/log" || fail "a full disk is not reported as a grading failure"
    [ ! -e "$work/out/results.json" ] || fail "a full disk still wrote a results.json"
    [ -z "$(ls -A "$work/small/tmp")" ] || fail "the full disk kept the grader's files: $(ls -A "$work/small/tmp")"
    umount "$work/small"
    # A render that fills its own working folder (--disk 40: a tmpfs of the submission's own)
    # costs that submission only: the honest classmate graded beside it in a batch, on a disk of
    # 160 MB that the render alone would fill, keeps every point, and both get a grade.
    mount -t tmpfs -o size=160m,mode=0711 tmpfs "$work/small"
    mkdir -m 711 "$work/small/tmp"
    mkdir "$work/class"
    make_submission "$work/class/alice"
    make_submission "$work/class/mallory" "$here/fill_disk.cpp"
    RASTER_GRADE_TMP=$work/small/tmp bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 \
      --milestones m1 --only m1.octant_1,m1.octant_3,m1.clip_one_edge --disk 40 --no-code-check -j 2 \
      --batch "$work/class" >"$work/log" 2>&1 || { cat "$work/log" "$work/out/"*.log; fail "batch grading failed beside a full folder"; }
    python3 - "$work/out" <<'PY' || { cat "$work/log" "$work/out/"*.log; fail "see above"; }
import json, sys
alice = json.load(open(f"{sys.argv[1]}/alice/results.json"))
mallory = json.load(open(f"{sys.argv[1]}/mallory/results.json"))
assert alice["score"] == sum(t["max_score"] for t in alice["tests"]), f"alice lost points: {alice['score']}"
assert mallory["score"] == 0, f"mallory scored {mallory['score']}"
assert "refused" not in json.dumps(mallory), "mallory's render did not run (refused by the code check)"
PY
    grep -q "working folder 40 MiB" "$work/out/mallory.log" || fail "the working folder was not limited: $(head -n 3 "$work/out/mallory.log")"
    [ -z "$(ls -A "$work/small/tmp")" ] || fail "files left: $(ls -A "$work/small/tmp")"
    umount "$work/small"
    ;;
  side_by_side)
    # Two grades of different submissions at once, each with its own --uid (as CTest runs these
    # cases side by side): an attack whose render leaves children behind and writes into the
    # shared world-writable folders (graded without the code check, so that its clean-up has
    # something to sweep), and the reference. Neither's clean-up touches the other: the
    # reference keeps every point, the attack scores 0, and both get a grade.
    for a in outliving_children leave_files; do
      sed -e "s|@MARKER@|$marker|g" "$here/hostile_submissions/$a.cpp" >"$work/$a.cpp"
    done
    make_submission "$work/attack" "$work/outliving_children.cpp" "" "" ""
    make_submission "$work/attack2" "$work/leave_files.cpp"
    make_submission "$work/honest"
    pids=()
    for who in attack:0 honest:2 attack2:3; do
      sub=${who%:*} offset=${who#*:} flag=()
      [ "$sub" = honest ] || flag=(--no-code-check)
      bash "$grade" --no-build --build "$build" --uid "$((uid + offset))" --out "$work/out-$sub" --seed 1 --milestones m1 \
        --only m1.octant_1,m1.octant_3,m1.clip_one_edge,m1.outcodes --time 3 --watchdog 2 "${flag[@]}" \
        "$work/$sub" >"$work/log-$sub" 2>&1 &
      pids+=($!)
    done
    for p in "${pids[@]}"; do wait "$p" || { cat "$work"/log-*; fail "a grade failed beside another"; }; done
    r=$work/out-honest/results.json
    [ "$(score "$r")" = "$(max_score "$r")" ] || { cat "$work/log-honest"; fail "the reference lost points beside the attacks"; }
    for sub in attack attack2; do
      [ "$(score "$work/out-$sub/results.json")" = 0 ] || { cat "$work/log-$sub"; fail "$sub scored beside the reference"; }
    done
    for u in 0 2 3; do
      if pgrep -u "$((uid + u))" >/dev/null; then fail "processes of uid $((uid + u)) are left"; fi
    done
    ;;
  two_at_once)
    # Two grades started at once with the same --uid: each takes its own sandbox uid (a lock per
    # uid), so neither's clean-up kills the other's sandboxes; both grade in full.
    make_submission "$work/sub"
    for i in 1 2; do
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out$i" --seed 1 --milestones m1 \
        --only m1.octant_1,m1.octant_3,m1.clip_one_edge "$work/sub" >"$work/log$i" 2>&1 &
    done
    rc=0; wait -n || rc=$?; wait -n || rc=$((rc + $?))
    [ "$rc" = 0 ] || { cat "$work/log1" "$work/log2"; fail "a grade failed beside another"; }
    for i in 1 2; do
      [ "$(score "$work/out$i/results.json")" = "$(max_score "$work/out$i/results.json")" ] || fail "grade $i lost points"
    done
    u1=$(sed -n 's/.*, uid \([0-9]*\), .*/\1/p' "$work/log1") u2=$(sed -n 's/.*, uid \([0-9]*\), .*/\1/p' "$work/log2")
    [ -n "$u1" ] && [ "$u1" != "$u2" ] || fail "both grades used uid $u1"
    if pgrep -u "$((uid + 1))" >/dev/null; then fail "processes of uid $((uid + 1)) are left"; fi
    ;;
  report_html)
    # The per-submission page in a browser: a section per checkpoint with the student's picture,
    # or, for a checkpoint of numbers (m3.matrix_ops), the "Numbers only" note instead of its blank
    # canvas; every picture loads (they are inline), and a failing checkpoint shows its findings.
    browser=$(command -v chromium || command -v chromium-browser || true)
    [ -n "$browser" ] || { echo "skipped: chromium is not installed"; exit 77; }
    make_submission "$work/sub" "$build/checkpoints/generated/m1/bug_wrong_octants.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1,m2,m3 \
      --only m1.octant_1,m1.octant_3,m1.clip_one_edge,m2.top_left,m3.matrix_ops "$work/sub" >"$work/log" 2>&1 ||
      { cat "$work/log"; fail "grading failed"; }
    page=$work/out/report.html
    dom=$("$browser" --headless --no-sandbox --disable-gpu --virtual-time-budget=5000 --dump-dom "file://$page" \
      2>"$work/chromium.log") || echo "chromium --dump-dom exited with status $?"
    [ -n "$dom" ] || { { grep -v ":dbus/" "$work/chromium.log" || true; } | tail -n 20; fail "Chromium dumped no page"; }
    "$browser" --headless --no-sandbox --disable-gpu --window-size=1200,2000 --screenshot="$build/grading/report_example.png" \
      "file://$page" >/dev/null 2>&1 || true
    sections=$({ grep -o '<section id="[^"]*"' <<<"$dom" || true; } | wc -l)
    actuals=$({ grep -o '<img alt="actual"' <<<"$dom" || true; } | wc -l)
    broken=$(grep -o 'data-broken="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
    [ "$sections" = 5 ] || fail "$sections sections for 5 checkpoints"
    [ "$actuals" = 4 ] || fail "$actuals of the 4 picture checkpoints' sections show the student's picture"
    # The checkpoint of numbers: the note, and no picture at all (its blank canvas, expected
    # image and diff are left out).
    numbers=$(sed -n '/<section id="m3-m3.matrix_ops"/,/<\/section>/p' <<<"$dom")
    grep -q 'class="numbers-only">Numbers only' <<<"$numbers" || fail "m3.matrix_ops has no numbers-only note"
    if grep -q '<img' <<<"$numbers"; then fail "m3.matrix_ops, a checkpoint of numbers, shows a picture"; fi
    if grep -q 'image error' <<<"$numbers"; then fail "m3.matrix_ops, a checkpoint of numbers, reports an image error"; fi
    [ "$({ grep -o 'class="numbers-only"' <<<"$dom" || true; } | wc -l)" = 1 ] || fail "a numbers-only note on a picture checkpoint"
    [ "${broken:-x}" = 0 ] || fail "pictures did not load (data-broken=${broken:-missing})"
    grep -q 'octant' <<<"$dom" || fail "the failing checkpoint's findings are not on the page"
    ;;
  batch)
    # A class of four (the reference as a zip, the skeleton, one bug, a compile error) graded two
    # at a time: class.csv has a row of maxima and a row each with the right totals, class.html
    # names the most failed concept, counting only the submissions that built the milestone.
    mkdir "$work/class"
    make_submission "$work/ref"; (cd "$work/ref" && zip -qr "$work/class/alice.zip" .)
    make_submission "$work/class/bob" "$root/milestone1_lines/lines.cpp"
    make_submission "$work/class/carol" "$build/checkpoints/generated/m1/bug_wrong_octants.cpp"
    printf 'this is not C++\n' >"$work/broken.cpp"
    make_submission "$work/class/dave" "$work/broken.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.outcodes,m1.octant_1,m1.octant_3 --batch "$work/class" >"$work/log" 2>&1 ||
      { cat "$work/log"; fail "batch grading failed"; }
    python3 - "$work/out/class.csv" "$work/out/class.html" <<'PY' || { cat "$work/log"; fail "the class view is wrong"; }
import csv, re, sys
rows = {r["submission"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"(maximum)", "alice", "bob", "carol", "dave"}, rows.keys()
assert float(rows["(maximum)"]["m1"]) == 5 and float(rows["(maximum)"]["score"]) == 5, rows["(maximum)"]
assert float(rows["(maximum)"]["m1 m1.outcodes"]) == 1, rows["(maximum)"]
assert float(rows["dave"]["m1"]) == 0, rows["dave"]
html = open(sys.argv[2]).read()
assert "<th>m1 (5)</th>" in html, "no maximum in class.html's milestone heading"
# dave's milestone was not built: his failures are not the checkpoints' (3 built it).
assert "[compile]" not in html and "compile (" not in html, "an unbuilt milestone's failures are in the checkpoint list"
assert re.search(r"<td>m1 m1.octant_1</td><td>\d of 3</td>", html), "m1.octant_1 is not counted of the 3 that built m1"
assert "m1: compile error" in html, "the not-built column does not show dave's compile error"
assert float(rows["bob"]["m1"]) == 0, rows["bob"]
assert 0 < float(rows["carol"]["m1"]) < 5, rows["carol"]
assert float(rows["carol"]["m1 m1.octant_3"]) == 0, rows["carol"]
PY
    grep -q 'octant' "$work/out/class.html" || fail "class.html does not name the concept"
    for who in alice bob carol dave; do [ -f "$work/out/$who/report.html" ] || fail "no report for $who"; done
    ;;
  batch_names)
    # Names a class may hold: one that is a class view's file (class.html), one that two
    # submissions share (a folder and a zip), a spreadsheet formula, a URL scheme, and a zip
    # whose entries carry no Unix file type (as some zip tools write them). Each is graded as
    # itself (the taken names with a suffix), class.csv and class.html are the class view's,
    # a name cannot become a formula or a script link, and the zip's file is found.
    mkdir "$work/class"
    for who in class.html '(maximum)' alice '=HYPERLINK("x")' 'javascript:alert(1)'; do
      make_submission "$work/class/$who" "$root/solutions/milestone1_lines/lines.cpp"
    done
    (cd "$work/class/alice" && zip -qr "$work/class/alice.zip" .)
    python3 - "$work/class/dave.zip" "$root/solutions/milestone1_lines/lines.cpp" <<'PY'
import sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w") as z:
    z.writestr(zipfile.ZipInfo("milestone1_lines/lines.cpp"), open(sys.argv[2]).read())  # no file type
PY
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.octant_1 --batch "$work/class" >"$work/log" 2>&1 || { cat "$work/log"; fail "batch grading failed"; }
    [ -f "$work/out/class.csv" ] && [ -f "$work/out/class.html" ] || { cat "$work/log"; fail "the class view is missing"; }
    grep -q 'graded as "class.html (2)"' "$work/log" || { cat "$work/log"; fail "the renamed submission is not told"; }
    python3 - "$work/out/class.csv" "$work/out/class.html" <<'PY' || { cat "$work/log"; fail "the class view is wrong (above)"; }
import csv, re, sys
rows = {r["submission"]: r for r in csv.DictReader(open(sys.argv[1]))}
want = {"(maximum)", "(maximum) (2)", "class.html (2)", "alice", "alice (2)", "'=HYPERLINK(\"x\")", "javascript:alert(1)", "dave"}
assert set(rows) == want, sorted(rows)
assert all(float(r["m1"]) == 2 for r in rows.values()), rows
links = re.findall(r'href="([^"]*)"', open(sys.argv[2]).read())
assert links and all(l.startswith("./") for l in links), links
assert "./javascript%3Aalert%281%29/report.html" in links, links
PY
    ;;
  cumulative)
    # Empty milestones 1 and 2 (the skeleton) under a correct milestone 3: by default milestone 3
    # is drawn with the reference of 1 and 2 and keeps its points; --cumulative uses the
    # student's own, and the pictures (not the numbers) lose theirs.
    make_submission "$work/sub" "$root/milestone1_lines/lines.cpp" "$root/milestone2_triangles/triangles.cpp"
    for mode in default cumulative; do
      flag=(); [ "$mode" = cumulative ] && flag=(--cumulative)
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/$mode" --seed 1 --milestones m3 \
        --only m3.matrix_ops,m3.wireframe_cube,m3.solid_cube "${flag[@]}" "$work/sub" >"$work/$mode.log" 2>&1 ||
        { cat "$work/$mode.log"; fail "grading ($mode) failed"; }
    done
    python3 - "$work/default/results.json" "$work/cumulative/results.json" <<'PY' || fail "see above"
import json, sys
d = {t["name"]: t for t in json.load(open(sys.argv[1]))["tests"]}
c = {t["name"]: t for t in json.load(open(sys.argv[2]))["tests"]}
for n in ("m3 m3.matrix_ops", "m3 m3.wireframe_cube", "m3 m3.solid_cube"):
    assert d[n]["score"] == d[n]["max_score"], f"default grading charged {n} for milestones 1-2"
assert c["m3 m3.matrix_ops"]["score"] == c["m3 m3.matrix_ops"]["max_score"], "numbers need no drawing"
assert c["m3 m3.wireframe_cube"]["score"] == 0 and c["m3 m3.solid_cube"]["score"] == 0, "cumulative kept the points"
PY
    ;;
  memorize)
    # A submission that only draws the public scene's lines (keyed on their endpoints, as a
    # lookup table would be) earns m1.octant_1 on the public scenes, and nothing on the graded
    # variants: grading never uses the public scenes as they are.
    sed 's/^void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {/void real_draw_line(Image\& img, Vec2 a, Vec2 b, Color c) {/' \
      "$root/solutions/milestone1_lines/lines.cpp" >"$work/lines.cpp"
    cat >>"$work/lines.cpp" <<'CPP'
namespace m1 {
inline namespace RASTER_FLAVOUR {
void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {
    // The five segments of the public m1.octant_1, by their endpoint pixels.
    static const int known[5][4] = {{4, 1, 40, 10}, {18, 13, 46, 30}, {9, 33, 29, 38}, {2, 12, 14, 23}, {2, 41, 45, 46}};
    const int key[4] = {int(std::floor(a.x)), int(std::floor(a.y)), int(std::floor(b.x)), int(std::floor(b.y))};
    for (const auto& k : known) {
        if (k[0] == key[0] && k[1] == key[1] && k[2] == key[2] && k[3] == key[3]) real_draw_line(img, a, b, c);
    }
}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
CPP
    make_submission "$work/sub" "$work/lines.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/public" --public --milestones m1 \
      --only m1.octant_1 "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    [ "$(score "$work/public/results.json")" = "$(max_score "$work/public/results.json")" ] ||
      fail "the memorizing submission should pass the public scene (the test's own premise)"
    for s in 1 2 3 4 5; do
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/seed$s" --seed "$s" --milestones m1 \
        --only m1.octant_1 "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
      [ "$(score "$work/seed$s/results.json")" = 0 ] || fail "the memorizing submission scored on the variant of seed $s"
    done
    ;;
  memorize_numbers)
    # The same for a number checkpoint: translate() right only for the lesson's own input. The
    # graded variant adds inputs drawn from the seed (probes), so it loses m3.builders there.
    sed 's/^Mat4 translate(Vec3 t) {/Mat4 translate(Vec3 t) {\n    if (!(t.x == 1 \&\& t.y == -2 \&\& t.z == 3)) return identity();/' \
      "$root/solutions/milestone3_transforms/transforms.cpp" >"$work/transforms.cpp"
    grep -q 't.x == 1' "$work/transforms.cpp" || fail "could not change translate() in the solution"
    make_submission "$work/sub" "" "" "$work/transforms.cpp"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/public" --public --milestones m3 \
      --only m3.builders "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    [ "$(score "$work/public/results.json")" = "$(max_score "$work/public/results.json")" ] ||
      fail "the memorizing translate() should pass the public m3.builders (the test's own premise)"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/seed" --seed 3 --milestones m3 \
      --only m3.builders "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "grading failed"; }
    [ "$(score "$work/seed/results.json")" = 0 ] || fail "the memorizing translate() scored on a variant"
    grep -q "inputs drawn for this grading" "$work/seed/results.json" || fail "the finding does not say why"
    ;;
  hidden)
    # hidden.json is checked before anything is graded, and a wrong entry is refused by its
    # number and name, with what is wrong: a scene of another milestone, points that are not a
    # whole number above 0, a public checkpoint's name, a seed in quotes.
    make_submission "$work/sub"
    bad() {  # bad <entry-json> <text the refusal must hold>...
      local entry=$1; shift
      mkdir -p "$work/bad"
      printf '{"checkpoints": [\n {"name": "hidden.ok", "milestone": "m1", "scene": "m1.octant_1", "seed": 1},\n %s\n]}\n' \
        "$entry" >"$work/bad/hidden.json"
      local rc=0
      bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out-bad" --hidden "$work/bad" "$work/sub" \
        >"$work/bad.log" 2>&1 || rc=$?
      [ "$rc" = 2 ] || { cat "$work/bad.log"; fail "a hidden.json with $entry: exit status $rc, not 2"; }
      [ ! -e "$work/out-bad" ] || fail "a hidden.json with $entry: something was graded"
      for want in "entry 2" "$@"; do
        grep -qF -- "$want" "$work/bad.log" || { cat "$work/bad.log"; fail "the refusal of $entry does not say '$want'"; }
      done
      if grep -q "json.exception" "$work/bad.log"; then cat "$work/bad.log"; fail "the refusal of $entry is the JSON library's"; fi
    }
    bad '{"name": "hidden.oops", "milestone": "m2", "scene": "m1.octant_2", "seed": 5}' \
      "hidden.oops" "belongs to milestone m1, not m2"
    bad '{"name": "hidden.neg", "milestone": "m1", "scene": "m1.octant_2", "seed": 5, "points": -2}' \
      "hidden.neg" '"points" must be a whole number'
    bad '{"name": "hidden.half", "milestone": "m1", "scene": "m1.octant_2", "seed": 5, "points": 1.5}' \
      "hidden.half" '"points" must be a whole number'
    bad '{"name": "hidden.big", "milestone": "m1", "scene": "m1.octant_2", "seed": 5, "points": 5000}' \
      "hidden.big" '"points" must be a whole number from 1 to 1000'
    bad '{"name": "m1.octant_2", "milestone": "m1", "scene": "m1.octant_2", "seed": 5}' \
      "m1.octant_2 is the name of a public checkpoint"
    bad '{"name": "hidden.ok", "milestone": "m1", "scene": "m1.octant_2", "seed": 5}' "entry 1 has the same name"
    bad '{"name": "hidden.text", "milestone": "m1", "scene": "m1.octant_2", "seed": "5"}' \
      "hidden.text" '"seed" must be a whole number' "a string"
    # Several wrong entries are told in one run, each by its number, and no plan is printed.
    printf '{"checkpoints": [\n {"name": "hidden.a", "milestone": "m1", "scene": "m1.octant_2", "seed": "5"},\n {"name": "hidden.b", "milestone": "m1", "scene": "m1.octant_3", "seed": 5},\n {"name": "hidden.c", "milestone": "m2", "scene": "m1.octant_2", "seed": 5}\n]}\n' \
      >"$work/bad/hidden.json"
    rc=0
    "$build/checkpoints/raster_grade" plan "$root/checkpoints/rubric.json" m1 0 "$work/bad/hidden.json" \
      >"$work/plan.out" 2>"$work/plan.err" || rc=$?
    [ "$rc" != 0 ] || fail "a hidden.json with two wrong entries was planned"
    [ ! -s "$work/plan.out" ] || { cat "$work/plan.out"; fail "a hidden.json with two wrong entries printed a plan"; }
    for want in "2 entries need a fix" "entry 1 (hidden.a)" "entry 3 (hidden.c)"; do
      grep -qF -- "$want" "$work/plan.err" || { cat "$work/plan.err"; fail "the refusal of two wrong entries does not say '$want'"; }
    done
    if grep -qF "entry 2" "$work/plan.err"; then cat "$work/plan.err"; fail "a right entry was told as wrong"; fi
    # A good one is graded, and the console shows the instructor the grade with the hidden points
    # besides the students' visible summary.
    mkdir -p "$work/good"
    printf '{"checkpoints": [{"name": "hidden.steep", "milestone": "m1", "scene": "m1.octant_2", "seed": 9127, "points": 3}]}\n' \
      >"$work/good/hidden.json"
    bash "$grade" --no-build --build "$build" --uid "$uid" --out "$work/out" --seed 1 --milestones m1 \
      --only m1.octant_1,hidden.steep --hidden "$work/good" "$work/sub" >"$work/log" 2>&1 ||
      { cat "$work/log"; fail "grading with a good hidden.json failed"; }
    grep -q '^Visible checkpoints: m1: 2/2\.' "$work/log" || { cat "$work/log"; fail "no visible summary"; }
    grep -q '^Score 5 / 5 with the 1 hidden checkpoint' "$work/log" || { cat "$work/log"; fail "the console does not show the grade"; }
    if grep -q 'Score 5' "$work/out/results.json"; then fail "results.json's visible output gives the total away"; fi
    # README's example grade has the rubric's maxima.
    totals=$(for m in m1 m2 m3 m4 m5; do
               "$build/checkpoints/raster_grade" plan "$root/checkpoints/rubric.json" "$m" 0 | awk -v m="$m" '{ s += $5 } END { print m, s }'
             done)
    python3 - "$root/README.md" "$totals" <<'PY' || fail "README.md's example grade does not have checkpoints/rubric.json's maxima (above)"
import re, sys
line = next(l for l in open(sys.argv[1]) if l.startswith("Score ") and "Scene seed" in l)
maxima = dict(l.split() for l in sys.argv[2].splitlines())
assert int(re.search(r" / (\d+)\.", line).group(1)) == sum(int(v) for v in maxima.values()), line
for m, got in re.findall(r"(m\d): \d+/(\d+)\.", line):
    assert got == maxima[m], f"{m}: {got} in README.md, {maxima[m]} in the rubric"
PY
    ;;
  *) fail "unknown case" ;;
esac
check_clean
echo "ok: $case_name"
exit
}
