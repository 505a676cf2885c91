#!/usr/bin/env bash
# Renders an HTML report (results/RUN/index.html, harness/report/html_report.h) in headless Chromium
# and checks what a reader would see: every image and plot the page references is on disk and
# non-empty, and the screenshot exists and is not blank. Not part of ctest: it needs Chromium
# (installed here with apt-get when missing, ~30 s) and takes seconds. docs/report.md says more.
#
#   tests/report_screenshot.sh REPORT_DIR [OUT.png] [WIDTHxHEIGHT]
#
# OUT.png defaults to REPORT_DIR/screenshot.png, the window to 1200x900 (docs/building.md); a taller
# window (e.g. 1200x5000) shows a whole pattern: table, plot and image grid.
set -euo pipefail

usage() { echo "usage: $0 REPORT_DIR [OUT.png] [WIDTHxHEIGHT]" >&2; exit 2; }
[[ $# -ge 1 && $# -le 3 ]] || usage
report_dir=$(cd "$1" && pwd) || usage
out=${2:-$report_dir/screenshot.png}
window=${3:-1200x900}
[[ $window =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "window must be WIDTHxHEIGHT" >&2; exit 2; }
window_size="${BASH_REMATCH[1]},${BASH_REMATCH[2]}"
case $out in /*) ;; *) out=$PWD/$out ;; esac
page=$report_dir/index.html
[[ -s $page ]] || { echo "FAIL: $page is missing or empty" >&2; exit 1; }

# 1. Everything the page points at (src= and href=, page anchors aside) is there, non-empty, and
#    local: the report must open offline.
missing=0
refs=0
while IFS= read -r ref; do
    refs=$((refs + 1))
    case $ref in
        *://*) echo "FAIL: network reference $ref" >&2; missing=1; continue ;;
    esac
    if [[ ! -s $report_dir/$ref ]]; then
        echo "FAIL: $ref is referenced but missing or empty" >&2
        missing=1
    fi
done < <(grep -oE '(src|href)="[^"#][^"]*"' "$page" | sed -E 's/^(src|href)="//; s/"$//' | sort -u)
[[ $missing -eq 0 ]] || exit 1
images=$(grep -oE '<img src="[^"]*\.png"' "$page" | wc -l)
plots=$(grep -c '<svg xmlns' "$page" || true)
echo "page: $refs files referenced, all present; $images images, $plots inline SVGs (plots, colour bars)"
[[ $images -gt 0 && $plots -gt 0 ]] || { echo "FAIL: no images or no plots on the page" >&2; exit 1; }

# 2. Chromium, installed when missing.
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $browser ]]; then
    echo "installing chromium (apt-get, ~30 s)" >&2
    sudo=()
    [[ $(id -u) -eq 0 ]] || sudo=(sudo)
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get install -y -q chromium >/dev/null ||
        { "${sudo[@]}" apt-get update -q >/dev/null &&
          "${sudo[@]}" apt-get install -y -q chromium >/dev/null; }
    browser=$(command -v chromium)
fi

# 3. The screenshot, with the flags of docs/building.md: no network, no profile left behind.
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
rm -f "$out"
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --screenshot="$out" --window-size="$window_size" \
    "file://$page" >/dev/null 2>&1 || true  # it exits non-zero on harmless dbus noise
[[ -s $out ]] || { echo "FAIL: no screenshot written to $out" >&2; exit 1; }

# 4. Not blank: OpenImageIO's statistics say the image is not constant, and it varies enough
#    to hold more than a heading (a white page with a line of text has a tiny deviation).
stats=$(oiiotool --stats "$out")
if grep -q 'Constant: Yes' <<<"$stats"; then
    echo "FAIL: $out is a constant image (blank page)" >&2
    exit 1
fi
deviation=$(awk '/Stats StdDev:/ { m = 0; for (i = 3; i <= 5; ++i) if ($i > m) m = $i; print m }' \
            <<<"$stats")
min_deviation=10  # of 255: tables, plots and images, not a near-white page
awk -v d="$deviation" -v m="$min_deviation" 'BEGIN { exit !(d >= m) }' ||
    { echo "FAIL: $out is nearly blank (max channel std dev $deviation of 255)" >&2; exit 1; }
echo "screenshot: $out ($(stat -c %s "$out") bytes, window $window, channel std dev $deviation)"
