#!/usr/bin/env bash
# A page in headless Chromium (ctest browser.report_page, browser.paper_page): it loads with no console message, its
# figures load, its maths is MathML, the hover script (report) shows a point's values inside the axes and nothing
# outside, and a screenshot is written. Exit 77 (ctest: skipped) when chromium is not installed (scripts/setup.sh
# test installs it).
#   report_page.sh CLI WORK_DIR [report|paper]
set -euo pipefail
cli="$1"
work="$2"
kind="${3:-report}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
  echo "SKIP: chromium not installed (apt-get install chromium; scripts/setup.sh test installs it)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"

# Chromium as root needs --no-sandbox; console messages go to stderr as ":CONSOLE" lines.
run_browser() {
  timeout 60 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --allow-file-access-from-files \
    --enable-logging=stderr --v=0 --virtual-time-budget=5000 "$@"
}
# Prints the page's console messages (none: nothing) and leaves its DOM in $work/dom.html.
console_of() {
  run_browser --dump-dom "file://$1" > "$work/dom.html" 2> "$work/browser.log" || true
  grep -E ':CONSOLE[^]]*\]' "$work/browser.log" || true
}
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# The console check sees errors: a page that logs one and throws, in the harness's frame, must be caught.
mkdir -p "$work/control/report"
printf '<!DOCTYPE html><html><body><script>console.error("deliberate"); null.x;</script></body></html>\n' \
  > "$work/control/report/index.html"
sed "s|PAGE|report/index.html|" "$here/harness.html" > "$work/control/harness.html"
[ -n "$(console_of "$work/control/harness.html")" ] || fail "the console check did not see a deliberate error"

if [ "$kind" = paper ]; then
  "$cli" paper --quick --quiet --output "$work/report" > "$work/report.log" 2>&1 ||
    fail "rbcstab paper failed: $(tail -5 "$work/report.log")"
  figures="$(grep -o '<div class="fig">' "$work/report/index.html" | wc -l)"
else
  # A small report with a phase diagram (a 6 x 5 grid, two classes), so that a hover figure is on the page.
  {
    echo "index,i,j,ln_B,ln_C,verdict,l_Delta,status"
    for i in 0 1 2 3 4 5; do
      for j in 0 1 2 3 4; do
        lv=$((i > j ? 3 : 2))
        echo "$((i * 5 + j)),$i,$j,$i,$((j - 4)),$([ $lv = 2 ] && echo stable || echo unstable),$lv,success"
      done
    done
  } > "$work/phase.csv"
  "$cli" report --L 4 --T 20 --frames 2 --shape-resolution 12 --phase-diagram "$work/phase.csv" \
    --output "$work/report" --quiet > "$work/report.log" 2>&1 ||
    fail "rbcstab report failed: $(tail -5 "$work/report.log")"
  figures="$(grep -c '<figure>' "$work/report/index.html")"
fi

# The page in the harness's frame: its console messages are logged as the harness's own.
sed "s|PAGE|report/index.html|" "$here/harness.html" > "$work/harness.html"
messages="$(console_of "$work/harness.html")"
[ -z "$messages" ] || fail "console messages on the report page: $messages"
result="$(sed -n '/<pre id="result">/,/<\/pre>/p' "$work/dom.html")"
echo "$result"
field() { sed -n "s/.*$1=\\([^<]*\\).*/\\1/p" <<< "$result" | head -1; }
[ "$(field images)" = "$figures" ] && [ "$figures" -ge 6 ] || fail "images on the page: $(field images), figures: $figures"
[ -z "$(field broken)" ] || fail "images that did not load: $(field broken)"
[ "$(field math)" -ge 5 ] || fail "MathML elements: $(field math)"
if [ "$kind" = report ]; then
  [ "$(field tip)" = 1 ] || fail "the hover script did not run (no .hover-tip element)"
  [ "$(field hover_figures)" = 1 ] || fail "hover figures: $(field hover_figures) (the phase diagram expected)"
  field tip_inside | grep -q 'l_Delta = [23]' || fail "hover inside the axes showed: $(field tip_inside)"
  [ "$(field tip_outside)" = hidden ] || fail "hover outside the axes showed: $(field tip_outside)"
fi

run_browser --window-size=1200,3000 --screenshot="$work/${kind}_page.png" "file://$work/report/index.html" \
  > /dev/null 2>&1 || true
[ "$(stat -c %s "$work/${kind}_page.png" 2>/dev/null || echo 0)" -gt 50000 ] || fail "no screenshot written"
echo "screenshot: $work/${kind}_page.png"
