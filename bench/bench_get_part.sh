#!/usr/bin/env bash
# GET /parts/{id} throughput: `fsdb serve` holding 1000 parts under `wrk -t2 -c16 -d5s` (a Lua
# script cycles through the 1000 ids), against bench/bare_httplib (a bare cpp-httplib server
# returning the same JSON body on the same route, same thread pool size) under the same load.
# Both set TCP_NODELAY.
# Usage: bench/bench_get_part.sh [BUILD_DIR] [DURATION]   (default build, 5s); one run each.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
duration=${2:-5s}
threads=$(python3 -c "import os; print(max(2, os.cpu_count()))")  # fsdb's default --threads
work=$(mktemp -d)
trap 'stop_server; rm -rf "$work"' EXIT

gen_parts 1000 "$work/parts.jsonl"
"$build/fsdb" import "$work/parts.jsonl" --db "$work/parts.sqlite" 2>/dev/null | tail -1

# load NAME URL: wrk on URL cycling the ids; prints one summary line, sets RPS, P50, P99.
load() {
  local out
  out=$(wrk -t2 -c16 -d"$duration" --latency -s "$work/cycle.lua" "$2")
  RPS=$(awk '/^Requests\/sec:/ {print $2}' <<<"$out")
  P50=$(awk '$1 == "50%" {print $2}' <<<"$out")
  P99=$(awk '$1 == "99%" {print $2}' <<<"$out")
  local errors
  errors=$(grep -E 'Non-2xx|Socket errors' <<<"$out" || true)
  printf '%-34s %10s req/s   p50 %8s   p99 %8s   %s\n' "$1" "$RPS" "$P50" "$P99" "$errors"
}

echo "== GET /parts/{id}, 1000 parts, wrk -t2 -c16 -d$duration, server threads $threads"
for level in info warn; do
  start_server "$work/serve-$level.log" "$build/fsdb" --log-level "$level" serve --port 0 \
    --threads "$threads" --db "$work/parts.sqlite"
  if [[ ! -f $work/cycle.lua ]]; then
    curl -sf "$SERVER_URL/parts?limit=1000" | python3 -c '
import json, sys
ids = [str(o["id"]) for o in json.load(sys.stdin)["items"]]
print("local ids = {" + ",".join(ids) + "}")
print("local i = 0")
print("request = function()\n  i = i % #ids + 1\n  return wrk.format(\"GET\", \"/parts/\" .. ids[i])\nend")
' >"$work/cycle.lua"
    curl -sf "$SERVER_URL/parts/$(grep -o '[0-9]\+' "$work/cycle.lua" | head -1)" >"$work/body.json"
  fi
  load "fsdb serve (--log-level $level)" "$SERVER_URL"
  [[ $level == info ]] && fsdb_rps=$RPS
  stop_server
done

start_server "$work/bare.log" "$build/bench/bare_httplib" "$work/body.json" "$threads" nodelay
load "bare cpp-httplib ($(wc -c <"$work/body.json") B body)" "$SERVER_URL"
stop_server
python3 -c "print('ratio bare / fsdb (log info) = %.2f' % ($RPS / $fsdb_rps))"
