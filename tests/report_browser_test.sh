#!/usr/bin/env bash
# What a browser makes of the report (ctest: report_browser; docs/report.md): the default
# comparison at 64x64 written as a report, then tests/report_screenshot.sh in headless Chromium
# (Debian's, installed by scripts/install-deps) checks that the summary table is whole in the
# first screen at 1400x1000 and that nothing but a table's own box scrolls sideways at 390 px,
# and shoots the summary section alone. The check is first shown to fail on the same page with
# a 2000 px wide block added, so a pass means something. About 15 s, most of it the comparison.
#
#   tests/report_browser_test.sh AABENCH_BINARY
set -euo pipefail
[[ $# -eq 1 && -x $1 ]] || { echo "usage: $0 AABENCH_BINARY" >&2; exit 2; }
aabench=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$aabench" compare --size 64x64 --runs 1 --jobs 2 --no-hardcases --quiet --out "$work/run" >/dev/null

# The check can fail: a copy of the page with a block wider than a phone must be refused.
mkdir "$work/wide"
cp -r "$work/run/images" "$work/run/plots" "$work/wide/"
sed 's|<body>|<body><div style="width:2000px;height:4px"></div>|' "$work/run/index.html" \
    >"$work/wide/index.html"
if "$here/report_screenshot.sh" "$work/wide" "$work/wide.png" --check-layout >/dev/null 2>&1; then
    echo "FAIL: the layout check passed a page with a 2000 px wide block" >&2
    exit 1
fi

"$here/report_screenshot.sh" "$work/run" "$work/page.png" 1400x1000 --check-layout
"$here/report_screenshot.sh" "$work/run" "$work/summary.png" 1400x1000 --section summary
