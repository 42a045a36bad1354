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
    --objective pairs --algorithm "$algorithm" --stats-json "$work/$algorithm.json"
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
    "$work/plate-$algorithm.off" --objective pairs --algorithm "$algorithm" --stats-json "$work/plate-$algorithm.json"
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
# The threshold mode: a pair over it is a cut of cause shape and its triangles stay. Vertex 5
# moved off the square makes the pair's quad a trapezoid, 26.6 degrees off at its worst corner.
sed 's/^2 1 0$/2.5 1 0/' "$work/mixed.off" >"$work/trapezoid.off"
check "a threshold no quad meets" "$petersen" quad "$work/trapezoid.off" "$work/mixed-t.off" \
  --max-corner-deviation 1 --objective quality --stats-json "$work/mixed-t.json"
grep -q '"shape": 1' "$work/mixed-t.json" && grep -q '"triangles_left": 2,' "$work/mixed-t.json" || {
  failed=$((failed + 1)); echo "FAILED: threshold"; cat "$work/mixed-t.json"; }
! grep -q "picks the cheapest" "$work/out" || { failed=$((failed + 1)); echo "FAILED: hint"; }
# A threshold with the pairs objective pairs within it at random: the summary points to
# --objective quality.
check "a threshold alone" "$petersen" quad "$work/trapezoid.off" "$work/mixed-t.off" \
  --max-corner-deviation 1 --objective pairs
grep -q "^threshold .*--objective quality picks the cheapest" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: threshold hint"; cat "$work/out"; }
refuses "--cross shape" "unknown value shape: one of uv_seam, normal_seam" \
  "$petersen" quad "$work/mixed.off" "$work/mixed-t.off" --max-corner-deviation 10 --cross shape
# A degenerate triangle is kept as it is under --all-quad, and counted.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n' >"$work/degenerate.off"
check "all-quad on a degenerate triangle" "$petersen" quad "$work/degenerate.off" \
  "$work/degenerate-q.off" --all-quad
grep -q "^degenerate  1 faces" "$work/out" || { failed=$((failed + 1)); echo "FAILED: degenerate count"; }
# A failed run leaves the existing output as it was: a prism's two triangles, each walled in by
# the quads --keep-polygons keeps, cannot become quads.
printf 'OFF\n6 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 1\n0 1 1\n3 0 2 1\n3 3 4 5\n4 0 1 4 3\n4 1 2 5 4\n4 2 0 3 5\n' \
  >"$work/prism.off"
cp "$work/mixed-q.off" "$work/keep.off"
refuses "all-quad on walled-in triangles" "no all-quad mesh exists" \
  "$petersen" quad "$work/prism.off" "$work/keep.off" --all-quad --keep-polygons
cmp -s "$work/keep.off" "$work/mixed-q.off" || { failed=$((failed + 1)); echo "FAILED: OUT damaged"; }
ls "$work" | grep -q "tmp" && { failed=$((failed + 1)); echo "FAILED: a temporary file was left"; }
# Nor does one that fails on its stats: OUT is written (whole), the old stats file stays whole.
mkdir "$work/stats-folder"
refuses "--stats-json onto a folder" "stats-folder" \
  "$petersen" quad "$work/mixed.off" "$work/keep2.off" --stats-json "$work/stats-folder"
[ -d "$work/stats-folder" ] && [ -z "$(ls "$work/stats-folder")" ] || {
  failed=$((failed + 1)); echo "FAILED: --stats-json damaged the folder"; }
echo '{"old": true}' >"$work/old.json"
printf 'OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n' >"$work/nan.off"
refuses "NaN coordinates leave OUT and the stats as they were" "vertex 1" \
  "$petersen" quad "$work/nan.off" "$work/keep.off" --stats-json "$work/old.json"
