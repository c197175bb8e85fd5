#!/usr/bin/env bash
# GET /parts/{id} and GET /shapes/{id} throughput: `fsdb serve` holding 1000 parts and 1000
# shapes (each a union of three of the parts) under `wrk -t2 -c16 -d5s` (a Lua script
# cycles through the ids), against bench/bare_httplib (a bare cpp-httplib server returning the
# same JSON body on the same route, same thread pool size) under the same load. Both set
# TCP_NODELAY. fsdb runs with its request log on (--log-level info: a line per request, the
# default) and off (warn). Each server first gets WARMUP (default 2s) of the same load, not
# counted: fsdb builds the structural search's graphs of its 1000 shapes in the background when it
# starts (about 0.2 s of both cores), and the measured run is of a server that has been up a while,
# as in bench_linguistic_wrk.sh; COLD=1 leaves the warm-up out. REPS rounds, alternating; medians
# and ratios of medians.
# Usage: [WARMUP=2s] [COLD=1] bench/bench_get_part.sh [BUILD_DIR] [DURATION] [REPS]   (default build, 5s, 3)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
duration=${2:-5s}
reps=${3:-3}
threads=$(python3 -c "import os; print(max(2, os.cpu_count()))")
work=$(mktemp -d)
trap 'stop_server; rm -rf "$work"' EXIT

gen_parts 1000 "$work/parts.jsonl"
python3 - "$work/shapes.jsonl" <<'PY'
import json, random, sys
rnd = random.Random(5)
with open(sys.argv[1], "w") as out:
    for i in range(1, 1001):
        picks = rnd.sample(range(1, 1001), 3)
        children = [{"part": "part-%06d" % p} for p in picks]
        out.write(json.dumps({"kind": "shape", "name": "shape-%06d" % i,
                              "tree": {"op": "union", "children": children}}) + "\n")
PY
"$build/fsdb" import "$work/parts.jsonl" "$work/shapes.jsonl" --db "$work/objects.sqlite" 2>/dev/null | tail -1

# cycle KIND: a wrk script cycling the ids of KIND; body.KIND.json: one answer, for the bare server.
cycle() {
  curl -sf "$SERVER_URL/$1s?limit=1000" | python3 -c '
import json, sys
ids = [str(o["id"]) for o in json.load(sys.stdin)["items"]]
print("local ids = {" + ",".join(ids) + "}")
print("local i = 0")
print("request = function()\n  i = i % #ids + 1\n  return wrk.format(\"GET\", \"/'"$1"'s/\" .. ids[i])\nend")
' >"$work/cycle.$1.lua"
  curl -sf "$SERVER_URL/$1s/$(grep -o '[0-9]\+' "$work/cycle.$1.lua" | head -1)" >"$work/body.$1.json"
}

# load NAME KIND: wrk on the server cycling KIND's ids; appends "rps p50 p99" (ms) to $work/NAME.
warmup=${WARMUP:-2s}
load() {
  local out
  [[ ${COLD:-0} == 1 ]] || wrk -t2 -c16 -d"$warmup" -s "$work/cycle.$2.lua" "$SERVER_URL" >/dev/null
  out=$(wrk -t2 -c16 -d"$duration" --latency -s "$work/cycle.$2.lua" "$SERVER_URL")
  if grep -qE 'Non-2xx|Socket errors' <<<"$out"; then echo "$1: $(grep -E 'Non-2xx|Socket errors' <<<"$out")" >&2; exit 1; fi
  python3 - "$out" >>"$work/$1" <<'PY'
import re, sys
text = sys.argv[1]
def ms(label):
    m = re.search(r"^\s*" + label + r"\s+([\d.]+)(us|ms|s)\s*$", text, re.M)
    return float(m.group(1)) * {"us": 0.001, "ms": 1, "s": 1000}[m.group(2)]
rps = float(re.search(r"^Requests/sec:\s+([\d.]+)", text, re.M).group(1))
print(rps, ms("50%"), ms("99%"))
PY
}

start_server "$work/setup.log" "$build/fsdb" --log-level warn serve --port 0 --db "$work/objects.sqlite"
cycle part
cycle shape
stop_server

for _ in $(seq 1 "$reps"); do
  for kind in part shape; do
    for level in info warn; do
      start_server "$work/serve.log" "$build/fsdb" --log-level "$level" serve --port 0 --threads "$threads" \
        --db "$work/objects.sqlite"
      load "fsdb.$kind.$level" "$kind"
      stop_server
    done
    # The bare server answers the route with the fsdb body (cpp-httplib, same pool size).
    start_server "$work/bare.log" "$build/bench/bare_httplib" "$work/body.$kind.json" "$threads" nodelay "$kind"
    load "bare.$kind" "$kind"
    stop_server
  done
done

echo "== GET /{parts,shapes}/{id}, 1000 of each, wrk -t2 -c16 -d$duration, server threads $threads, medians of $reps, $([[ ${COLD:-0} == 1 ]] && echo "measured from the start" || echo "after $warmup of warm-up")"
python3 - "$work" <<'PY'
import statistics, sys, os
work = sys.argv[1]
def med(name, k):
    rows = [list(map(float, l.split())) for l in open(os.path.join(work, name))]
    return statistics.median(r[k] for r in rows), [r[0] for r in rows]
for kind in ("part", "shape"):
    bare, bare_runs = med("bare." + kind, 0)
    bare50, bare99 = med("bare." + kind, 1)[0], med("bare." + kind, 2)[0]
    size = os.path.getsize(os.path.join(work, "body.%s.json" % kind))
    print("GET /%ss/{id} (%d B body)" % (kind, size))
    print("  %-30s %8.0f req/s  p50 %6.2f ms  p99 %6.2f ms  runs %s" % ("bare cpp-httplib", bare, bare50, bare99, " ".join("%.0f" % r for r in bare_runs)))
    for level, what in (("info", "fsdb, request log on (info)"), ("warn", "fsdb, request log off (warn)")):
        rps, runs = med("fsdb.%s.%s" % (kind, level), 0)
        p50, p99 = med("fsdb.%s.%s" % (kind, level), 1)[0], med("fsdb.%s.%s" % (kind, level), 2)[0]
        print("  %-30s %8.0f req/s  p50 %6.2f ms  p99 %6.2f ms  runs %s   %.2fx bare, p99 %.2fx bare" % (what, rps, p50, p99, " ".join("%.0f" % r for r in runs), rps / bare, p99 / bare99))
PY
