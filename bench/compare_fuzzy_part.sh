#!/usr/bin/env bash
# Base-against-new timing of the alpha-field benches in one run, alternating the
# two builds so that load from other work on the machine hits both alike. Prints one line per run
# (wall and process CPU from /usr/bin/time, the bench's counters) and then the medians.
#   bench/compare_fuzzy_part.sh BASE_BUILD NEW_BUILD [REPEATS] [SIZES]
# BASE_BUILD, NEW_BUILD: build folders holding bench/bench_fuzzy_part_field and
# bench/bench_evaluation (e.g. the base commit built elsewhere, and build/). REPEATS (default 3)
# runs of each; SIZES (default "32 64") of BM_DeformedPartGrid; then the 10-part assembly and the
# crisp sphere part at 256.
set -euo pipefail
base=$1 new=$2 repeats=${3:-3} sizes=${4:-"32 64"}
log=$(mktemp)
run() {  # label build bench filter
  local label=$1 build=$2 bench=$3 filter=$4 t out
  t=$(mktemp)
  out=$(/usr/bin/time -f '%e %U %S' -o "$t" "$build/bench/$bench" --benchmark_filter="$filter" \
          2>/dev/null | grep -E '^BM_' | tail -n 1)
  read -r wall user sys < "$t"
  rm -f "$t"
  local cpu exhausted active
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
  exhausted=$(grep -oE 'exhausted=[0-9.]+k?' <<< "$out" | cut -d= -f2 || true)
  active=$(grep -oE 'active_voxels=[0-9.k M]+' <<< "$out" | head -n 1 | cut -d= -f2 || true)
  # The bench's own real time per iteration (the process's wall also holds setup and repeats).
  local time
  time=$(awk '{ print $2 $3 }' <<< "$out")
  echo "$label $filter wall=$wall cpu=$cpu bench=$time exhausted=${exhausted:--} active=${active:--}" \
    | tee -a "$log"
}
for r in $(seq "$repeats"); do
  for n in $sizes; do
    f="BM_DeformedPartGrid/across:$n/impl:1"
    if (( r % 2 )); then run base "$base" bench_fuzzy_part_field "$f"; run new "$new" bench_fuzzy_part_field "$f"
    else run new "$new" bench_fuzzy_part_field "$f"; run base "$base" bench_fuzzy_part_field "$f"; fi
  done
  for f in 'BM_TenPartAssembly/256/' 'BM_CrispSpherePart/256/'; do
    run base "$base" bench_evaluation "$f"; run new "$new" bench_evaluation "$f"
  done
done
echo "medians (process wall s, process cpu s, bench real time per iteration):"
median() {  # field name; the lines of one key on stdin
  grep -oE "$1=[0-9.]+[a-z]*" | cut -d= -f2 | sort -n | awk '{ v[NR] = $0 } END { print v[int((NR + 1) / 2)] }'
}
cut -d' ' -f1,2 "$log" | sort -u -k2,2 -k1,1 | while read -r label filter; do
  lines=$(grep -F "$label $filter " "$log")
  echo "$label $filter wall=$(median wall <<< "$lines") cpu=$(median cpu <<< "$lines")" \
       "bench=$(median bench <<< "$lines") (n=$(wc -l <<< "$lines"))"
done
rm -f "$log"
