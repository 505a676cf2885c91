#!/usr/bin/env bash
# Renders an HTML report (results/RUN/index.html, harness/report/html_report.h) in headless Chromium
# and checks what a reader would see: every image and plot the page references is on disk and
# non-empty, and the screenshot exists and is not blank. Chromium comes from Debian
# (scripts/install-deps installs it; here with apt-get when still missing, ~30 s). docs/report.md
# says more; tests/report_browser_test.sh runs it under ctest.
#
#   tests/report_screenshot.sh REPORT_DIR [OUT.png] [WIDTHxHEIGHT] [--section ID] [--check-layout]
#
# OUT.png defaults to REPORT_DIR/screenshot.png, the window to 1200x900 (docs/building.md); a taller
# window (e.g. 1200x5000) shows a whole pattern: table, plot and image grid.
#   --section ID     shoot only that section of the page (summary, a pattern's name, context, ...):
#                    every other part of the page is hidden, the section starts at the top.
#   --check-layout   also measure the page in two frames: at 1400x1000 the summary table must be
#                    whole in the first screen (no scrolling, down or sideways), and at 390 px wide
#                    nothing outside a table's own scrolling box may stick out sideways.
set -euo pipefail

usage() {
    echo "usage: $0 REPORT_DIR [OUT.png] [WIDTHxHEIGHT] [--section ID] [--check-layout]" >&2
    exit 2
}
section=
check_layout=0
positional=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --section) [[ $# -ge 2 && -n $2 ]] || usage; section=$2; shift 2 ;;
        --check-layout) check_layout=1; shift ;;
        -*) usage ;;
        *) positional+=("$1"); shift ;;
    esac
