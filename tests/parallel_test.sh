#!/usr/bin/env bash
# GNU parallel on this machine as its only host (-S :): scripts/parallel/compare runs a small
# sweep in 3 shards and merges them, and the merged error columns must equal the unsharded
# run's bit for bit (merge --same-as). CI runs it (.ci/run); docs/cluster.md.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v parallel >/dev/null; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "parallel_test: skipped: GNU parallel is not installed (scripts/install-deps parallel)"
    exit 0
  fi
  scripts/install-deps parallel
fi
aabench=$PWD/build/aabench
[[ -x $aabench ]] || { echo "parallel_test: no $aabench: run scripts/build first" >&2; exit 1; }
work=$(mktemp -d /tmp/aabench_parallel.XXXXXX)
trap 'rm -rf "$work"' EXIT
opts=(--methods none,exact,box-multiscan --patterns star,strips --size 32x32 --runs 1 --sweep
      --no-hardcases)
"$aabench" compare "${opts[@]}" --quiet --out "$work/whole"
AABENCH=$aabench AABENCH_SAME_AS=$work/whole scripts/parallel/compare : "$work/sweep" 3 \
  "${opts[@]}" >"$work/out.txt"
grep '^merged == unsharded' "$work/out.txt"
echo "parallel_test: passed (3 shards over parallel -S :, merged == unsharded)"
