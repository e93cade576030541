#!/usr/bin/env bash
# A class graded on this machine: N submissions (default 200) generated from the corrected listing
# and the listing as printed (its parentheses fixed), each text its own (a comment names the
# student, and the corrected ones differ in a constant's spelling), graded by `impulse grade
# FOLDER --jobs J` (default 2) twice: cold (an empty build cache: every file compiled) and warm
# (the same files again: nothing compiled). Videos are never made by a class's grade. Prints:
#   submissions jobs cold_s cold_s_per_submission warm_s warm_s_per_submission compile_s_per_submission
# compile_s_per_submission is (cold - warm) x jobs / N: a file's compile, on one core.
# Both runs pass --regrade: without it the warm run would reuse every kept result and run no case.
# Usage: tests/bench/grade_bench.sh build/demos/impulse [N [JOBS]]     (--smoke: 4 submissions)
set -euo pipefail
impulse=$(realpath "$1"); count=${2:-200}; jobs=${3:-2}
[ "$count" = --smoke ] && count=4
cd "$(dirname "$0")/../.."
work=$(mktemp -d /tmp/impulse-grade-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
mkdir "$work/submissions"
for i in $(seq 1 "$count"); do
  if [ $((i % 2)) -eq 0 ]; then
    { echo "// student $i: listing 1 as printed, parentheses fixed"; cat assets/workshop/listing1.cpp; } > "$work/submissions/student_$i.cpp"
  else
    { echo "// student $i: listing 1 corrected"; sed "s/0\.5f/(0.5f + 0.0f * $i)/" assets/workshop/listing1_corrected.cpp; } \
      > "$work/submissions/student_$i.cpp"
  fi
done
export IMPULSE_RESPONSE_CACHE=$work/cache
run() {
  local start=$EPOCHREALTIME
  "$impulse" grade "$work/submissions" --jobs "$jobs" --regrade --csv "$work/grades.csv" > "$work/table.txt" 2> "$work/progress.txt" || true
  awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }'
}
cold=$(run)
warm=$(run)
graded=$(tail -n +2 "$work/grades.csv" | awk -F, '$5 == 1' | wc -l)
[ "$graded" -eq "$count" ] || { echo "grade_bench: only $graded of $count submissions compiled" >&2; head -20 "$work/table.txt" >&2; exit 1; }
printf 'submissions jobs cold_s cold_s_per_submission warm_s warm_s_per_submission compile_s_per_submission\n'
awk -v n="$count" -v j="$jobs" -v c="$cold" -v w="$warm" \
  'BEGIN { printf "%d %d %.1f %.3f %.1f %.3f %.3f\n", n, j, c, c / n, w, w / n, (c - w) * j / n }'
