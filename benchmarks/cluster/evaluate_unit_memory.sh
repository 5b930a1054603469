#!/usr/bin/env bash
# Peak memory of one evaluate unit of a plan whose descriptor values are large: two synthetic
# sessions of SCANS coarse scans (100 azimuths) and an Open-RadVLAD of 256 clusters x 512 bins
# (131,072 floats, 512 KiB per scan), so each session's values are SCANS x 512 KiB (768 MiB at
# the default 1,536 scans). Plans the pair, runs its train and values units, then runs the
# evaluate unit under /usr/bin/time -v on one thread and prints its peak resident memory and CPU
# time. docs/cluster.md quotes this script's output.
#
# Usage: benchmarks/cluster/evaluate_unit_memory.sh RADARPR_PROGRAM [SCANS] [WORK_DIR]
# WORK_DIR (default: a temporary folder, removed afterwards) holds the plan; it needs about
# 2 x SCANS x 512 KiB of disk.
set -euo pipefail

radarpr="$(realpath "$1")"
scans="${2:-1536}"
work="${3:-}"
if [ -z "$work" ]; then
  work="$(mktemp -d /tmp/radarpr_evaluate_memory.XXXXXX)"
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (apt-get install time)"; exit 1; }

session() {  # name, session number
  printf '{"name": "%s", "sequence": {"type": "synthetic", "world": "city", "seed": 7, "session": %s, "scans": %s, "azimuths": 100, "range_bins": 300, "range_resolution_m": 0.5}}' \
    "$1" "$2" "$scans"
}
cat > "$work/study.json" << JSON
{
  "experiment": "evaluate_unit_memory",
  "datasets": [{"kind": "session_matrix", "name": "pair",
                "sessions": [$(session first 0), $(session second 1)],
                "pairs": [{"query": "second", "database": "first"}]}],
  "descriptors": [{"name": "open_radvlad",
                   "params": {"clusters": 256, "bin_dim": 512, "max_iterations": 3,
                              "max_training_rows": 20000}}],
  "protocol": {"revisit_radius_m": 20, "recall_at_k": [1, 5]}
}
JSON

plan="$work/plan"
rm -rf "$plan"
"$radarpr" plan "$work/study.json" --out "$plan" > /dev/null
for phase in train values; do
  while read -r unit; do
    "$radarpr" run-unit --threads 1 "$plan" "$unit" > /dev/null 2>&1
  done < "$plan/$phase.units"
done
unit="$(head -1 "$plan/evaluate.units")"
values_bytes="$(du -cb "$plan"/cache/descriptors/open_radvlad/*.bin | tail -1 | cut -f1)"
/usr/bin/time -v -o "$work/time.txt" "$radarpr" run-unit --threads 1 "$plan" "$unit" > /dev/null 2>&1
peak_kib="$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")"
user="$(sed -n 's/.*User time (seconds): //p' "$work/time.txt")"
system="$(sed -n 's/.*System time (seconds): //p' "$work/time.txt")"
echo "evaluate unit $unit: $scans + $scans scans of 512 KiB values" \
  "($((values_bytes / 1048576)) MiB of values files in the plan)"
echo "peak resident memory: $((peak_kib / 1024)) MiB; CPU: user $user s + system $system s"