cmp -s "$work/keep.off" "$work/mixed-q.off" || { failed=$((failed + 1)); echo "FAILED: OUT damaged"; }
grep -q '"old": true' "$work/old.json" || { failed=$((failed + 1)); echo "FAILED: stats damaged"; }
ls "$work" | grep -q "tmp" && { failed=$((failed + 1)); echo "FAILED: a temporary file was left"; }
# OUT may be the input: it is read whole before anything is written.
cp "$work/mixed.off" "$work/same.off"
check "OUT is IN" "$petersen" quad "$work/same.off" "$work/same.off"
grep -q "^4 0 1 2 3$" "$work/same.off" || { failed=$((failed + 1)); echo "FAILED: OUT is IN"; }

# Coordinates that are not finite, in every reader: refused naming the file, line or element,
# and the vertex. The binary PLYs hold x, y, z as little-endian doubles, then as big-endian floats.
printf 'v 0 0 0\nv 1 0 -inf\nv 0 1 0\nf 1 2 3\n' >"$work/inf.obj"
ply_head() {  # ply_head FORMAT TYPE
  printf 'ply\nformat %s 1.0\nelement vertex 3\nproperty %s x\nproperty %s y\nproperty %s z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n' "$1" "$2" "$2" "$2"
}
{ ply_head ascii float; printf '0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n'; } >"$work/nan-ascii.ply"
zero8='\x00\x00\x00\x00\x00\x00\x00\x00' one8='\x00\x00\x00\x00\x00\x00\xf0\x3f'
nan8='\x00\x00\x00\x00\x00\x00\xf8\x7f'
{ ply_head binary_little_endian double
  printf "$zero8$zero8$zero8$one8$nan8$zero8$zero8$one8$zero8"
  printf '\x03\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00'; } >"$work/nan-le.ply"
zero4='\x00\x00\x00\x00' one4='\x3f\x80\x00\x00' inf4='\xff\x80\x00\x00'
{ ply_head binary_big_endian float
  printf "$zero4$zero4$zero4$one4$inf4$zero4$zero4$one4$zero4"
  printf '\x03\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x02'; } >"$work/inf-be.ply"
refuses "NaN in an OFF" "nan.off:4: vertex 1" "$petersen" quad "$work/nan.off" "$work/x.off"
refuses "-inf in an OBJ" "inf.obj:2: vertex 2" "$petersen" quad "$work/inf.obj" "$work/x.off"
refuses "NaN in an ascii PLY" "nan-ascii.ply:11: vertex 1" \
  "$petersen" quad "$work/nan-ascii.ply" "$work/x.off"
refuses "NaN in a binary PLY of doubles" "nan-le.ply: vertex 1: non-finite y" \
  "$petersen" quad "$work/nan-le.ply" "$work/x.off"
refuses "-inf in a big-endian PLY of floats" "inf-be.ply: vertex 1: non-finite y" \
  "$petersen" quad "$work/inf-be.ply" "$work/x.off"
# Empty input: no faces is no mesh to pair.
printf 'OFF\n0 0 0\n' >"$work/empty.off"
printf 'v 0 0 0\nv 1 0 0\n' >"$work/points.obj"
refuses "an OFF with no faces" "empty.off: no faces" "$petersen" quad "$work/empty.off" "$work/x.off"
refuses "an OBJ of vertices only" "points.obj: no faces" \
  "$petersen" quad "$work/points.obj" "$work/x.off"
# Options out of range: CLI11 names the flag, before any file is read.
for spec in "--max-corner-deviation nan" "--max-corner-deviation -1" \
  "--max-corner-deviation 270.5" "--sharp-angle 181" "--sharp-angle inf" "--threads 1025" \
  "--render-width 10" "--stats-json $work/no-such-folder/s.json"; do
  read -r flag value <<<"$spec"
  refuses "$flag $value" "$flag" "$petersen" quad "$work/mixed.off" "$work/x.off" "$flag" "$value"
done
refuses "--view zero" "--view" "$petersen" quad "$work/mixed.off" "$work/x.off" \
  --render "$work/x.png" --view 0,0,0
