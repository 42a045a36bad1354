#!/usr/bin/env bash
# bench/scale_out_of_core.sh [TRIANGLES...]: the out-of-core conversion at scale. For each size
# (default 1e8 3e8 1e9): a closed streamed plate written by `petersen generate`, then
# `petersen quad` in memory where the mesh fits (3·10^8 and below on a 24 GiB machine) and out of
# core with --memory-limit (MEMORY_LIMIT, default 3G below 10^9 and 10G at 10^9), each under
# /usr/bin/time -v. Prints one row per run: wall time, user and system CPU, peak RSS, the bytes on
# disk (input, output, the temporary pairing) and the pairing's figures from --stats-json. The big
# files go to WORK (default /tmp/petersen-scale) and are deleted after each size; keep WORK out
# of the repository. PARTS_SWEEP=1 also runs 10^8 with 2 to 32 parts (--part-triangles), for
# how the repair's cost grows with the number of parts. OBJECTIVES (default pairs) names the
# objectives run, each in memory and out of core: "quads quality" measures the cost objectives,
# whose rows add the out-of-core total's gap to the in-memory certified optimum. KIND=open-grid
# makes an open grid with holes (one per 5,000 triangles) instead of the closed plate. FLAGS are
# given to both runs: FLAGS="--all-quad --max-corner-deviation 30" adds a row with the midpoints
# and centres out of core against the in-memory certified minimum.
# Expects a Release build: scripts/build build/release (or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."
petersen=${PETERSEN:-build/tools/petersen}
work=${WORK:-/tmp/petersen-scale}
mkdir -p "$work"
[ $# -eq 0 ] && set -- 100000000 300000000 1000000000

measure() {  # label, then the command
  local label=$1
  shift
  /usr/bin/time -v "$@" >"$work/run.out" 2>"$work/run.time"
  local wall user sys rss
  wall=$(grep 'Elapsed (wall clock)' "$work/run.time" | awk '{print $NF}')
  user=$(grep 'User time' "$work/run.time" | awk '{print $NF}')
  sys=$(grep 'System time' "$work/run.time" | awk '{print $NF}')
  rss=$(grep 'Maximum resident' "$work/run.time" | awk '{printf "%.2f", $NF / 1048576}')
  local stats=""
  [ -f "$work/stats.json" ] && stats=$(tr -d '\n' <"$work/stats.json") &&
    mv "$work/stats.json" "$work/last.json"
  echo "| $label | $wall | $user | $sys | $rss GiB | $stats |"
}

echo "| run | wall | user s | sys s | peak RSS | stats |"
echo "|---|---:|---:|---:|---:|---|"
# A value of the last --stats-json, or nothing.
value() { sed -n "s/.*\"$1\": \([-0-9.e+]*\).*/\1/p" "$work/last.json"; }

for n in "$@"; do
  in="$work/${KIND:-plate}-$n.ply"
  if [ "${KIND:-plate}" = open-grid ]; then
    ny=$(awk -v n="$n" 'BEGIN { printf "%d", sqrt(n / 2.5) }')
    "$petersen" generate --kind open-grid --nx $((ny * 5 / 4)) --ny "$ny" --holes $((n / 5000)) \
      "$in" >/dev/null
  else
    "$petersen" generate --kind streamed-plate --triangles "$n" "$in" >/dev/null
  fi
  in_bytes=$(stat -c %s "$in")
  limit=${MEMORY_LIMIT:-$([ "$n" -ge 1000000000 ] && echo 10G || echo 3G)}
  available_kib=$(awk '/MemAvailable/ {print $2}' /proc/meminfo)
  for objective in ${OBJECTIVES:-pairs}; do
    optimum="" midpoints=""
    if [ $((n * 60 / 1024)) -lt "$available_kib" ]; then
      measure "$n $objective in memory" "$petersen" quad "$in" "$work/mem.ply" \
        --objective "$objective" --stats-json "$work/stats.json" ${FLAGS:-}
      optimum=$(value objective_total)
      midpoints=$(value split_edges) centres=$(value centre_vertices)
      rm -f "$work/mem.ply"
    fi
    measure "$n $objective out of core, $limit" "$petersen" quad "$in" "$work/out.ply" \
      --memory-limit "$limit" --objective "$objective" --stats-json "$work/stats.json" ${FLAGS:-}
    if [ -n "${midpoints:-}" ]; then
      awk -v m="$midpoints" -v c="$centres" -v om="$(value split_edges)" \
        -v oc="$(value centre_vertices)" 'BEGIN {
        printf "|   all-quad midpoints: in memory %d (the certified minimum), out of core %d (%+.3f%%);", m, om, m > 0 ? 100 * (om - m) / m : 0
        printf " centres %d / %d | | | | | |\n", c, oc }'
    fi
    if [ -n "$optimum" ] && [ "$objective" != pairs ] && [[ "${FLAGS:-}" != *--all-quad* ]]; then
      awk -v o="$optimum" -v t="$(value objective_total)" -v l="$(value lower_bound)" 'BEGIN {
        printf "|   in-memory optimum %.3f; out of core %.3f (%+.4f%%)", o, t, 100 * (t - o) / o
        if (l != "") printf ", lower bound %.3f (%+.4f%%)", l, 100 * (l - o) / o
        print " | | | | | |" }'
    fi
  done
  echo "|   bytes on disk: input $in_bytes, output $(stat -c %s "$work/out.ply"), pairing $((n * 4)) | | | | | |"
  # The independent check of the output against the input, where both fit in memory (about 160
  # bytes a triangle): CHECK, default the tests' petersen_check_quads beside the tool's build.
  if [ $((n * 160 / 1024)) -lt "$available_kib" ]; then
    "${CHECK:-$(dirname "$petersen")/../tests/partition/petersen_check_quads}" "$in" "$work/out.ply"
  fi
  rm -f "$work/out.ply"
  if [ "${PARTS_SWEEP:-0}" = 1 ] && [ "$n" -le 100000000 ]; then
    for parts in 2 4 8 16 32; do
      measure "$n in $parts parts" "$petersen" quad "$in" "$work/out.ply" --memory-limit 64G \
        --objective pairs \
        --part-triangles $(((n + parts - 1) / parts)) --stats-json "$work/stats.json"
      rm -f "$work/out.ply"
    done
  fi
  rm -f "$in"
done
