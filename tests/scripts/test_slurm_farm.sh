#!/usr/bin/env bash
# A render farm on this machine (issue 21): single-node Slurm (Debian's slurm-wlm and munge) on
# 127.0.0.1 from a generated slurm.conf in a temporary folder, stopped at the end whatever
# happens. scripts/slurm/submit.sh sends a simulated smoke scene (8 frames) as a simulation job
# and a 3-task render array; every frame must be the bytes of the one-process live render, and the
# merged manifest that render's manifest. Then a task is killed mid-chunk (after its first frame)
# and the scene resubmitted: the tasks resume (the finished frames kept), and the set is the same.
# Exit 77 (ctest: skipped) with one line saying why when Slurm cannot start here.
# Usage: tests/scripts/test_slurm_farm.sh EIKON_BINARY SCRATCH_DIR
set -euo pipefail
EIKON=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SCRATCH=$2
repo=$(cd "$(dirname "$0")/../.." && pwd)
skip() { echo "slurm farm test skipped: $*"; exit 77; }
fail() { echo "slurm farm test FAILED: $*"; exit 1; }

[ "$(id -u)" = 0 ] || skip "slurmd runs jobs as their users and needs root here"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol scancel; do
    command -v "$tool" >/dev/null || skip "$tool not found (scripts/install-deps.sh installs slurm-wlm and munge)"
done