refuses "OUT in no folder" "no such folder" "$petersen" quad "$work/mixed.off" "$work/nope/x.off"
check "the ends of the ranges" "$petersen" quad "$work/mixed.off" "$work/x.off" \
  --max-corner-deviation 270 --sharp-angle 0 --threads 1024

# Triangles left by attribute cuts: the summary and the stats name the causes and the --cross
# that lets pairs cross them. A square of two triangles in two materials: both are left.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n' \
  >"$work/materials.obj"
check "two materials" "$petersen" quad "$work/materials.obj" "$work/x.obj" \
  --stats-json "$work/materials.json"
grep -q "100.0 % of the triangles left.*(material 1); --cross material lets" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: the summary does not say why"; cat "$work/out"; }
grep -q '"cross_to_pair": {"material": 1}' "$work/materials.json" || {
  failed=$((failed + 1)); echo "FAILED: the stats do not say why"; cat "$work/materials.json"; }
check "two materials crossed" "$petersen" quad "$work/materials.obj" "$work/x.obj" \
  --cross material --stats-json "$work/materials.json"
grep -q '"triangles_left": 0,' "$work/materials.json" &&
  ! grep -q "cross_to_pair" "$work/materials.json" && ! grep -q "^left by" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: --cross material"; cat "$work/out"; }

printf '0 1\n# a comment\n1 7\n' >"$work/keep-edges.txt"
refuses "--keep-edges out of range" "keep-edges.txt:3: vertex id 7 out of range (6 vertices)" \
  "$petersen" quad "$work/mixed.off" "$work/x.off" --keep-edges "$work/keep-edges.txt"
refuses "an index out of range" "range.off" "$petersen" quad "$work/range.off" "$work/x.obj"
refuses "a missing file" "missing.obj" "$petersen" info "$work/missing.obj"
check "--cross the attributes' cuts" "$petersen" quad "$work/open.off" "$work/open-q.off" \
  --cross uv_seam,material,face_property
refuses "--cross a cut of the structure" "unknown value boundary: one of uv_seam" \
  "$petersen" quad "$work/open.off" "$work/x.off" --cross uv_seam,boundary
refuses "an unknown algorithm" "blossom" "$petersen" quad "$example" "$work/x.obj" --algorithm blossom
refuses "an unknown output format" "x.stl" "$petersen" quad "$example" "$work/x.stl"

# generate --kind: V and F of the OFF header are those of the generator's grid.
for spec in "klein 20 40 --nx 5 --ny 4" "open-grid 30 40 --nx 5 --ny 4" \
  "projective 21 40 --subdivision 1"; do
  read -r kind vertices faces size <<<"$spec"
  # shellcheck disable=SC2086 # $size is flags
  check "generate --kind $kind" "$petersen" generate "$work/$kind.off" --kind "$kind" $size
  header=$(sed -n 2p "$work/$kind.off")
  [ "$header" = "$vertices $faces 0" ] || {
    failed=$((failed + 1)); echo "FAILED: generate --kind $kind wrote header $header"; }
done
check "generate with holes, fins, pinches, flips" "$petersen" generate "$work/mixed.obj" \
  --kind klein --holes 2 --fins 2 --pinches 1 --flip-faces 3 --seed 5
refuses "an unknown kind" "torus" "$petersen" generate "$work/x.off" --kind torus

# Files as they come. Dangling OBJ normal and texture coordinate indices: each attribute dropped
# for its faces with one warning, the faces paired; --strict refuses, naming the line.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1//1 2//1 3//1\nf 1/1 3/2 4/1\n' \
  >"$work/dangling.obj"
check "dangling OBJ indices" "$petersen" quad "$work/dangling.obj" "$work/dangling-q.obj"
[ "$(grep -c "warning: .*dangling.obj: dropped 1 faces' " "$work/out")" = 2 ] || {
  failed=$((failed + 1)); echo "FAILED: dangling warnings"; cat "$work/out"; }
