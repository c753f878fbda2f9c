#!/usr/bin/env bash
# The Gradescope package end to end, as Gradescope runs it, in a simulated /autograder
# (AUTOGRADER_ROOT) as root with the `plain` sandbox (Gradescope's containers have no
# namespaces): build the zip, unpack it, run setup.sh, put the reference in as the submission,
# run run_autograder; results.json must give full marks with Gradescope's fields; then
# milestone 1's skeleton alone must score 0.
#   gradescope_test.sh <uid-unused>
#   gradescope_test.sh dirty     (fast, no root: only that uncommitted changes are told as left out)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
if [ "${1:-}" = dirty ]; then
  # In a clone (with this tree's gradescope-package, committed there): a clean tree packs with
  # no warning; a changed rubric and an untracked file are each named on stderr as NOT in the
  # package, and the package holds the committed rubric.
  work=$(mktemp -d /tmp/gradescope-dirty.XXXXXX)
  trap 'rm -rf "$work"' EXIT
  git clone -q "$root" "$work/repo"
  cp "$root/tools/grading/gradescope-package" "$work/repo/tools/grading/gradescope-package"
  git -C "$work/repo" -c user.name=test -c user.email=test@example.org commit -qam "this tree's package script" || true
  bash "$work/repo/tools/grading/gradescope-package" "$work/clean.zip" 2>"$work/clean.err"
  if grep -q WARNING "$work/clean.err"; then cat "$work/clean.err"; echo "FAIL: a clean tree is warned about"; exit 1; fi
  printf '\n' >>"$work/repo/checkpoints/rubric.json"
  : >"$work/repo/checkpoints/notes.txt"
  bash "$work/repo/tools/grading/gradescope-package" "$work/dirty.zip" 2>"$work/dirty.err"
  for want in "NOT in it" "M checkpoints/rubric.json" "?? checkpoints/notes.txt"; do
    grep -qF -- "$want" "$work/dirty.err" || { cat "$work/dirty.err"; echo "FAIL: the warning does not say '$want'"; exit 1; }
  done
  unzip -p "$work/dirty.zip" checkpoints/rubric.json | cmp -s - <(git -C "$work/repo" show HEAD:checkpoints/rubric.json) ||
    { echo "FAIL: the package's rubric is not the committed one"; exit 1; }
  echo "ok: uncommitted changes are told as left out"
  exit 0
fi
[ "$(id -u)" = 0 ] || { echo "skipped: needs root"; exit 77; }
work=$(mktemp -d /tmp/gradescope-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
chmod 711 "$work"
ag=$work/autograder
mkdir -p "$ag/source" "$ag/submission" "$work/hidden"
cat >"$work/hidden/hidden.json" <<'JSON'
{"checkpoints": [{"name": "hidden.steep", "milestone": "m1", "scene": "m1.octant_2", "seed": 4242, "points": 3}]}
JSON
bash "$root/tools/grading/gradescope-package" "$work/autograder.zip" --hidden "$work/hidden"
(cd "$ag/source" && unzip -qq "$work/autograder.zip")
for f in setup.sh run_autograder hidden/hidden.json; do [ -f "$ag/source/$f" ] || { echo "no $f in the zip"; exit 1; }; done
AUTOGRADER_ROOT=$ag bash "$ag/source/setup.sh" >"$work/setup.log" 2>&1 || { tail -n 30 "$work/setup.log"; exit 1; }
cp "$root/solutions/milestone1_lines/lines.cpp" "$root/solutions/milestone2_triangles/triangles.cpp" \
   "$root/solutions/milestone3_transforms/transforms.cpp" \
   "$root/solutions/milestone4_depth_lighting/depth_lighting.cpp" \
   "$root/solutions/milestone5_textures_shadows/textures_shadows.cpp" "$ag/submission/"
AUTOGRADER_ROOT=$ag RASTER_SANDBOX_MODE=plain bash "$ag/source/run_autograder" >"$work/run.log" 2>&1 || true
python3 - "$ag/results/results.json" full <<'PY' || { cat "$work/run.log"; exit 1; }
import json, sys
r = json.load(open(sys.argv[1]))
for key in ("score", "execution_time", "output", "tests"):
    assert key in r, f"results.json has no {key}"
for t in r["tests"]:
    for key in ("name", "score", "max_score", "status", "output", "visibility"):
        assert key in t, f"a test has no {key}: {t}"
total = sum(t["max_score"] for t in r["tests"])
assert total > 0 and abs(r["score"] - total) < 1e-9, f"the reference scores {r['score']} of {total}"
hidden = [t for t in r["tests"] if "hidden.steep" in t["name"]]
assert hidden and hidden[0]["visibility"] == "after_published", "the hidden checkpoint is missing or visible"
print("reference:", r["score"], "of", total)
PY
# The skeleton of milestone 1 alone (a student who has only begun): its checkpoints score 0,
# and the milestones without a file score 0 too. (grade_test.sh grades the whole skeleton.)
rm -f "$ag/submission/"*
cp "$root/milestone1_lines/lines.cpp" "$ag/submission/"
AUTOGRADER_ROOT=$ag RASTER_SANDBOX_MODE=plain bash "$ag/source/run_autograder" >"$work/run.log" 2>&1 || true
python3 -c "
import json,sys; r=json.load(open('$ag/results/results.json')); assert r['score']==0, r['score']; print('skeleton: 0')" ||
  { cat "$work/run.log"; exit 1; }
