#!/usr/bin/env bash
# Opens the check report (check_results.html) in headless Chromium and requires: every picture
# on the page loaded, every checkpoint's section shows the student's picture (passing
# checkpoints too) or says it judges numbers only, every picture is linked relative to the page
# (so the build folder can move), and the measured error against run time comes after the
# checkpoints' sections (a student sees the failures first). Also leaves a screenshot beside the
# page for a person to look at.
set -euo pipefail
page=$1
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "skipped: chromium is not installed (bash tools/install-deps.sh installs it)"
  exit 77
fi
[ -f "$page" ] || { echo "no report at $page"; exit 1; }
page=$(realpath "$page")
flags=(--headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=5000)
# Chromium's own messages are kept and shown only when the page fails a check, so a failure
# that depends on the machine (a crash, a budget spent under load) says what Chromium saw.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
fail() {
  echo "$1"
  echo "(the page's DOM as dumped: ${#dom} characters; Chromium said, its D-Bus complaints left out:)"
  { grep -v ":dbus/" "$log" || true; } | tail -n 20
  exit 1
}
dom=$("$browser" "${flags[@]}" --dump-dom "file://$page" 2>"$log") || echo "chromium --dump-dom exited with status $?"
"$browser" "${flags[@]}" --window-size=1280,2400 --screenshot="${page%.html}.png" "file://$page" >/dev/null 2>&1 || true

sections=$({ grep -o '<h2 id="[^"]*"' <<<"$dom" || true; } | wc -l)
actuals=$({ grep -o 'alt="[^"]* actual"' <<<"$dom" || true; } | wc -l)
numbers=$({ grep -o 'class="numbers-only"' <<<"$dom" || true; } | wc -l)
broken=$(grep -o 'data-broken="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
pictures=$(grep -o 'data-pictures="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
echo "sections: $sections, student pictures: $actuals, numbers only: $numbers, pictures on the page: ${pictures:-?}, not loaded: ${broken:-?}"
[ "$sections" -gt 0 ] || fail "the report has no checkpoint sections"
[ $((actuals + numbers)) -eq "$sections" ] ||
  fail "a checkpoint section has neither a picture of the student's image nor a numbers-only note"
absolute=$({ grep -Eo 'src="(/|[a-z]+:)[^"]*"' <<<"$dom" || true; } | head -3)
[ -z "$absolute" ] ||
  fail "pictures linked by absolute paths (they break when the build folder moves): $absolute"
first_section=$(grep -bo '<h2 id="' <<<"$dom" | head -1 | cut -d: -f1)
measures=$({ grep -bo 'id="measures"' <<<"$dom" || true; } | head -1 | cut -d: -f1)
[ -z "$measures" ] || [ "$first_section" -lt "$measures" ] ||
  fail "the measured error against run time comes before the first checkpoint's section"
[ "${broken:-x}" = "0" ] || fail "pictures failed to load in the browser (or the page's load script never ran)"
echo "the report renders with every picture"
