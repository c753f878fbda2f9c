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
flags=(--headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=5000)
dom=$("$browser" "${flags[@]}" --dump-dom "file://$page" 2>/dev/null)
"$browser" "${flags[@]}" --window-size=1280,2400 --screenshot="${page%.html}.png" "file://$page" >/dev/null 2>&1 || true

sections=$(grep -o '<h2 id="[^"]*"' <<<"$dom" | wc -l)
actuals=$(grep -o 'alt="[^"]* actual"' <<<"$dom" | wc -l)
numbers=$({ grep -o 'class="numbers-only"' <<<"$dom" || true; } | wc -l)
broken=$(grep -o 'data-broken="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
pictures=$(grep -o 'data-pictures="[0-9]*"' <<<"$dom" | grep -o '[0-9]*' || true)
echo "sections: $sections, student pictures: $actuals, numbers only: $numbers, pictures on the page: ${pictures:-?}, not loaded: ${broken:-?}"
[ "$sections" -gt 0 ] || { echo "the report has no checkpoint sections"; exit 1; }
[ $((actuals + numbers)) -eq "$sections" ] ||
  { echo "a checkpoint section has neither a picture of the student's image nor a numbers-only note"; exit 1; }
absolute=$({ grep -Eo 'src="(/|[a-z]+:)[^"]*"' <<<"$dom" || true; } | head -3)
[ -z "$absolute" ] ||
  { echo "pictures linked by absolute paths (they break when the build folder moves): $absolute"; exit 1; }
first_section=$(grep -bo '<h2 id="' <<<"$dom" | head -1 | cut -d: -f1)
measures=$({ grep -bo 'id="measures"' <<<"$dom" || true; } | head -1 | cut -d: -f1)
[ -z "$measures" ] || [ "$first_section" -lt "$measures" ] ||
  { echo "the measured error against run time comes before the first checkpoint's section"; exit 1; }
[ "${broken:-x}" = "0" ] || { echo "pictures failed to load in the browser (or the page's load script never ran)"; exit 1; }
echo "the report renders with every picture"
