#!/usr/bin/env bash
# End-to-end tests of the petersen CLI: cli_test.sh PETERSEN EXAMPLE_MESH ALGORITHM...
set -uo pipefail
petersen=$1 example=$2; shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
check() {  # check NAME COMMAND...: the command must succeed
  if "${@:2}" >"$work/out" 2>&1; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAILED: $1"; cat "$work/out"; fi
}
refuses() {  # refuses NAME PATTERN COMMAND...: must fail, stderr naming PATTERN
  if "${@:3}" >"$work/out" 2>"$work/err"; then
    failed=$((failed + 1)); echo "FAILED (accepted): $1"
  elif grep -q -- "$2" "$work/err"; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAILED (message): $1"; cat "$work/err"; fi
}

check "info on the example" "$petersen" info "$example"
grep -q "genus 2" "$work/out" || { failed=$((failed + 1)); echo "FAILED: info does not say genus 2"; }
for algorithm in "$@"; do
  check "quad --algorithm $algorithm" "$petersen" quad "$example" "$work/q-$algorithm.obj" \
    --algorithm "$algorithm" --stats-json "$work/$algorithm.json"
  for key in algorithm faces_in triangles polygons_kept genus load_seconds check_seconds \
    dual_seconds initial_seconds initial_paired_percent unpaired_after_initial augment_seconds \
    matching_seconds verify_seconds pairs triangles_left added_vertices cut_edges \
    cut_edges_by_cause maximum_certified write_seconds total_seconds; do
    grep -q "\"$key\":" "$work/$algorithm.json" || {
      failed=$((failed + 1)); echo "FAILED: $algorithm stats lack $key"; }
  done
  grep -q '"triangles_left": 0,' "$work/$algorithm.json" || {
    failed=$((failed + 1)); echo "FAILED: $algorithm left triangles on a closed mesh"; }
  # The quads it wrote read back as a mesh of quads only.
  check "info on the quads ($algorithm)" "$petersen" info "$work/q-$algorithm.obj"
  grep -q "faces by corners: 4: 1550$" "$work/out" || {
    failed=$((failed + 1)); echo "FAILED: $algorithm did not write 1550 quads"; cat "$work/out"; }
done
# auto pairs in PS's place by the ordered sweep or Schrijver's exact matching (a voxel plate's
# dual is bipartite, in a local order); ps runs the paper's PS alone and reports neither.
check "generate a plate" "$petersen" generate "$work/plate.off"
for algorithm in auto ps; do
  check "quad --algorithm $algorithm on the plate" "$petersen" quad "$work/plate.off" \
    "$work/plate-$algorithm.off" --algorithm "$algorithm" --stats-json "$work/plate-$algorithm.json"
done
grep -qE '"(ordered_sweep|schrijver)": true' "$work/plate-auto.json" || {
  failed=$((failed + 1)); echo "FAILED: auto reports neither the sweep nor Schrijver's"; }
grep -q '"ordered_sweep": false' "$work/plate-ps.json" &&
  grep -q '"schrijver": false' "$work/plate-ps.json" || {
  failed=$((failed + 1)); echo "FAILED: ps reports the sweep or Schrijver's"; }
for format in off ply obj.gz; do
  check "quad to .$format" "$petersen" quad "$example" "$work/q.$format"
done

# Any mesh: a lone triangle is left, and --all-quad splits a boundary edge to make it a quad.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$work/open.off"
check "an open mesh" "$petersen" quad "$work/open.off" "$work/open-q.off" --stats-json "$work/open.json"
grep -q '"triangles_left": 1,' "$work/open.json" || { failed=$((failed + 1)); echo "FAILED: open mesh"; }
check "an open mesh, all quads" "$petersen" quad "$work/open.off" "$work/open-q.off" --all-quad \
  --stats-json "$work/open.json"
grep -q '"added_vertices": 1,' "$work/open.json" || { failed=$((failed + 1)); echo "FAILED: all-quad"; }
grep -q "^4 " "$work/open-q.off" || { failed=$((failed + 1)); echo "FAILED: all-quad wrote no quad"; }
# A quad beside two triangles: the quad is kept as it is, the triangles paired.
printf 'OFF\n6 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n4 0 1 2 3\n3 1 4 5\n3 1 5 2\n' \
  >"$work/mixed.off"
