#!/usr/bin/env bash
# docs/autograders/slurm/grade_class.sh run for real, on a Slurm of one node that this test starts
# on 127.0.0.1 (Debian's slurmctld, slurmd and munge): six submissions graded by three array
# tasks, then merged. The merged table, CSV, Gradescope files and JUnit XML must be byte for byte
# what one `impulse grade` of the folder writes, and each task must have graded its own two.
# Skipped (exit 77, the reason on the last line) where the daemons cannot run: not root, not
# installed, no munge key, or a daemon that does not come up.
# Usage: slurm_test.sh IMPULSE WORK_DIR      (from the repository's root, as CTest runs it)
set -uo pipefail
impulse=$(realpath "$1") work=$(realpath -m "$2")
skip() { echo "slurm_test: skipped: $*"; exit 77; }
fail() { echo "slurm_test: FAILED: $*"; for log in "$work"/*.log "$work"/out/logs/*; do [ -f "$log" ] && { echo "== $log"; tail -15 "$log"; }; done; exit 1; }

[ "$(id -u)" = 0 ] || skip "slurmd runs as root, and this is uid $(id -u) (CI runs as root)"
for program in slurmctld slurmd sbatch sinfo munged munge unmunge; do
  command -v "$program" > /dev/null || skip "$program is not installed (Debian's slurmctld, slurmd, slurm-client and munge: scripts/setup.sh)"
done
[ -r /etc/munge/munge.key ] || skip "munge has no key (/etc/munge/munge.key)"
rm -rf "$work" && mkdir -p "$work/state" "$work/spool" "$work/class"

started=()  # what this test started, ended at exit
munged_pid=
cleanup() {
  for pid in "${started[@]}"; do kill "$pid" 2> /dev/null; done
  for pid in "${started[@]}"; do wait "$pid" 2> /dev/null; done
  [ -n "$munged_pid" ] && kill "$munged_pid" 2> /dev/null
}
trap cleanup EXIT

if ! munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  install -d -o munge -g munge -m 0755 /run/munge && install -d -o munge -g munge -m 0700 /var/lib/munge /var/log/munge
  runuser -u munge -- munged > "$work/munged.log" 2>&1 || skip "munged does not start: $(tail -1 "$work/munged.log")"
  munged_pid=$(cat /run/munge/munged.pid 2> /dev/null)
  munge -n | unmunge > /dev/null 2>&1 || skip "munged started but does not answer"
fi

port=$((17000 + $$ % 1000 * 2))
export SLURM_CONF=$work/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=impulse-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 & started+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 & started+=($!)
for _ in $(seq 60); do
  [ "$(sinfo -h -n localhost -o %t 2> /dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo -h -n localhost -o %t 2> /dev/null)" = idle ] ||
  skip "the node did not come up within 30 s ($(tail -1 "$work/slurmctld.log" 2> /dev/null); $(tail -1 "$work/slurmd.log" 2> /dev/null))"

# Six submissions: the corrected listing twice, the printed one twice, one that does not compile,
# one that reads /etc/passwd.
for name in alice bob; do cp assets/workshop/listing1_corrected.cpp "$work/class/$name.cpp"; done
for name in carol dave; do cp assets/workshop/listing1.cpp "$work/class/$name.cpp"; done
cp assets/workshop/listing1_printed.cpp "$work/class/erin.cpp"
{ cat tests/response/hostile/run/read_file.cpp; echo 'static void AddCollisionImpulse(RigidBody&, RigidBody&, const Vector3&, const Vector3&, float) { Hostile(); }'; } > "$work/class/frank.cpp"

export IMPULSE_RESPONSE_CACHE=$work/cache
status=0
IMPULSE=$impulse CPUS_PER_TASK=1 WAIT=1 timeout 300 docs/autograders/slurm/grade_class.sh "$work/class" "$work/out" 3 || status=$?
[ "$status" = 2 ] || fail "the merge ended with exit code $status, not 2 (some students fail)"
for task in 1 2 3; do
  log=$work/out/logs/shard-$task.out
  # Each task's two: graded, or kept from a submission of the same text graded before (alice's is bob's).
  graded=$(grep -c '^\[[12]/[12]\] ' "$log" || true)
  kept=$(sed -n 's/^\([0-9]*\) unchanged since they were graded.*/\1/p' "$log")
  [ $((graded + ${kept:-0})) = 2 ] || fail "task $task did not grade two submissions: $(cat "$log")"
done

# What one run writes, from the same cache: the merge must have written exactly that.
mkdir -p "$work/one"
"$impulse" grade "$work/class" --jobs 2 --csv "$work/one/grades.csv" --gradescope "$work/one/gradescope" --junit "$work/one/grades.xml" \
  > "$work/one/grades.txt" 2> /dev/null
for output in grades.txt grades.csv grades.xml; do
  cmp "$work/one/$output" "$work/out/$output" || fail "the merged $output differs from one run's: $(diff "$work/one/$output" "$work/out/$output" | head)"
done
diff -r "$work/one/gradescope" "$work/out/gradescope" > /dev/null || fail "the merged Gradescope files differ from one run's"
grep -q '^  frank *0/13  every case (AddCollisionImpulse tried to open a file' "$work/out/grades.txt" || fail "the hostile's row: $(cat "$work/out/grades.txt")"
[ "$(tail -n +2 "$work/out/grades.csv" | cut -d, -f1,3 | tr '\n' ' ')" = "alice,13 bob,13 carol,2 dave,2 erin,0 frank,0 " ] ||
  fail "the scores: $(cat "$work/out/grades.csv")"
echo "slurm_test: 6 submissions graded by 3 array tasks on Slurm $(sinfo -V | cut -d' ' -f2), merged as one run writes them"
