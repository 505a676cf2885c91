#!/usr/bin/env bash
# Rewrites the seed corpus of world_fuzz (docs/fuzzing.md): every built-in 3-D pattern as a
# version-2 scene file at 24 x 24, with parameters small enough that each seed stays within
# the target's limits (512 vertices, 160 faces) and runs in milliseconds.
# Usage: tests/fuzz/make_world_corpus.sh [path to aabench, default build/aabench]
set -euo pipefail
cd "$(dirname "$0")/../.."
aabench=${1:-build/aabench}
out=tests/fuzz/corpus/world_fuzz
mkdir -p "$out"
for spec in room room:mats=1,windows=0,edges=black blocks:count=2 interpenetrate \
    mesh:subdivisions=1 terrain:cells=6 terrain-edges:cells=4 \
    torus:major_segments=8,minor_segments=4 checkerboard:squares=4 mirror \
    foliage:leaves=100 foliage:leaves=100,seed=7,shadows=on; do
  name=$(printf '%s' "$spec" | tr ':,=' '___')
  "$aabench" export --pattern "$spec" --size 24x24 --out "$out/$name.json"
done
