#!/usr/bin/env bash
# The changes `impulse verify` must see at every quality (the other half of verify_tolerance.sh):
# bounce.toml's goldens at four moments, then a recoloured ball, the ball moved by a quarter of its
# radius, a missing arrow (the velocity arrows, with the legend off in goldens and run alike, so
# that only the arrows differ), one caption word changed (2 m -> 3 m) and a missing legend line
# (friction impulse); and a block at rest, asleep and drawn pale at 2 s, recoloured green ->
# vermillion. One line per moment compared:
#   QUALITY CASE t=SECONDS REGION SHARE% FAINT VERDICT BOX
# BOX is where the largest region of differing pixels lies; FAINT is the largest region over the
# faint threshold when that is what differs.
# Usage: tests/bench/verify_changes.sh build/demos/impulse OUT_DIR [low medium high] > table.txt
set -uo pipefail
impulse=$(realpath "$1"); out=$2; shift 2
qualities=${*:-low medium high}
cd "$(dirname "$0")/../.."
scene=assets/scenes/bounce.toml
caption='caption[0].text="Two impacts: a ball dropped from 3 m, and two spheres rolling towards each other."'

rows() {  # quality case -- verify arguments...
  local quality=$1 case=$2; shift 3
  "$@" 2>&1 | sed -n 's/.*t = \([0-9.]*\) s \(matches\|DIFFERS\) from [^:]*\(.*\)/\1 \2 \3/p' |
    while read -r time verdict line; do
      region=$(sed -n 's/.*largest region of differing pixels \([0-9]*\).*/\1/p' <<<"$line")
      share=$(sed -n 's/.* \([0-9.]*\) % of the frame.*/\1/p' <<<"$line")
      faint=$(sed -n 's/.*a faint difference over an area: \([0-9]*\) touching pixels.*/\1/p' <<<"$line")
      box=$(sed -n 's/.*\(in x [0-9]*\.\.[0-9]*, y [0-9]*\.\.[0-9]*\).*/\1/p' <<<"$line")
      echo "$quality $case t=$time ${region:-0} ${share:-0} ${faint:-0} $verdict ${box// /_}"
    done
}

block=$out/pale_block.toml  # a block at rest, seen from its side: asleep from about 1 s
mkdir -p "$out"
cat >"$block" <<'END'
[scene]
duration = 2.0
[camera]
position = [0.8, 0.25, 3.5]
target = [0, 0.2, 0]
[[body]]
shape = "plane"
[[body]]
name = "block"
shape = "box"
size = [0.8, 0.4, 0.4]
position = [0, 0.2, 0]
colour = "#009e73"
END

for quality in $qualities; do
  golden=$out/$quality/bounce bare=$out/$quality/bounce_no_legend
  run=("$impulse" -q verify "$scene" --quality "$quality")
  "${run[@]}" --golden "$golden" --at 0,0.3,0.65,2.6 --update >/dev/null 2>&1
  "${run[@]}" --golden "$bare" --at 0,0.3,0.65,2.6 --set overlay.legend=false --update >/dev/null 2>&1
  rows "$quality" recoloured -- "${run[@]}" --golden "$golden" --set 'body[dropped ball].colour="#d55e00"'
  rows "$quality" moved_r/4 -- "${run[@]}" --golden "$golden" --set 'body[dropped ball].position=[-2.1, 2.4, 0]'
  rows "$quality" no_velocity_arrows -- "${run[@]}" --golden "$bare" --set overlay.legend=false --set draw.velocities=false
  rows "$quality" caption_word -- "${run[@]}" --golden "$golden" --at 0.3 --set "$caption"
  rows "$quality" no_friction_legend_line -- "${run[@]}" --golden "$golden" --at 0.3 --set draw.friction=false
  "$impulse" -q verify "$block" --quality "$quality" --golden "$out/$quality/pale_block" --at 0,2 --update >/dev/null 2>&1
  rows "$quality" pale_recoloured -- "$impulse" -q verify "$block" --quality "$quality" --golden "$out/$quality/pale_block" \
    --set 'body[block].colour="#d55e00"'
done