check "a mesh with a quad" "$petersen" quad "$work/mixed.off" "$work/mixed-q.off"
grep -q "^4 0 1 2 3$" "$work/mixed-q.off" || { failed=$((failed + 1)); echo "FAILED: quad not kept"; }
# info gives the quads' shape: the kept square and the paired one, both right-angled.
check "info on a mixed mesh" "$petersen" info "$work/mixed-q.off"
grep -q "^quality: 2 quads, worst corner median 0.0" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: info lacks the quality figures"; cat "$work/out"; }
# The threshold mode: a pair over it is a cut of cause shape and its triangles stay.
check "a threshold no quad meets" "$petersen" quad "$work/mixed.off" "$work/mixed-t.off" \
  --max-corner-deviation -1 --objective quality --stats-json "$work/mixed-t.json"
grep -q '"shape": 1' "$work/mixed-t.json" && grep -q '"triangles_left": 2,' "$work/mixed-t.json" || {
  failed=$((failed + 1)); echo "FAILED: threshold"; cat "$work/mixed-t.json"; }
refuses "--cross shape" "not a cut of the mesh's attributes" \
  "$petersen" quad "$work/mixed.off" "$work/mixed-t.off" --max-corner-deviation 10 --cross shape
# A failed run leaves the existing output as it was: a degenerate triangle cannot become a quad.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n' >"$work/degenerate.off"
cp "$work/mixed-q.off" "$work/keep.off"
refuses "all-quad on a degenerate triangle" "repeats a vertex" \
  "$petersen" quad "$work/degenerate.off" "$work/keep.off" --all-quad
cmp -s "$work/keep.off" "$work/mixed-q.off" || { failed=$((failed + 1)); echo "FAILED: OUT damaged"; }
ls "$work" | grep -q "tmp" && { failed=$((failed + 1)); echo "FAILED: a temporary file was left"; }
# OUT may be the input: it is read whole before anything is written.
cp "$work/mixed.off" "$work/same.off"
check "OUT is IN" "$petersen" quad "$work/same.off" "$work/same.off"
grep -q "^4 0 1 2 3$" "$work/same.off" || { failed=$((failed + 1)); echo "FAILED: OUT is IN"; }

refuses "an index out of range" "range.off" "$petersen" quad "$work/range.off" "$work/x.obj"
refuses "a missing file" "missing.obj" "$petersen" info "$work/missing.obj"
check "--cross the attributes' cuts" "$petersen" quad "$work/open.off" "$work/open-q.off" \
  --cross uv_seam,material,face_property
refuses "--cross a cut of the structure" "not a cut of the mesh's attributes: boundary" \
  "$petersen" quad "$work/open.off" "$work/x.off" --cross uv_seam,boundary
refuses "an unknown algorithm" "blossom" "$petersen" quad "$example" "$work/x.obj" --algorithm blossom
refuses "an unknown output format" "x.stl" "$petersen" quad "$example" "$work/x.stl"

# generate --kind: V and F of the OFF header are those of the generator's grid.
for spec in "klein 20 40" "open-grid 30 40" "projective 21 40"; do
  read -r kind vertices faces <<<"$spec"
  check "generate --kind $kind" "$petersen" generate "$work/$kind.off" --kind "$kind" --nx 5 \
    --ny 4 --subdivision 1
  header=$(sed -n 2p "$work/$kind.off")
  [ "$header" = "$vertices $faces 0" ] || {
    failed=$((failed + 1)); echo "FAILED: generate --kind $kind wrote header $header"; }
done
check "generate with holes, fins, pinches, flips" "$petersen" generate "$work/mixed.obj" \
  --kind klein --holes 2 --fins 2 --pinches 1 --flip-faces 3 --seed 5
refuses "an unknown kind" "torus" "$petersen" generate "$work/x.off" --kind torus

# render: PNG and SVG of a mesh and of a quad result (the pixels are checked by tests/render).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8}'; }
check "render a mesh" "$petersen" render "$example" "$work/example.png" --width 640 --height 480
[ "$(png_size "$work/example.png")" = "640x480" ] || {
  failed=$((failed + 1)); echo "FAILED: render wrote $(png_size "$work/example.png")"; }
check "render as SVG" "$petersen" render "$example" "$work/example.svg" --view 0,0,-1
grep -q "<svg" "$work/example.svg" || { failed=$((failed + 1)); echo "FAILED: render SVG"; }
check "quad --render" "$petersen" quad "$work/open.off" "$work/open-q.off" --all-quad \
  --render "$work/open.png"
[ "$(png_size "$work/open.png")" = "800x800" ] || { failed=$((failed + 1)); echo "FAILED: quad --render"; }
refuses "a picture that is not png or svg" "png or .svg" "$petersen" render "$example" "$work/x.jpg"
refuses "quad --render to a jpg" "png or .svg" "$petersen" quad "$example" "$work/x.obj" \
  --render "$work/x.jpg"
refuses "a view of three zeros" "view" "$petersen" render "$example" "$work/x.png" --view 0,0,0

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
