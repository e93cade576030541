#!/usr/bin/env bash
# Every test, the README's second command (.ci/run runs it):
#   1. build      scripts/build.sh --tests: the Release build in build/, tests and all (setup.sh --tests first)
#   2. ctest      every test of build/
#   3. asan       every test again, AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
#                 built without OSMesa (as on Mesa 25.1 and later): every render through EGL alone
#   4. tsan       the threaded tests under ThreadSanitizer (build-tsan/): the solver's thread team
#                 and the render pipeline's threads
#   5. fuzz       the scene loader and --set under libFuzzer for FUZZ_SECONDS (built in build-asan/,
#                 its corpus and findings in build-fuzz/)
# Sanitizer settings and the system-library suppressions: tests/sanitizers/README.md.
# Every stage runs even when one before failed; each prints its time. Exits non-zero if any
# failed; the last line is "N passed, N failed" (stages).
set -uo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=$(nproc)
FUZZ_SECONDS=${FUZZ_SECONDS:-120}

./scripts/setup.sh --tests || { echo "0 passed, 1 failed (setup)"; exit 1; }

san="$root/tests/sanitizers"
# exitcode/halt: a finding fails the test; the suppressions name system libraries only.
# detect_stack_use_after_return is off: it made the solver 35 % slower still (the determinism test
# 17.1 s vs 12.6 s; 2.9 s without sanitizers).
# intercept_tls_get_addr is off: clang 14's runtime takes a dynamic TLS block that starts 16 bytes
# into a page for glibc 2.19's layout and reads the two words before it as the block's address and
# size (google/sanitizers#1322); Mesa's and LLVM's blocks (EGL) land there by chance, and
# LeakSanitizer's tracer then crashed scanning that range at exit ("Tracer caught signal 11"). The
# blocks stay reachable through each thread's DTV, which LeakSanitizer scans as heap.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:check_initialization_order=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$san/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="suppressions=$san/tsan.supp:print_suppressions=0:second_deadlock_stack=1:halt_on_error=1"

# The tests ThreadSanitizer runs (ctest -R): the solver's thread team and sweep schedule alone
# and two threads in the team (the determinism test's two-thread run, the 1000-box heap, the
# 21-box pyramid); the frame pipeline alone, and whole scenes rendered, one pane or two, with the
# picturing thread, the drawing thread and the encoder's worker (film_tests). The program's
# commands start no threads of their own.
tsan_targets=(physics_tests physics_box_tests film_tests)
tsan_tests='^(ThreadTeam\.|SweepSchedule\.|FramePipeline\.|Determinism\.|Heap\.Thousand|Stack\.PyramidOf21Boxes|Video\.|RenderVideo\.|Playback\.)'

# Left out of the ASan+UBSan run, and only for their time: the five longest runs of the solver,
# 389 s, 355 s, 265 s, 264 s and 135 s under ASan+UBSan on two cores (11-70 s without). They run the
# code the 1000-box heap, the 21-box pyramid, the many-bodies scene of spheres and the determinism
# test run under ASan already, for more steps and bodies; the Release ctest runs them. The 210-box
# pyramid's minute (78 s) is left out for the same reason. Likewise the 120 renders of the
# concurrent-writers test (about 70 s in Release): every other render test runs the same
# temporary-file code under ASan; and the Slurm array (47 s), whose shards run the class grading
# that ClassGrade.* runs under ASan; and the layout check of the 1001-body scene (118 s, 27 s in
# Release): catalogue_checks_ex2_many_bodies simulates that scene under ASan, and the layout code
# runs on every other scene. And the pages and glTF files of the catalogue's scenes but three (the
# balls', the half-pipe's: spheres, planes, cylinders and a mesh; and s3_restitution's: three
# panes, equations, plots): the export's code is the same for every scene, and the Release run
# checks them all.
asan_exclude='^(Catalogue/EveryScene\.(ThePageDrawsEachBodyWhereTheTraceAndTheVideosCameraPutIt|TheGlbValidatesAndPutsEachBodyWhereTheTraceDoes)/(ex|s[124]|s3_(billiard|restitution_erratum)|s5_(boxes|hulls|rolling|shapes)|s6)|Stack\.(LargePyramidOf5050BoxesStandsFiveHundredSteps|PyramidOf210BoxesStandsSixtySeconds)|Heap/LongRun\.|Heap\.(Boxes|Spheres)ComeToRestWithSleepingOff|OutputConcurrency\.TwoOrFour|SlurmArray\.|Catalogue/EveryScene\.NothingCoversAnything/ex2_many_bodies)'