grep -q "^pairs       1 " "$work/out" || { failed=$((failed + 1)); echo "FAILED: dangling pairs"; }
refuses "--strict on a dangling normal" "dangling.obj:6: face 1: normal index 1 out of range" \
  "$petersen" quad "$work/dangling.obj" "$work/x.obj" --strict
refuses "info --strict" "dangling.obj:6: face 1" "$petersen" info "$work/dangling.obj" --strict
# Every face twice: the summary names the duplicates and the flag; dropped, the result is the
# single copy's.
"$petersen" generate "$work/single.off" --kind plate >/dev/null
awk 'NR == 2 { split($0, n, " "); print n[1], 2 * n[2], 0; v = n[1]; f = n[2]; next }
     NR > 2 && NR <= 2 + v { print; next }
     NR > 2 + v { print; faces[++k] = $0 }
     NR == 1 { print }
     END { for (i = 1; i <= k; ++i) { split(faces[i], c, " "); print 3, c[4], c[3], c[2] } }' \
  "$work/single.off" >"$work/doubled.off"
check "doubled faces" "$petersen" quad "$work/doubled.off" "$work/doubled-q.off"
grep -q "^duplicates  .*--drop-duplicate-faces" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: duplicates not named"; cat "$work/out"; }
grep -q "^pairs       0 " "$work/out" || { failed=$((failed + 1)); echo "FAILED: doubled pairs"; }
check "single copy" "$petersen" quad "$work/single.off" "$work/single-q.off"
check "--drop-duplicate-faces" "$petersen" quad "$work/doubled.off" "$work/dropped-q.off" \
  --drop-duplicate-faces
cmp -s "$work/single-q.off" "$work/dropped-q.off" || {
  failed=$((failed + 1)); echo "FAILED: dropped copies pair otherwise"; }
check "info on doubled faces" "$petersen" info "$work/doubled.off"
grep -q "duplicate faces [1-9]" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: info names no duplicates"; }
# A tristrip PLY pairs as the same triangles written as faces.
printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 1 2 3 -1\n' \
  >"$work/strip.ply"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 1 3\n' >"$work/strip-faces.off"
check "tristrips" "$petersen" quad "$work/strip.ply" "$work/strip-q.off"
check "tristrips as faces" "$petersen" quad "$work/strip-faces.off" "$work/strip-faces-q.off"
cmp -s "$work/strip-q.off" "$work/strip-faces-q.off" || {
  failed=$((failed + 1)); echo "FAILED: tristrips pair otherwise"; }

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

# Messages that help: the values of a bad enum listed (names taken in any case), the closest flag
# or subcommand to a misspelt one, output folders checked before any work in every subcommand.
check "an enum value in capitals" "$petersen" quad "$example" "$work/x.obj" --algorithm PS \
  --objective Pairs --augment LOCAL
refuses "a bad algorithm lists the algorithms" "one of auto, sg, ps, ds, gw, frink, lrs" \
  "$petersen" quad "$example" "$work/x.obj" --algorithm blossom
# LEMON is the tests' and the bench's peer, not an algorithm of the tool.
refuses "quad lemon" "unknown value lemon: one of auto, sg, ps, ds, gw, frink, lrs" \
  "$petersen" quad "$example" "$work/x.obj" --algorithm lemon
refuses "match lemon" "unknown value lemon: one of auto, sg, ps, ds, gw, frink (lrs" \
  "$petersen" match "$work/g.txt" "$work/m.txt" --algorithm lemon
refuses "a bad objective lists the objectives" "unknown value best: one of quads, pairs, quality" \
  "$petersen" quad "$example" "$work/x.obj" --objective best
refuses "match lrs" "lrs works on meshes" "$petersen" match "$work/g.txt" "$work/m.txt" --algorithm lrs
refuses "a bad graph format" "one of dimacs, edges" \
  "$petersen" match "$work/g.txt" "$work/m.txt" --format graphml
