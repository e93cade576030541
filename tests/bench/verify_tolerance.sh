#!/usr/bin/env bash
# What `impulse verify`'s comparison sees (render/image_compare.h), to choose its defaults by
# measurement: every catalogue scene's default moments recorded with llvmpipe as it comes, then
# rendered again at other vector widths and CPU capabilities (which must pass), and changes a
# course must see (which must fail). One line per moment compared:
#   QUALITY SCENE CASE t=SECONDS REGION SHARE% EDGES VERDICT
# REGION is the largest connected region of differing pixels, SHARE the differing pixels' share of
# the frame, EDGES the anti-aliased edge pixels forgiven; VERDICT matches or DIFFERS.
# Usage: tests/bench/verify_tolerance.sh build/demos/impulse OUT_DIR [low medium high] > table.txt
# (SCENES='assets/scenes/ex5*.toml' to measure only some scenes.) GALLIUM_OVERRIDE_CPU_CAPS=nosse is
# llvmpipe without any SIMD, which no x86-64 CPU is; sse2 renders the same bytes as sse4.1.
set -uo pipefail
impulse=$(realpath "$1"); out=$2; shift 2
qualities=${*:-low medium high}
cd "$(dirname "$0")/../.."

# Prints the moments of one verify run as table rows.
rows() {  # quality scene case -- verify arguments...
  local quality=$1 scene=$2 case=$3; shift 4
  "$@" 2>&1 | sed -n 's/.*t = \([0-9.]*\) s \(matches\|DIFFERS\).*/\1 \2 \0/p' |
    while read -r time verdict line; do
      region=$(sed -n 's/.*largest region of differing pixels \([0-9]*\).*/\1/p' <<<"$line")
      share=$(sed -n 's/.* \([0-9.]*\) % of the frame.*/\1/p' <<<"$line")
      edges=$(sed -n 's/.* \([0-9]*\) anti-aliased edge pixels forgiven.*/\1/p' <<<"$line")
      echo "$quality $scene $case t=$time ${region:-0} ${share:-0} ${edges:-0} $verdict"
    done
}

for quality in $qualities; do
  for path in ${SCENES:-assets/scenes/*.toml}; do
    scene=$(basename "$path" .toml)
    golden=$out/$quality/$scene
    env -u LP_NATIVE_VECTOR_WIDTH -u GALLIUM_OVERRIDE_CPU_CAPS "$impulse" -q verify "$path" --golden "$golden" \
      --quality "$quality" --update >/dev/null 2>&1 || echo "# $scene: --update failed" >&2
    for variant in LP_NATIVE_VECTOR_WIDTH=128 LP_NATIVE_VECTOR_WIDTH=256 GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 \
                   GALLIUM_OVERRIDE_CPU_CAPS=nosse; do
      rows "$quality" "$scene" "$variant" -- env -u LP_NATIVE_VECTOR_WIDTH "$variant" "$impulse" -q verify "$path" \
        --golden "$golden" --quality "$quality"
    done
  done
done