# Sanitizer builds use clang: GCC 12 compiles the solver with ASan+UBSan and -g 7x slower (69 s vs
# 10 s for physics/contact_solver.cpp: its variable tracking), and libFuzzer needs clang anyway.
# Line tables only: a finding's stack trace keeps its files and lines, and the build is faster;
# lld links the instrumented programs several times faster than ld.bfd.
san_flags="-O2 -gline-tables-only -DNDEBUG"
san_link="-fuse-ld=lld"
build_san() {  # build_san DIR SANITIZERS [CMake arguments...] -- [targets...]
  local dir=$1 sanitize=$2; shift 2
  local config=() targets=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do config+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  for t in "$@"; do targets+=(--target "$t"); done
  CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIMPULSE_SANITIZE="$sanitize" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$san_flags" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$san_flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$san_link" -DCMAKE_SHARED_LINKER_FLAGS="$san_link" "${config[@]}" >/dev/null &&
    cmake --build "$dir" -j"$jobs" "${targets[@]}"
}

stage_build() { ./scripts/build.sh --tests; }
stage_ctest() { ctest --test-dir build --output-on-failure -j2; }
stage_asan() {
  build_san build-asan address,undefined -DIMPULSE_FUZZ=ON -DIMPULSE_OSMESA=OFF &&
    ctest --test-dir build-asan --output-on-failure -j2 -E "$asan_exclude"
}
stage_tsan() {
  build_san build-tsan thread -- "${tsan_targets[@]}" &&
    ctest --test-dir build-tsan --output-on-failure -j2 -R "$tsan_tests"
}
stage_fuzz() {
  local fuzzer=build-asan/tests/fuzz/fuzz_scene
  [ -x "$fuzzer" ] || { echo "fuzz: $fuzzer was not built (the asan stage builds it)"; return 1; }
  local corpus=build-fuzz/corpus seeds=(assets/scenes tests/fuzz/seeds)
  [ -d tests/bad_scenes ] && seeds+=(tests/bad_scenes)
  mkdir -p "$corpus" build-fuzz/findings
  # -timeout: an input taking longer is a hang (a finding). Crashes are written to build-fuzz/findings/.
  "$fuzzer" -max_total_time="$FUZZ_SECONDS" -timeout=10 -rss_limit_mb=2048 \
    -dict=tests/fuzz/scene.dict -artifact_prefix=build-fuzz/findings/ -print_final_stats=1 \
    "$corpus" "${seeds[@]}" 2>build-fuzz/fuzz.log
  local status=$?
  grep -E '^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==|SUMMARY|fuzz_scene:)' build-fuzz/fuzz.log
  [ $status -eq 0 ] || { tail -60 build-fuzz/fuzz.log; ls build-fuzz/findings; }
  return $status
}

passed=0 failed=0 times=()
for stage in build ctest asan tsan fuzz; do
  echo "=== $stage"
  start=$SECONDS
  if "stage_$stage"; then passed=$((passed + 1)); result=passed; else failed=$((failed + 1)); result=FAILED; fi
  times+=("$stage $result in $(((SECONDS - start) / 60)) min $(((SECONDS - start) % 60)) s")
  echo "=== $stage $result"
done
echo "=== stages"
printf '%s\n' "${times[@]}"
echo "total $((SECONDS / 60)) min $((SECONDS % 60)) s"
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
