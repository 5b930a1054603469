#!/usr/bin/env bash
# A study on a real Slurm: starts a single-node Slurm on this machine (munged, slurmctld, slurmd
# from Debian's packages, a minimal slurm.conf on localhost, every file in a temporary folder),
# plans a small synthetic session matrix (4 sessions, 12 ordered pairs, 3 descriptors including
# open_radvlad) with `radarpr plan --slurm`, submits it with its submit.sh, kills one unit's task
# while it runs, resubmits only that array index (and the phases after it), merges, and checks
# the merged results against `radarpr run` in one process byte for byte.
#
# Usage: slurm_study_test.sh RADARPR_PROGRAM
# Exit 0: passed; 1: failed; 77: skipped, with the reason on stdout (not root, a package
# missing, or Slurm did not start). Stops the daemons it started, by their PIDs, on every exit.
set -euo pipefail

radarpr="$(realpath "$1")"
skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "FAILED: $*"; exit 1; }

[ "$(id -u)" = 0 ] || skip "starting slurmctld and slurmd needs root (.ci/run runs this as root)"
for program in munged slurmctld slurmd sbatch squeue scancel sinfo; do
  command -v "$program" > /dev/null ||
    skip "$program is not installed (apt-get install munge slurmctld slurmd slurm-client)"
done

work="$(mktemp -d /tmp/radarpr_slurm_test.XXXXXX)"
chmod 755 "$work"
pids=()
stop_daemons() {
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2> /dev/null || true
  done
  rm -rf "$work"
}
trap stop_daemons EXIT

# munge: its own key, socket and files.
mkdir -p "$work/munge"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --foreground --key-file="$work/munge/munge.key" \
  --socket="$work/munge/munge.socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" \
  > "$work/munge/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$work/munge/munge.socket" ] && break; sleep 0.1; done
[ -S "$work/munge/munge.socket" ] || skip "munged did not start: $(tail -3 "$work/munge/munged.log" 2> /dev/null)"

host="$(hostname -s)"
cpus="$(nproc)"
mkdir -p "$work/state" "$work/spool"
export SLURM_CONF="$work/slurm.conf"
cat > "$SLURM_CONF" << CONF
ClusterName=radarpr-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" > "$work/slurmd.out" 2>&1 &
pids+=($!)
up=
for _ in $(seq 100); do
  state="$(sinfo -h -o %T 2> /dev/null | head -1 || true)"
  case "$state" in idle*|mixed*|allocated*) up=1; break ;; esac
  sleep 0.3
done
[ -n "$up" ] || skip "Slurm did not start (node state '${state:-none}'): $(tail -3 "$work/slurmctld.log" "$work/slurmd.log" 2> /dev/null | tr '\n' ' ')"
echo "slurm: node $host up with $cpus CPUs"

# The study: 4 sessions of one synthetic town (weather, traffic, parked cars), all 12
# ordered pairs, referee, referee_r and a small open_radvlad (trained once per database session).
mkdir -p "$work/study"
sequence() {  # session, then extra keys
  printf '{"type": "synthetic", "seed": 11, "session": %s, "scans": 60, "azimuths": 120, "range_bins": 210, "range_resolution_m": 0.476, "route_blocks_x": 1, "speed_mps": 30%s}' "$1" "$2"
}
cat > "$work/study/study.json" << JSON
{
  "experiment": "slurm_study",
  "datasets": [{"kind": "session_matrix", "name": "town", "sessions": [
    {"name": "clear", "sequence": $(sequence 0 "")},
    {"name": "rain", "sequence": $(sequence 1 ', "weather": "rain"')},
    {"name": "busy", "sequence": $(sequence 2 ', "traffic": 0.9')},
    {"name": "parked", "sequence": $(sequence 3 ', "parked_car_churn": 0.8')}]}],
  "descriptors": ["referee", "referee_r",
    {"name": "open_radvlad", "params": {"min_bin": 10, "bin_dim": 32, "clusters": 16, "max_iterations": 20}}],
  "protocol": {"revisit_radius_m": 10, "recall_at_k": [1, 3]}
}
JSON
chmod -R a+rX "$work"

"$radarpr" run "$work/study/study.json" --out "$work/single" --cache-dir "$work/single_cache" --quiet \
  > "$work/single.log" 2>&1 || fail "radarpr run failed: $(tail -5 "$work/single.log")"
"$radarpr" plan "$work/study/study.json" --out "$work/plan" --slurm --cpus-per-task 1 \
  > "$work/plan.log" 2>&1 || fail "radarpr plan failed: $(tail -5 "$work/plan.log")"
grep -v '^warning: ' "$work/plan.log"

