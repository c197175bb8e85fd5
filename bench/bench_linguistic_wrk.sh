#!/usr/bin/env bash
# POST /query/linguistic under load: `fsdb serve` on the bench catalogue of N parts (built once by
# bench_linguistic into build/bench-data/parts-N.sqlite and reused), `wrk -t2 -c16` cycling
# through bench_linguistic's five queries (selective to broad), each answered with limit 10.
# Reports throughput, p50 and p99 per query and for the mix. Goal: p99 < 50 ms at 1M parts.
# Usage: bench/bench_linguistic_wrk.sh [BUILD_DIR] [N] [DURATION]   (default build 1000000 10s)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
n=${2:-1000000}
duration=${3:-10s}
data="$build/bench-data"
db="$data/parts-$n.sqlite"
work=$(mktemp -d)
trap 'stop_server; rm -rf "$work"' EXIT

if [[ ! -f $db ]]; then
  echo "== building the catalogue of $n parts (once: $db)"
  "$build/bench/bench_linguistic" --sizes "$n" --dir "$data" --reps 1 --scan-reps 0 >/dev/null
fi

queries=("find a very twisted part" "find a slightly bent part" "find a very tapered and slightly bent part"
         "find a very round part" "find a big part")

# wrk script: POST the given queries in turn (one per request).
lua() {
  {
    echo "local bodies = {"
    for q in "$@"; do printf '  [[{"text": "%s", "limit": 10}]],\n' "$q"; done
    echo "}"
    echo "local i = 0"
    echo 'request = function()'
    echo '  i = i % #bodies + 1'
    echo '  return wrk.format("POST", "/query/linguistic", {["Content-Type"] = "application/json"}, bodies[i])'
    echo 'end'
  } >"$work/q.lua"
}

load() {
  local out
  out=$(wrk -t2 -c16 -d"$duration" --latency -s "$work/q.lua" "$SERVER_URL")
  local rps p50 p99 errors
  rps=$(awk '/^Requests\/sec:/ {print $2}' <<<"$out")
  p50=$(awk '$1 == "50%" {print $2}' <<<"$out")
  p99=$(awk '$1 == "99%" {print $2}' <<<"$out")
  errors=$(grep -E 'Non-2xx|Socket errors' <<<"$out" || true)
  printf '%-46s %9s req/s   p50 %9s   p99 %9s   %s\n' "$1" "$rps" "$p50" "$p99" "$errors"
}

start_server "$work/serve.log" "$build/fsdb" --log-level warn serve --port 0 --db "$db"
# One request of each first: the answer must be 200 with hits (a broken query would time as fast).
for q in "${queries[@]}"; do
  hits=$(curl -sf -H 'Content-Type: application/json' -d "{\"text\": \"$q\", \"limit\": 10}" \
    "$SERVER_URL/query/linguistic" | python3 -c 'import json,sys; print(len(json.load(sys.stdin)["results"]))')
  [[ $hits -gt 0 ]] || { echo "no hits for \"$q\"" >&2; exit 1; }
done
# Five seconds of the mix first, not counted: the server's background warm-up of the structural
# search's graphs finishes and the page caches fill, as on a server that has been up a while.
lua "${queries[@]}"
wrk -t2 -c16 -d5s -s "$work/q.lua" "$SERVER_URL" >/dev/null
echo "== POST /query/linguistic, $n parts, wrk -t2 -c16 -d$duration, server threads default"
for q in "${queries[@]}"; do
  lua "$q"
  load "\"$q\""
done
lua "${queries[@]}"
load "the five in turn"
