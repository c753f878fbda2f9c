#!/usr/bin/env bash
# The check report of a run that has measures (the student's run of the skeleton has none): the
# milestone 5 reference stands in for the student's code, run by a stand-in for CTest, in a
# build folder of its own that then moves. html_report_test.sh checks the page there: every
# picture loads (links relative to the page), and the measured error against run time comes
# after the checkpoints' sections.
#
#   html_report_measures_test.sh <checkpoint_summary> <checkpoints_m5_reference> <html_report_test.sh>
set -euo pipefail
summary=$(realpath "$1") checkpoints=$(realpath "$2") report_test=$(realpath "$3")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run="$work/build/checkpoints/run/m5_student"
mkdir -p "$run"
# A number checkpoint and two pictures with measures.
cat >"$work/ctest" <<STANDIN
#!/usr/bin/env bash
cd "$run" && for id in m5.wrap m5.fill_triangle m5.grazing; do "$checkpoints" "\$id"; done >/dev/null 2>&1
STANDIN
chmod +x "$work/ctest"
"$summary" "$work/ctest" "$work/build" unused >"$work/summary.txt" || { cat "$work/summary.txt"; exit 1; }
grep -q 'id="measures"' "$work/build/check_results.html" || { echo "the report has no measures"; exit 1; }
mv "$work/build" "$work/moved"
bash "$report_test" "$work/moved/check_results.html"
