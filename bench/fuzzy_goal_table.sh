#!/usr/bin/env bash
# The goal table of fuzzy-part evaluation speed (docs/performance.md): for each size and core
# count, `fsdb eval` of the bench part with all fourteen values fuzzy (the part of
# tests/testing/fuzzy_bench_part.h), pinned with taskset to the first K cores; and of parts made
# from words, at the largest core count. Prints per row: wall and CPU seconds (/usr/bin/time), the
# evaluation's own millis, active voxels, microseconds of CPU per active voxel, that cost's ratio
# to the crisp sphere part's at the same size (same run), searches out of budget, and the
# speedup over one core. The parts made from words (and a shape of two, one placed by words)
# run at 128 on every core.
#   bench/fuzzy_goal_table.sh [BUILD] [SIZES] [CORES]
# BUILD (default build) holds fsdb; SIZES (default "64 128"); CORES (default "1 2"; e.g.
# "1 2 4 8 16" on a larger machine). One run per cell: the machine is noisy, so compare rows of
# one run, not runs.
set -euo pipefail
build=${1:-build} sizes=${2:-"64 128"} cores=${3:-"1 2"}
fsdb="$build/fsdb"
[ -x "$fsdb" ] || { echo "no $fsdb: build first (make build)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/fuzzy14.json" <<'JSON'
{"kind":"part","name":"bench","params":{
 "eps1":{"tri":[0.665,0.7,0.735]},"eps2":{"tri":[1.235,1.3,1.365]},"a1":{"tri":[0.95,1,1.05]},
 "a2":{"tri":[0.76,0.8,0.84]},"a3":{"tri":[1.9,2,2.1]},"kx":{"tri":[0.35,0.4,0.45]},
 "ky":{"tri":[-0.35,-0.3,-0.25]},"kv":{"tri":[0.285,0.3,0.315]},"t":{"tri":[1.15,1.2,1.25]}},
 "transform":{"translate":[{"tri":[0.475,0.5,0.525]},{"tri":[-0.2625,-0.25,-0.2375]},{"tri":[0.095,0.1,0.105]}],
 "rotate":{"axis":[1,1,0],"deg":{"tri":[27,30,33]}},"scale":{"tri":[1.425,1.5,1.575]}}}
JSON
echo '{"kind":"part","name":"sphere","params":{"eps1":1,"eps2":1,"a1":1,"a2":1,"a3":1}}' > "$work/crisp.json"
i=0
for text in "a slightly bent cylinder" "a very twisted long box" "a very sharp pyramid" \
            "a slightly tapered and slightly bent rod"; do
  echo "{\"kind\":\"part\",\"name\":\"words$i\",\"text\":\"$text\"}" > "$work/words$i.json"
  i=$((i + 1))
done
# The shape of the goal: a big box with a slightly bent cylinder placed about 3 to its right.
echo '{"kind":"shape","name":"placed","tree":{"op":"union","children":[{"part":{"name":"base","text":"a big box"}},{"part":{"name":"c","text":"a slightly bent cylinder"},"transform":{"place":{"relative_to":"base","direction":"right","distance":"about 3"}}}]}}' > "$work/words$i.json"
max=$(nproc)
# run FILE SIZE K: prints "wall cpu millis active exhausted"
run() {
  local file=$1 n=$2 k=$3 t out
  t="$work/time"
  out=$(/usr/bin/time -f '%e %U %S' -o "$t" taskset -c "0-$((k - 1))" "$fsdb" eval "$file" --resolution "$n")
  read -r wall user sys < "$t"
  python3 -c '
import json, sys
r = json.loads(sys.argv[1])
print(sys.argv[2], "%.2f" % (float(sys.argv[3]) + float(sys.argv[4])), round(r["millis"]), r["active_voxels"], r["exhausted_searches"])
' "$out" "$wall" "$user" "$sys"
}
printf '%-28s %5s %5s %8s %8s %9s %10s %9s %9s %9s %8s\n' part size cores wall_s cpu_s eval_ms active us/active x_crisp exhausted speedup
for n in $sizes; do
  lastk=${cores##* }
  (( lastk > max )) && lastk=$max
  read -r cw cc cm ca ce <<< "$(run "$work/crisp.json" "$n" "$lastk")"
  crisp_us=$(python3 -c "print($cc * 1e6 / max($ca, 1))")
  printf '%-28s %5s %5s %8s %8s %9s %10s %9.2f %9s %9s %8s\n' "crisp sphere" "$n" "$lastk" "$cw" "$cc" "$cm" "$ca" "$crisp_us" 1 "$ce" -
  one=""
  for k in $cores; do
    (( k > max )) && continue
    read -r w c m a e <<< "$(run "$work/fuzzy14.json" "$n" "$k")"
    [ -z "$one" ] && one=$w
    python3 -c "
w, c, a = $w, $c, $a
us = c * 1e6 / max(a, 1)
print('%-28s %5s %5s %8s %8s %9s %10s %9.2f %9.1f %9s %8.2f' % ('all 14 values fuzzy', '$n', '$k', w, c, '$m', a, us, us / $crisp_us, '$e', $one / w))"
  done
done
# Parts made from words, at 128 (the size of the goal for them), on every core.
n=128
for f in "$work"/words*.json; do
  read -r w c m a e <<< "$(run "$f" "$n" "$max")"
  label=$(python3 -c 'import json,sys; d = json.load(open(sys.argv[1])); print(d.get("text", "big box + bent cylinder right")[:28])' "$f")
  printf '%-28s %5s %5s %8s %8s %9s %10s %9s %9s %9s %8s\n' "$label" "$n" "$max" "$w" "$c" "$m" "$a" - - "$e" -
done