refuses "a bad generator kind" "one of plate, trefoil, klein" \
  "$petersen" generate "$work/x.obj" --kind donut
refuses "a misspelt flag" "did you mean --all-quad" "$petersen" quad "$example" "$work/x.obj" --all-quads
refuses "a misspelt subcommand" "did you mean quad" "$petersen" qaud "$example" "$work/x.obj"
for command in "render $example" "generate" "match $work/g.txt" "quad $example"; do
  # shellcheck disable=SC2086 # the words of $command are separate arguments
  refuses "$command into no folder" "no such folder to write into: $work/nope" \
    "$petersen" $command "$work/nope/x.obj"
done
refuses "--memory-limit on an OFF" "out-of-core conversion reads a binary PLY" \
  "$petersen" quad "$example" "$work/x.ply" --memory-limit 1G
refuses "--memory-limit with a flag out of core cannot honour" "--strict: not taken by the out-of-core" \
  "$petersen" quad "$work/k-trefoil.ply" "$work/x.ply" --memory-limit 1G --objective quality --strict
refuses "a weight the objective does not read" "--triangle-cost: prices the triangles --objective quads leaves" \
  "$petersen" quad "$example" "$work/x.obj" --objective quality --triangle-cost 40
refuses "a triangle price with --all-quad" "--triangle-cost: with --all-quad every triangle left is split" \
  "$petersen" quad "$example" "$work/x.obj" --all-quad --triangle-cost 40
refuses "an edge-flow weight without --objective quads" "--flow-weight: weighs the edge flow" \
  "$petersen" quad "$example" "$work/x.obj" --objective pairs --flow-weight 1
refuses "--part-triangles alone" "give --memory-limit" \
  "$petersen" quad "$example" "$work/x.obj" --part-triangles 1000
# Every generator kind works with its defaults.
for kind in plate trefoil klein projective open-grid jittered-grid jittered-torus quad-dominant \
  quad-dominant-torus chamfered-cube; do
  check "generate --kind $kind by default" "$petersen" generate "$work/k-$kind.obj" --kind "$kind"
done
check "generate a trefoil PLY" "$petersen" generate "$work/k-trefoil.ply" --kind trefoil
refuses "--nx for a kind without a grid" "plate has no grid to size" \
  "$petersen" generate "$work/x.obj" --nx 5
refuses "a torus too thin" "jittered-torus needs --ny >= 3 and --nx >= 3 x --ny" \
  "$petersen" generate "$work/x.obj" --kind jittered-torus --nx 20 --ny 10
# A quad model converts back: the chamfered cube's 18 quads, its 8 corner triangles left.
check "quad a chamfered cube" "$petersen" quad "$work/k-chamfered-cube.obj" "$work/cq.obj"
"$petersen" info "$work/cq.obj" | grep -q "^faces by corners: 3: 8 4: 18$" || {
  failed=$((failed + 1)); echo "FAILED: the chamfered cube's faces"; "$petersen" info "$work/cq.obj"; }
# The summary reads as a success: no dangling colon, a written line for each file.
check "quad --render's written line" "$petersen" quad "$work/k-trefoil.obj" "$work/t.obj" \
  --render "$work/t.png"
grep -q "^written     $work/t.png$" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: no written line for --render"; cat "$work/out"; }
grep -q "^cut edges   0 of 6528$" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: cut edges line"; cat "$work/out"; }
check "lrs on a Klein bottle" "$petersen" quad "$work/k-klein.obj" "$work/kq.obj" --objective pairs --algorithm lrs
grep -q "^            lrs refused 1 closed component (paired by auto instead): not a closed surface: inconsistently oriented edge" "$work/out" || {
  failed=$((failed + 1)); echo "FAILED: the lrs refusal line"; cat "$work/out"; }

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
