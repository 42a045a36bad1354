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
  for key in algorithm triangles genus load_seconds dual_seconds initial_seconds \
    initial_paired_percent unpaired_after_initial augment_seconds matching_seconds total_seconds; do
    grep -q "\"$key\":" "$work/$algorithm.json" || {
      failed=$((failed + 1)); echo "FAILED: $algorithm stats lack $key"; }
  done
  # The quads it wrote read back as a mesh of quads: 'info' refuses them as non-triangles.
  refuses "written quads are quads ($algorithm)" "has 4 corners" \
    "$petersen" info "$work/q-$algorithm.obj"
done
for format in off ply; do
  check "quad to .$format" "$petersen" quad "$example" "$work/q.$format"
done

printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$work/open.off"
refuses "an open mesh" "open.off.*boundary edge" "$petersen" quad "$work/open.off" "$work/x.obj"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >"$work/range.off"
refuses "an index out of range" "range.off" "$petersen" quad "$work/range.off" "$work/x.obj"
refuses "a missing file" "missing.obj" "$petersen" info "$work/missing.obj"
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

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
