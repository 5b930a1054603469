#!/usr/bin/env bash
# The CPU rates behind docs/cluster.md's cost of a 30-session Oxford study, each as CPU time
# (user + sys) on one thread from an empty cache:
# 1. per Oxford scan (400 x 3768, the real sample of the shared data folder): PNG decode,
#    Open-RadVLAD's spectra, ReFeree and Open-RadVLAD extraction, from
#    `radarpr bench --threads 1` (its extraction table is in ms of CPU);
# 2. one Lloyd iteration of Open-RadVLAD's k-means (64 clusters, 240,000 azimuth rows of 512
#    floats: 600 scans of 400 azimuths): two train units of one synthetic session that differ
#    only in max_iterations (2 and 6), the scans already rendered: (6-iteration unit - 2-iteration
#    unit) / 4;
# 3. per query-database pair of the exhaustive search of 32,768-float values: an evaluate unit of
#    two synthetic sessions of PAIR_SCANS coarse scans with the default Open-RadVLAD (64 x 512),
#    its CPU over PAIR_SCANS^2; and the CPU of the same pair's ReFeree evaluate unit (KD-tree).
#
# Usage: benchmarks/cluster/cost_rates.sh RADARPR_PROGRAM [PAIR_SCANS]   (default 2048)
set -euo pipefail

radarpr="$(realpath "$1")"
pair_scans="${2:-2048}"
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (apt-get install time)"; exit 1; }
work="$(mktemp -d /tmp/radarpr_cost_rates.XXXXXX)"
trap 'rm -rf "$work"' EXIT

cpu_of() {  # command...: prints its user + sys seconds
  /usr/bin/time -o "$work/time" -f '%U %S' "$@" > /dev/null 2>&1
  awk '{ printf "%.2f", $1 + $2 }' "$work/time"
}

echo "== 1. per Oxford scan, one thread (radarpr bench, ms of CPU, medians of 3)"
"$radarpr" bench --threads 1 --repetitions 3 --out "$work/bench" \
  --filter '^(png_decode/|(extract|stage)/(referee|open_radvlad)/)400x3768' > /dev/null 2>&1
grep -E '^\| (Descriptor|referee|open_radvlad) \|' "$work/bench/bench.md" | grep -E 'Descriptor|400x3768'

echo "== 2. k-means: one Lloyd iteration, 240,000 rows x 512 floats, 64 clusters"
radvlad() {  # max_iterations
  printf '{"name": "open_radvlad", "params": {"max_iterations": %s}}' "$1"
}
cat > "$work/kmeans.json" << JSON
{"experiment": "cost_rates_kmeans",
 "datasets": [{"kind": "session_matrix", "name": "m", "pairs": [{"query": "b", "database": "a"}],
   "sessions": [{"name": "a", "sequence": {"type": "synthetic", "world": "city", "seed": 7, "session": 0, "scans": 600}},
                {"name": "b", "sequence": {"type": "synthetic", "world": "city", "seed": 7, "session": 1, "scans": 2}}]}],
 "descriptors": [$(radvlad 2), $(radvlad 6)],
 "protocol": {"revisit_radius_m": 20}}
JSON
"$radarpr" plan "$work/kmeans.json" --out "$work/kmeans" > /dev/null
mapfile -t train < "$work/kmeans/train.units"
"$radarpr" run-unit --threads 1 --quiet "$work/kmeans" "${train[0]}" > /dev/null  # renders the scans
rm -f "$work/kmeans/units/${train[0]}".*
two="$(cpu_of "$radarpr" run-unit --threads 1 --quiet "$work/kmeans" "${train[0]}")"
six="$(cpu_of "$radarpr" run-unit --threads 1 --quiet "$work/kmeans" "${train[1]}")"
awk -v a="$two" -v b="$six" 'BEGIN { printf "train unit, 2 iterations: %.2f s; 6 iterations: %.2f s; per iteration: %.3f s\n", a, b, (b - a) / 4 }'

echo "== 3. evaluate units: two sessions of $pair_scans coarse scans"
coarse() {  # name, session
  printf '{"name": "%s", "sequence": {"type": "synthetic", "world": "city", "seed": 7, "session": %s, "scans": %s, "azimuths": 100, "range_bins": 300, "range_resolution_m": 0.5}}' \
    "$1" "$2" "$pair_scans"
}
cat > "$work/pair.json" << JSON
{"experiment": "cost_rates_pair",
 "datasets": [{"kind": "session_matrix", "name": "m", "pairs": [{"query": "b", "database": "a"}],
               "sessions": [$(coarse a 0), $(coarse b 1)]}],
 "descriptors": ["referee", {"name": "open_radvlad", "params": {"max_iterations": 3, "max_training_rows": 20000}}],
 "protocol": {"revisit_radius_m": 20, "recall_at_k": [1, 5, 10]}}
JSON
"$radarpr" plan "$work/pair.json" --out "$work/pair" > /dev/null
for phase in train values; do
  while read -r unit; do
    "$radarpr" run-unit --threads 1 --quiet "$work/pair" "$unit" > /dev/null
  done < "$work/pair/$phase.units"
done
while read -r unit; do
  seconds="$(cpu_of "$radarpr" run-unit --threads 1 --quiet "$work/pair" "$unit")"
  awk -v s="$seconds" -v n="$pair_scans" -v u="$unit" 'BEGIN { printf "%s: %.2f s, %.3f us per query-database pair\n", u, s, 1e6 * s / (n * n) }'
done < "$work/pair/evaluate.units"
