#!/usr/bin/env bash
# Packs a radarpr results folder into one input of the results fuzz target (results_fuzz.cpp):
# summary.json first, then every CSV the reader opens, each after a "==> relative/path" line.
# Usage: tests/fuzz/pack_results_folder.sh RESULTS_FOLDER > packed
set -euo pipefail
cd "$1"
cat summary.json
find . \( -name trajectory.csv -o -name matches.csv -o -name curve.csv -o -name matching_graph.csv \) | LC_ALL=C sort | while read -r file; do
  printf '\n==> %s\n' "${file#./}"
  cat "$file"
done