rm -rf "$SCRATCH"
mkdir -p "$SCRATCH"/{state,spool,log,run}
T=$(cd "$SCRATCH" && pwd)
export SLURM_CONF=$T/slurm.conf
cleanup() {
    scontrol shutdown >/dev/null 2>&1 || true
    for pid in "$T"/run/*.pid; do
        [ -f "$pid" ] && kill "$(cat "$pid")" 2>/dev/null || true
    done
    sleep 1
    for pid in "$T"/run/*.pid; do
        [ -f "$pid" ] && kill -9 "$(cat "$pid")" 2>/dev/null || true
    done
}
trap cleanup EXIT

# Munge with a key of its own, on a socket of its own.
head -c 1024 /dev/urandom >"$T/munge.key"
chmod 600 "$T/munge.key"
munged --force --socket="$T/run/munge.sock" --key-file="$T/munge.key" \
    --log-file="$T/log/munged.log" --pid-file="$T/run/munged.pid" \
    --seed-file="$T/run/munged.seed" || skip "munged did not start: $(tail -n 1 "$T/log/munged.log" 2>/dev/null)"

port=$((20000 + $$ % 20000))
cat >"$SLURM_CONF" <<CONF
ClusterName=eikonfarmtest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$T/run/munge.sock
CredType=cred/munge
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/run/slurmctld.pid
SlurmdPidFile=$T/run/slurmd.pid
SlurmctldLogFile=$T/log/slurmctld.log
SlurmdLogFile=$T/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=3600
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MailProg=/bin/true
PlugStackConfig=/dev/null
NodeName=eikon1 NodeAddr=127.0.0.1 NodeHostname=localhost CPUs=$(nproc) State=UNKNOWN
PartitionName=eikon Nodes=eikon1 Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$SLURM_CONF" || skip "slurmctld did not start: $(tail -n 1 "$T/log/slurmctld.log" 2>/dev/null)"
slurmd -f "$SLURM_CONF" -N eikon1 || skip "slurmd did not start: $(tail -n 1 "$T/log/slurmd.log" 2>/dev/null)"
for _ in $(seq 60); do
    sinfo -h -o %t 2>/dev/null | grep -q idle && break
    sleep 0.5
done
sinfo -h -o %t 2>/dev/null | grep -q idle ||
    skip "the node did not come up: $(tail -n 1 "$T/log/slurmd.log" 2>/dev/null)"
echo "slurm up: slurmctld on 127.0.0.1:$port, node eikon1 with $(nproc) CPUs"

# The scene (tests/scripts/farm_smoke.json): live smoke, 8 frames; 640² so that a frame takes long
# enough to be killed inside.
mkdir -p "$T/scene"
cp "$repo/tests/scripts/farm_smoke.json" "$T/scene/farm.json"

t0=$(date +%s.%N)
"$EIKON" render "$T/scene/farm.json" --backend cpu --quiet -o "$T/local/" \
    --manifest "$T/local/manifest.tsv"
t1=$(date +%s.%N)
echo "one process (live): $(awk "BEGIN {printf \"%.1f\", $t1 - $t0}") s for 8 frames"

wait_for_jobs() {  # until the queue is empty (or only jobs that can never run are left)
    for _ in $(seq 600); do
        local left
        left=$(squeue -h -o "%i %r" 2>/dev/null || true)
        [ -z "$left" ] && return 0
        if grep -q DependencyNeverSatisfied <<< "$left"; then
            echo "$left" | awk '/DependencyNeverSatisfied/ {print $1}' | xargs -r scancel
        fi
        sleep 0.2
    done
    fail "jobs still queued after 120 s: $(squeue -h)"
}

submit() {  # OUT
    OUT=$1 EIKON="$EIKON" EIKON_RENDER_ARGS="--backend cpu" \
        bash "$repo/scripts/slurm/submit.sh" "$T/scene/farm.json" 1-8 3
}

check_same_as_local() {  # OUT
    local n=0
    for f in "$T"/local/smoke_*.png; do
        cmp -s "$f" "$1/$(basename "$f")" || fail "$1/$(basename "$f") differs from the one-process render"
        n=$((n + 1))
    done
    [ "$n" = 8 ] || fail "the local render wrote $n frames, not 8"
    [ "$(ls "$1"/smoke_*.png | wc -l)" = 8 ] || fail "$1 holds $(ls "$1"/smoke_*.png | wc -l) frames, not 8"
    cmp -s "$T/local/manifest.tsv" "$1/manifest.tsv" ||
        fail "$1/manifest.tsv differs from the local manifest: $(diff "$T/local/manifest.tsv" "$1/manifest.tsv" | head -n 3)"
}

# What a task costs before it renders anything (figures for BENCHMARKS.md, not checked): a 3-task
# array of `true`, and of eikon tasks whose chunks are empty (start, scene read, exit).
for what in true empty; do
    cmd="true"
    [ "$what" = empty ] &&
        cmd="'$EIKON' render '$T/scene/farm.json' --frames 1-2 --chunk \$((SLURM_ARRAY_TASK_ID + 1))/6 -o '$T/empty/' --backend cpu"
    t0=$(date +%s.%N)
    sbatch --parsable --array 0-2 --output /dev/null --wrap "$cmd" >/dev/null
    wait_for_jobs
    t1=$(date +%s.%N)
    echo "slurm: a 3-task array of $what tasks, submission to done: $(awk "BEGIN {printf \"%.2f\", $t1 - $t0}") s"
done

# 1. Simulate, render in 3 chunks, merge.
t0=$(date +%s.%N)
submit "$T/farm" | tee "$T/submit.txt"
wait_for_jobs
t1=$(date +%s.%N)
check_same_as_local "$T/farm"
echo "farm: 8 frames in 3 tasks equal the one-process render; $(awk "BEGIN {printf \"%.1f\", $t1 - $t0}") s from submission"

# 2. Kill chunk 2 (array task 1) after its first frame, then resubmit: the same set.
rm -rf "$T/scene/cache"
submit "$T/killed" >"$T/submit_killed.txt"
array=$(awk '/^render: job array/ {print $4}' "$T/submit_killed.txt")
log="$T/killed/logs/render_${array}_1.txt"
for _ in $(seq 1200); do
    grep -q "^wrote " "$log" 2>/dev/null && break
    sleep 0.05
done
grep -q "^wrote " "$log" || fail "array task 1 never wrote a frame: $(tail -n 2 "$log" 2>/dev/null)"
scancel --signal=KILL --full "${array}_1"
wait_for_jobs
written=$(grep -c "^wrote " "$log" || true)
[ "$written" -lt 3 ] || fail "the kill came after task 1 had written its 3 frames: nothing to resume"
[ ! -f "$T/killed/manifest.tsv" ] || fail "the manifest was merged although a task was killed"
echo "killed array task 1 after $written of its 3 frames"
submit "$T/killed" >"$T/submit_resumed.txt"
wait_for_jobs
array=$(awk '/^render: job array/ {print $4}' "$T/submit_resumed.txt")
kept=$(grep -c "kept frame" "$T/killed/logs/render_${array}_1.txt" || true)
[ "$kept" = "$written" ] || fail "the resumed task 1 kept $kept frames, not the $written written"
check_same_as_local "$T/killed"
echo "resubmitted: task 1 kept its $kept finished frames and rendered the rest; the set equals the one-process render"
echo "slurm farm test passed"