done
[[ ${#positional[@]} -ge 1 && ${#positional[@]} -le 3 ]] || usage
report_dir=$(cd "${positional[0]}" && pwd) || usage
out=${positional[1]:-$report_dir/screenshot.png}
window=${positional[2]:-1200x900}
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
#    Helper pages go beside index.html (its images are relative to it) and are removed on exit.
profile=$(mktemp -d)
helpers=()
trap 'rm -rf "$profile" "${helpers[@]}"' EXIT
browse() {  # browse URL FLAGS...: Chromium headless on a page
    local url=$1
    shift
    timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$profile" "$@" "$url" 2>/dev/null
}
shot_page=$page
if [[ -n $section ]]; then
    grep -q "<section id=\"$section\">" "$page" ||
        { echo "no section '$section' in $page (ids: $(grep -oE '<section id="[^"]*"' "$page" |
                                                      sed -E 's/.*id="//; s/"$//' | tr '\n' ' '))" >&2
          exit 2; }
    # The page as it is, with every other part of the body hidden: the section at the top.
    shot_page=$report_dir/.screenshot-section.html
    helpers+=("$shot_page")
    sed "s|</head>|<style>body>*:not(#$section){display:none!important}</style></head>|" \
        "$page" >"$shot_page"
fi
rm -f "$out"
# It exits non-zero on harmless dbus noise: the file it writes is what counts.
browse "file://$shot_page" --screenshot="$out" --window-size="$window_size" >/dev/null || true
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

# 5. The layout, measured by the browser (--check-layout). Headless Chromium will not make a
#    window narrower than 500 px, so the page is measured in two frames of exactly the sizes
#    wanted, by a script in a helper page that reads the frames' layout once both have loaded
#    (file pages may read each other with --allow-file-access-from-files) and writes what it
#    found into its own DOM, which --dump-dom prints.
[[ $check_layout -eq 1 ]] || exit 0
wide_w=1400 wide_h=1000 narrow_w=390 narrow_h=844
layout_page=$report_dir/.layout-check.html
helpers+=("$layout_page")
cat >"$layout_page" <<HTML
<!DOCTYPE html><html><body style="margin:0">
<iframe id="wide" src="index.html" style="border:0;width:${wide_w}px;height:${wide_h}px"></iframe>
<iframe id="narrow" src="index.html" style="border:0;width:${narrow_w}px;height:${narrow_h}px"></iframe>
<script>
var loaded = 0;
function sticksOut(win) {
  // Elements whose right edge passes the frame's or whose content spills out of them, outside a
  // table's scrolling box (a box itself counts) and not inside an SVG (the SVG element counts).
  var found = [];
  win.document.querySelectorAll('body *').forEach(function(e) {
    if (e.parentElement && e.parentElement.closest('.table-box, svg')) return;
    var r = e.getBoundingClientRect();
    // Its box past the frame's edge, or its content (a long word, a wide child) past its box.
    var spills = e.clientWidth > 0 && e.scrollWidth > e.clientWidth + 1 &&
                 win.getComputedStyle(e).overflowX === 'visible';
    if (r.width > 0 && (r.right > win.innerWidth + 0.5 || spills)) {
      var c = typeof e.className === 'string' && e.className ? '.' + e.className.split(' ')[0] : '';
      found.push(e.tagName.toLowerCase() + c + '@' + Math.round(r.right));
    }
  });
  return found;
}
function measure() {
  var lines = [];
  var wide = document.getElementById('wide').contentWindow;
  var box = wide.document.querySelector('#summary .table-box');
  if (!box) {
    lines.push('summary missing');
  } else {
    var r = box.getBoundingClientRect();
    lines.push('summary ' + Math.round(r.top) + ' ' + Math.round(r.right) + ' ' +
               Math.round(r.bottom) + ' scroll ' + (box.scrollWidth - box.clientWidth) + ' ' +
               (box.scrollHeight - box.clientHeight) + ' in ' + wide.innerWidth + 'x' +
               wide.innerHeight);
  }
  var narrow = document.getElementById('narrow').contentWindow;
  var out = sticksOut(narrow);
  lines.push('narrow ' + narrow.innerWidth + ' scrollWidth ' +
             narrow.document.documentElement.scrollWidth + ' sticking-out ' + out.length + ' ' +
             out.slice(0, 8).join(' '));
  var pre = document.createElement('pre');
  pre.id = 'layout';
  pre.textContent = lines.join('\\n');
  document.body.appendChild(pre);
}
['wide', 'narrow'].forEach(function(id) {
  document.getElementById(id).addEventListener('load', function() { if (++loaded === 2) measure(); });
});
</script></body></html>
HTML
dom=$(browse "file://$layout_page" --allow-file-access-from-files \
      --window-size=$((wide_w + narrow_w + 20)),$((wide_h + 20)) --dump-dom || true)
report=$(sed -n '/<pre id="layout">/,/<\/pre>/p' <<<"$dom" | sed -E 's/<[^>]*>//g')
[[ -n $report ]] || { echo "FAIL: the layout check page reported nothing" >&2; exit 1; }
echo "layout: ${report//$'\n'/; }"
failed=0
read -r _ top right bottom _ scroll_x scroll_y _ _ < <(grep '^summary' <<<"$report") || true
if [[ -z ${bottom:-} || ! $bottom =~ ^-?[0-9]+$ ]]; then
    echo "FAIL: the page has no summary table" >&2
    failed=1
elif ((top < 0 || bottom > wide_h || right > wide_w || scroll_x > 0 || scroll_y > 0)); then
    echo "FAIL: at ${wide_w}x${wide_h} the summary table is not whole in the first screen" \
         "(top $top, right $right, bottom $bottom, its box scrolls by $scroll_x, $scroll_y)" >&2
    failed=1
fi
read -r _ _ _ scroll_width _ sticking _ < <(grep '^narrow' <<<"$report") || true
if [[ -z ${sticking:-} ]] || ((scroll_width > narrow_w || sticking > 0)); then
    echo "FAIL: at $narrow_w px wide the page is $scroll_width px wide; sticking out:" \
         "$(grep '^narrow' <<<"$report" | cut -d' ' -f6-)" >&2
    failed=1
fi
exit $failed