compare() {  # the merged results against the single process, byte for byte (timing.json holds run times)
  diff -r -x timing.json -x summary.json -x summary.csv -x metrics.json -x figures -x index.html \
    "$work/single" "$work/plan/results" > "$work/diff.txt" ||
    fail "merged results differ from radarpr run: $(head -20 "$work/diff.txt")"
  for file in summary.md town/pairs.csv town/aggregate.csv town.rain.clear/referee/matches.csv; do
    cmp -s "$work/single/$file" "$work/plan/results/$file" || fail "$file differs"
  done
}

wait_jobs() {  # until none of the given jobs is queued or running
  for _ in $(seq 1200); do
    [ -z "$(squeue -h -j "$(IFS=,; echo "$*")" -o %i 2> /dev/null)" ] && return 0
    sleep 0.5
  done
  fail "jobs $* did not finish within 10 minutes: $(squeue)"
}

# Round 1: the whole plan through submit.sh (train, values, evaluate, then merge).
submitted="$(sh "$work/plan/slurm/submit.sh")"
echo "$submitted"
jobs=($(echo "$submitted" | sed -n 's/^[a-z]*: job \([0-9]*\).*/\1/p'))
[ "${#jobs[@]}" = 4 ] || fail "submit.sh did not print four job ids: $submitted"
wait_jobs "${jobs[@]}"
"$radarpr" status "$work/plan" > "$work/status.txt" ||
  fail "units not done: $(cat "$work/status.txt"; tail -5 "$work"/plan/logs/*.log)"
[ -s "$work/plan/results/summary.md" ] ||
  fail "the merge job wrote no results: $(tail -20 "$work"/plan/logs/merge-*.log)"
compare
echo "round 1: merged results identical to radarpr run"

# Round 2: one unit's outputs removed, its task killed while it runs, only that index resubmitted.
# The victim is a unit of the train phase: an open_radvlad codebook.
victim="$(grep -n '^train\.town\.busy\.' "$work/plan/train.units" | head -1)"
index=$(( ${victim%%:*} - 1 ))
victim_id="${victim#*:}"
stamp="$work/plan/units/$victim_id.done.json"
cd "$work/plan/slurm"
# Killed as soon as it runs. On an idle machine the codebook can take well under a second, so a
# kill may come after the unit finished (its stamp is then back): the unit's outputs are removed
# again and the kill retried, up to five times.
killed_mid_way=
for attempt in 1 2 3 4 5; do
  for entry in $(grep -o '"\(cache\|units\)/[^"]*"' "$stamp" | tr -d '"'); do rm -f "$work/plan/$entry"; done
  rm -rf "$stamp" "$work/plan/results"
  doomed="$(sbatch --parsable --array="$index" train.sbatch)"
  killed=
  for _ in $(seq 6000); do
    if [ "$(squeue -h -j "$doomed" -o %T 2> /dev/null)" = RUNNING ]; then
      scancel --signal=KILL "$doomed" && killed=1
      break
    fi
    sleep 0.01
  done
  [ -n "$killed" ] || fail "task $doomed ($victim_id) was never seen running"
  wait_jobs "$doomed"
  if [ ! -e "$stamp" ]; then killed_mid_way=1; break; fi
  echo "attempt $attempt: $victim_id finished before the kill; again"
done
[ -n "$killed_mid_way" ] || fail "$victim_id finished before every one of five kills"
if "$radarpr" status "$work/plan" > "$work/status.txt"; then fail "status says done after a kill"; fi
grep -Eq "^(missing|failed) $victim_id" "$work/status.txt" ||
  fail "status does not list $victim_id: $(cat "$work/status.txt")"
[ "$(grep -Ec '^(missing|failed) ' "$work/status.txt")" = 1 ] ||
  fail "more than the killed unit is not done: $(cat "$work/status.txt")"
echo "round 2: killed $victim_id (task $doomed) mid-way; status: $(grep '^train:' "$work/status.txt")"
again="$(sbatch --parsable --array="$index" train.sbatch)"
merge_again="$(sbatch --parsable --dependency=afterok:"$again" merge.sbatch)"
wait_jobs "$again" "$merge_again"
"$radarpr" status "$work/plan" > "$work/status.txt" ||
  fail "units not done after the resubmission: $(cat "$work/status.txt")"
[ -s "$work/plan/results/summary.md" ] ||
  fail "the merge job wrote no results: $(tail -20 "$work"/plan/logs/merge-*.log)"
compare
echo "PASSED: 12 pairs x 3 descriptors on Slurm; one task killed mid-way and its index resubmitted; merged results identical to radarpr run both times"
