#!/usr/bin/env bash
# A session matrix run in one process against the same study as a plan's units, both from an empty
# cache on one thread, in CPU time (user + sys, which other load on the machine barely changes):
#   one process: radarpr run CONFIG --cache-dir EMPTY --threads 1
#   units:       radarpr plan CONFIG --out P, then radarpr run-unit --threads 1 P ID for every
#                line of P/train.units, P/values.units and P/evaluate.units, then radarpr merge P
# Prints the CPU seconds of each (the units' per phase), the difference, how many codebooks each
# trained, and whether the merged results equal the single process's (diff -r without
# timing.json). Figures are not drawn (RADARPR_GNUPLOT=off): drawing them is the same work after
# `run` and after `merge`. docs/cluster.md quotes this script's output.
#
# Usage: benchmarks/cluster/units_vs_one_process.sh RADARPR_PROGRAM [CONFIG]
# CONFIG defaults to configs/synthetic/town_session_matrix.json (6 sessions, 30 pairs).
set -euo pipefail

radarpr="$(realpath "$1")"
config="$(realpath "${2:-$(dirname "$0")/../../configs/synthetic/town_session_matrix.json}")"
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (apt-get install time)"; exit 1; }
work="$(mktemp -d /tmp/radarpr_units_vs_one_process.XXXXXX)"
trap 'rm -rf "$work"' EXIT
export RADARPR_GNUPLOT=off

# Runs a command under /usr/bin/time, appending "user sys" to the file $1; its stderr (progress)
# is appended to $work/progress-<file name>.
timed() {
  local out="$1"
  shift
  /usr/bin/time -a -o "$out" -f '%U %S' "$@" > /dev/null 2>> "$work/progress-$(basename "$out")"
}
cpu() { awk '{ s += $1 + $2 } END { printf "%.1f", s }' "$1"; }
count() { awk 'END { print NR }' "$1"; }

timed "$work/one" "$radarpr" run "$config" --cache-dir "$work/one-cache" --threads 1 --out "$work/one-results"

plan="$work/plan"
timed "$work/plan-cpu" "$radarpr" plan "$config" --out "$plan"
for phase in train values evaluate; do
  : > "$work/$phase"
  while read -r unit; do
    timed "$work/$phase" "$radarpr" run-unit --threads 1 "$plan" "$unit"
  done < "$plan/$phase.units"
done
timed "$work/merge" "$radarpr" merge "$plan" --out "$work/merged" --threads 1

one="$(cpu "$work/one")"
units_total="$(cat "$work/plan-cpu" "$work/train" "$work/values" "$work/evaluate" "$work/merge" |
  awk '{ s += $1 + $2 } END { printf "%.1f", s }')"
echo "one process: $one s of CPU"
echo "units: $units_total s of CPU: plan $(cpu "$work/plan-cpu") s," \
  "$(count "$work/train") train units $(cpu "$work/train") s," \
  "$(count "$work/values") values units $(cpu "$work/values") s," \
  "$(count "$work/evaluate") evaluate units $(cpu "$work/evaluate") s, merge $(cpu "$work/merge") s"
awk -v a="$units_total" -v b="$one" 'BEGIN { printf "units - one process: %+.1f s (%+.1f%%)\n", a - b, 100 * (a - b) / b }'
echo "codebooks trained: one process $(grep -c 'training ' "$work/progress-one" || true)," \
  "units $(cat "$work"/progress-train "$work"/progress-values "$work"/progress-evaluate | grep -c 'training ' || true)"
if diff -r -x timing.json "$work/one-results" "$work/merged" > "$work/diff"; then
  echo "merged results: identical to the single process's (diff -r without timing.json)"
else
  echo "merged results DIFFER from the single process's:"
  head -20 "$work/diff"
  exit 1
fi
