#!/usr/bin/env bash
# bench/quality_table.sh [MESH...]: the quality table (bench/quality_table.cpp) for each
# mesh (default: the shared meshes below), with Blender's Tris to Quads beside petersen when
# `blender` is on the PATH (Debian: apt-get install blender; bench/blender_tris_to_quads.py runs
# headless). Writes bench/out/quality/table.md and one SVG of the distributions per mesh.
# Expects a Release build: TARGET=petersen_quality_bench scripts/build build/release ...
set -euo pipefail
cd "$(dirname "$0")/.."
shared=${PETERSEN_SHARED_MESHES:-../shared/meshes}
if [ $# -eq 0 ]; then
  set -- "$shared"/bunny.off.gz "$shared"/armadillo.obj.gz "$shared"/nefertiti.obj.gz \
    "$shared"/fertility.off.gz "$shared"/rocker-arm.obj.gz "$shared"/fandisk.obj.gz \
    "$shared"/armadillo-sub2.ply.gz
fi
bench=build/release/bench/petersen_quality_bench
out=bench/out/quality
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
{
  echo "| mesh | method | paired % | median ° | p95 ° | non-convex % | s | note |"
  echo "|---|---|---:|---:|---:|---:|---:|---|"
} >"$out/table.md"
for mesh in "$@"; do
  name=$(basename "$mesh")
  name=${name%%.*}
  externals=()
  if command -v blender >/dev/null 2>&1; then
    "$bench" --obj "$mesh" "$work/$name.obj"
    for mode in default off; do
      line=$(blender -b --factory-startup --python bench/blender_tris_to_quads.py -- \
        "$work/$name.obj" "$work/$name-$mode.obj" "$mode" 2>&1 | grep '^blender ')
      externals+=(--external "Blender $mode" "$work/$name-$mode.obj" "${line##* }")
    done
  fi
  nice "$bench" "$mesh" --svg "$out/$name.svg" "${externals[@]}" | tee -a "$out/table.md"
done
