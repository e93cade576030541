#!/usr/bin/env bash
# A class graded on a Slurm cluster: an array job whose tasks each grade every Nth submission
# (`impulse grade --shard K/N`, keeping each student's result in OUT/reports), then one job, once
# they have all ended, that merges the results into the table (OUT/grades.txt), the CSV, Gradescope's
# files and the JUnit XML, as one run on one machine would have written them.
#
# Usage: grade_class.sh SUBMISSIONS OUT [TASKS]
#   IMPULSE        the impulse program (default: impulse on PATH), on a path every node sees
#   CPUS_PER_TASK  cores per task, its --jobs (default 2)
#   WAIT=1         return when the merge has ended (sbatch --wait), with its exit code
# SUBMISSIONS and OUT must be on a file system every node sees; so must IMPULSE_RESPONSE_CACHE,
# when set, for the tasks to share compiled files.
set -euo pipefail
submissions=$(realpath "$1") out=$(realpath -m "$2") tasks=${3:-4}
impulse=$(realpath "${IMPULSE:-$(command -v impulse)}") cpus=${CPUS_PER_TASK:-2}
mkdir -p "$out/logs" "$out/reports"

array=$(sbatch --parsable --job-name=impulse-grade --array="1-$tasks" --cpus-per-task="$cpus" \
  --output="$out/logs/shard-%a.out" \
  --wrap="'$impulse' grade '$submissions' --jobs $cpus --shard \$SLURM_ARRAY_TASK_ID/$tasks --reports '$out/reports'")
echo "grade_class: array job $array, $tasks tasks of $cpus cores"

# afterany: the merge runs whatever the tasks' exit codes (2 is some student failing a case).
merge=(sbatch --parsable --job-name=impulse-grade-merge --dependency="afterany:$array" --output="$out/logs/merge.out"
  --wrap="'$impulse' grade '$submissions' --merge-reports '$out/reports' --csv '$out/grades.csv' --gradescope '$out/gradescope' --junit '$out/grades.xml' > '$out/grades.txt'")
if [ "${WAIT:-0}" = 1 ]; then
  status=0
  "${merge[@]}" --wait > /dev/null || status=$?
  echo "grade_class: merged into $out (exit code $status)"
  exit "$status"
fi
echo "grade_class: merge job $("${merge[@]}"), into $out"
