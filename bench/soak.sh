#!/usr/bin/env bash
# Soak: `fsdb serve` (request log off: --log-level warn) on a catalogue of 3000 parts and 600
# shapes (bench parts from gen_parts, shapes of two or three of them, plus the demo catalogue)
# under a mixed load for DURATION seconds: `wrk -t2 -c64 --latency` on reads (a Lua script
# cycling GET /parts/{id}, GET /shapes/{id} and every tenth request a GET /parts?limit=&after=
# page) while four closed-loop clients (python3, one request at a time, a new connection each)
# run beside it: writes (POST /parts, from parameters or from words, PUT /parts/{id}, DELETE of
# its own parts), evaluations (POST /shapes/{id}/evaluate and POST /evaluate, resolution 32),
# linguistic searches (POST /query/linguistic, POST /query) and structural searches
# (POST /query/csg: phrases, relations, a formula). Every answer is checked (status and the
# members it must have). The server's VmRSS is sampled every second.
# Reports wrk's rate, p50 and p99, its non-2xx and socket errors (with the host's listen-queue
# overflows, which explain timeouts), each client's count and errors (the first five failures in
# full), the 5xx total and the RSS in the first seconds after the warm-up and at the end (each the
# median of five samples), the growth between the two and the peak. The warm-up (SOAK_WARMUP
# seconds, default 40) runs the same load before the measured DURATION: its answers are checked,
# its rates not reported. The last line is `soak: errors=N 5xx=N rss_growth=X%`; exit 1 when
# errors > 0 (any non-2xx, socket or connection error, or answer lacking a member), 5xx > 0, the
# server died or did not stop cleanly, or the RSS grew by 10% or more.
# Usage: bench/soak.sh [BUILD_DIR] [DURATION_S]   (default build, 60)
#   SOAK_THREADS=N passes --threads N to the server (default: the server's own, max(8, cores)).
#   SOAK_CLIENTS="write eval ling csg" chooses the clients beside wrk (to tell what grows the RSS).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
duration=${2:-60}
[[ $duration =~ ^[0-9]+$ && $duration -ge 5 ]] || { echo "DURATION_S must be a whole number of seconds, at least 5" >&2; exit 2; }
warmup=${SOAK_WARMUP:-40}
[[ $warmup =~ ^[0-9]+$ && $warmup -ge 1 ]] || { echo "SOAK_WARMUP must be a whole number of seconds, at least 1" >&2; exit 2; }
threads=${SOAK_THREADS:-}
read -r -a clients <<<"${SOAK_CLIENTS-write eval ling csg}"
work=$(mktemp -d)
loop_pids=()
sampler_pid=
cleanup() {
  [[ -n $sampler_pid ]] && kill "$sampler_pid" 2>/dev/null || true
  for p in "${loop_pids[@]}"; do kill "$p" 2>/dev/null || true; done
  stop_server
  rm -rf "$work"
}
trap cleanup EXIT

# The catalogue: the demo's, 3000 bench parts and 600 shapes over them (unions of three,
# differences of two, a union with an intersection inside).
gen_parts 3000 "$work/parts.jsonl"
python3 - "$work/shapes.jsonl" <<'PY'
import json, random, sys
rnd = random.Random(6)
leaf = lambda p: {"part": "part-%06d" % p}
with open(sys.argv[1], "w") as out:
    for i in range(1, 601):
        a, b, c = rnd.sample(range(1, 3001), 3)
        if i % 3 == 0: tree = {"op": "union", "children": [leaf(a), leaf(b), leaf(c)]}
        elif i % 3 == 1: tree = {"op": "difference", "children": [leaf(a), leaf(b)]}
        else: tree = {"op": "union", "children": [leaf(a), {"op": "intersection", "children": [leaf(b), leaf(c)]}]}
        out.write(json.dumps({"kind": "shape", "name": "shape-%06d" % i, "tree": tree}) + "\n")
PY
imported=$("$build/fsdb" import "$here/../schema/demo"/*.jsonl "$work/parts.jsonl" "$work/shapes.jsonl" \
  --db "$work/soak.sqlite" 2>/dev/null | tail -1)
[[ $imported == *"failed 0" ]] || { echo "import: $imported" >&2; exit 1; }

start_server "$work/serve.log" "$build/fsdb" --log-level warn serve --port 0 --db "$work/soak.sqlite" \
  ${threads:+--threads "$threads"}
curl -sf "$SERVER_URL/health" >/dev/null

# ids.json (for the clients) and reads.lua (for wrk): every stored part and shape id.
python3 - "$SERVER_URL" "$work" <<'PY'
import json, os, sys, urllib.request
url, work = sys.argv[1], sys.argv[2]
def listing(kind):
    items, after = [], None
    while True:
        q = "%s/%s?limit=1000" % (url, kind) + ("&after=%d" % after if after else "")
        page = json.load(urllib.request.urlopen(q))
        items += page["items"]
        after = page["next_after"]
        if after is None: return items
parts, shapes = listing("parts"), listing("shapes")
ids = {"parts": [p["id"] for p in parts], "shapes": [s["id"] for s in shapes],
       "bench_parts": [p["id"] for p in parts if p["name"].startswith("part-")]}
json.dump(ids, open(os.path.join(work, "ids.json"), "w"))
lua = """local parts = {%s}
local shapes = {%s}
local threads = {}
function setup(thread) table.insert(threads, thread) end
local n, i, j, k = 0, 0, 0, 0
c4, c5, first = 0, 0, ""
request = function()
  n = n + 1
  if n %% 10 == 0 then
    k = k %% #parts + 1
    return wrk.format("GET", "/parts?limit=" .. (10 + n %% 91) .. "&after=" .. parts[k])
  elseif n %% 2 == 0 then
    i = i %% #parts + 1
    return wrk.format("GET", "/parts/" .. parts[i])
  end
  j = j %% #shapes + 1
  return wrk.format("GET", "/shapes/" .. shapes[j])
end
response = function(status, headers, body)
  if status >= 500 then c5 = c5 + 1 elseif status >= 400 then c4 = c4 + 1 end
  if status >= 400 and first == "" then first = status .. " " .. string.sub(body, 1, 300) end
end
done = function(summary, latency, requests)
  local t4, t5, f = 0, 0, ""
  for _, t in ipairs(threads) do
    t4 = t4 + t:get("c4")
    t5 = t5 + t:get("c5")
    if f == "" then f = t:get("first") end
  end
  io.write(string.format("lua: 4xx %%d 5xx %%d first %%s\\n", t4, t5, f))
end
""" % (",".join(map(str, ids["parts"])), ",".join(map(str, ids["shapes"])))
open(os.path.join(work, "reads.lua"), "w").write(lua)
PY
read -r nparts nshapes < <(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(len(d["parts"]), len(d["shapes"]))' "$work/ids.json")

# The clients: loop.py MODE URL DEADLINE OUT IDS runs MODE until DEADLINE (epoch seconds), one
# request at a time, and writes its counts to OUT (JSON). Each answer is checked: its status and
# the members it must have; a failure's request and answer are kept (the first five).
cat >"$work/loop.py" <<'PY'
import http.client, json, os, random, sys, time, urllib.parse
mode, url, deadline, out, idsfile = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5]
ids = json.load(open(idsfile))
u = urllib.parse.urlsplit(url)
rnd = random.Random(sum(map(ord, mode)))
start = time.time()
st = {"mode": mode, "requests": 0, "2xx": 0, "4xx": 0, "5xx": 0, "other": 0, "conn_errors": 0,
      "bad_answers": 0, "ops": {}, "ms": [], "failures": []}

def fail(what, method, path, body, status, answer, t0):
    if len(st["failures"]) < 5:
        st["failures"].append({"what": what, "at": "%.1f s, after %.0f ms" % (t0 - start, (time.time() - t0) * 1000),
                               "request": "%s %s" % (method, path),
                               "body": json.dumps(body)[:300] if body is not None else None,
                               "status": status, "answer": answer[:400]})

def call(op, method, path, body=None, want=200, keys=()):
    st["requests"] += 1
    st["ops"][op] = st["ops"].get(op, 0) + 1
    t0 = time.time()
    try:
        c = http.client.HTTPConnection(u.hostname, u.port, timeout=120)
        data = json.dumps(body).encode() if body is not None else None
        c.request(method, path, body=data, headers={"Content-Type": "application/json"} if data else {})
        r = c.getresponse()
        status, text = r.status, r.read().decode("utf-8", "replace")
        c.close()
    except (OSError, http.client.HTTPException) as e:
        st["conn_errors"] += 1
        fail("connection", method, path, body, None, repr(e), t0)
        return None
    st["ms"].append((time.time() - t0) * 1000)
    cls = status // 100
    st[{2: "2xx", 4: "4xx", 5: "5xx"}.get(cls, "other")] += 1
    if cls != 2:
        fail("status", method, path, body, status, text, t0)
        return None
    try:
        answer = json.loads(text)
        missing = [k for k in keys if k not in answer]
    except ValueError:
        answer, missing = None, ["(not JSON)"]
    if status != want or missing:
        st["bad_answers"] += 1
        fail("answer: status %d, want %d, missing %s" % (status, want, missing), method, path, body, status, text, t0)
        return None
    return answer

def fz(lo, hi):
    m = rnd.uniform(lo, hi)
    s = rnd.uniform(0.02, 0.1) * m
    return rnd.choice([round(m, 3), {"tri": [round(m - s, 3), round(m, 3), round(m + s, 3)]},
                       {"about": round(m, 3), "spread": round(s, 3)}])

def part_doc(name=None):
    if rnd.random() < 0.2:
        doc = {"text": rnd.choice(["a slightly bent cylinder", "a very twisted box", "a small cone",
                                   "a round sphere", "a very tapered rod"])}
    else:
        doc = {"params": {"eps1": fz(0.3, 2), "eps2": fz(0.3, 2), "a1": fz(0.5, 3), "a2": fz(0.5, 2),
                          "a3": fz(0.5, 2), "kx": round(rnd.uniform(-0.3, 0.3), 3), "kv": {"tri": [0, 0.02, 0.04]},
                          "t": round(rnd.uniform(0, 1), 3)},
               "transform": {"translate": [fz(1, 5), 0, round(rnd.uniform(-2, 2), 3)],
                             "rotate": {"axis": [0, 0, 1], "deg": fz(10, 80)}},
               "descriptors": ["soak"], "meta": {"soak": True}}
    if name: doc["name"] = name
    return doc

ling = ["find a slightly bent shape", "show me something twisted", "find a very round part",
        "find parts with bendness at least 0.3 and twistness at most 0.1", "find a sphere about 3 above a box",
        "find shapes that are not (bent or twisted) and very round at least 0.5", "find a big part",
        "a rod with a round cross-section"]
csg = ["a sphere on top of a cylinder", "a cube minus a cylinder", "a cube with a cylindrical hole",
       "the union of a sphere, a box and a cylinder", "a cone on top of a cylinder on top of a box",
       "a cube and a sphere about 2 units to its right", "the intersection of a very bent cylinder and a box",
       "sphere + (cylinder - cube)"]
created, n = [], 0
while time.time() < deadline:
    n += 1
    if mode == "write":
        r = rnd.random()
        if len(created) < 5 or r < 0.45:
            if len(created) >= 20:
                # One of its own parts goes first, so the catalogue keeps its size: RSS growth is
                # then a leak, not more data (posting alone grew it by 30% in three minutes).
                pid, _ = created.pop(rnd.randrange(len(created)))
                call("delete", "DELETE", "/parts/%d" % pid, None, 200, ("deleted",))
            name = "soak-%d-%d" % (os.getpid(), n)
            a = call("post", "POST", "/parts", part_doc(name), 201, ("id", "version"))
            if a: created.append((a["id"], name))
        elif r < 0.65:
            pid, name = rnd.choice(created)
            call("put", "PUT", "/parts/%d" % pid, part_doc(name if rnd.random() < 0.5 else None), 200, ("id", "version"))
        elif r < 0.8:
            call("put_catalogue", "PUT", "/parts/%d" % rnd.choice(ids["bench_parts"]), part_doc(), 200, ("id", "version"))
        elif len(created) > 20 or r > 0.95:
            pid, _ = created.pop(rnd.randrange(len(created)))
            call("delete", "DELETE", "/parts/%d" % pid, None, 200, ("deleted",))
        else:
            call("get_own", "GET", "/parts/%d" % rnd.choice(created)[0], None, 200, ("document",))
    elif mode == "eval":
        if n % 4:
            call("shape_eval", "POST", "/shapes/%d/evaluate" % rnd.choice(ids["shapes"]),
                 {"resolution": 32, "alphas": [0, 0.5, 1]}, 200, ("alphas", "cached"))
        else:
            a, b = rnd.sample(ids["bench_parts"], 2)
            call("inline_eval", "POST", "/evaluate",
                 {"shape": {"kind": "shape", "tree": {"op": "difference", "children": [{"part": a}, {"part": b}]}},
                  "resolution": 32}, 200, ("alphas", "active_voxels"))
    elif mode == "ling":
        text = ling[n % len(ling)]
        if n % 5 == 0:
            call("query", "POST", "/query", {"text": text, "limit": 10}, 200, ("results", "search"))
        else:
            body = {"text": text, "limit": 10}
            if n % 3 == 0: body["kind"] = rnd.choice(["part", "shape"])
            call("linguistic", "POST", "/query/linguistic", body, 200, ("results", "parsed"))
    elif mode == "csg":
        call("csg", "POST", "/query/csg", {"text": csg[n % len(csg)], "limit": 10}, 200, ("results", "parsed"))
ms = sorted(st.pop("ms"))
st["p50_ms"] = ms[len(ms) // 2] if ms else None
st["p99_ms"] = ms[min(len(ms) - 1, int(len(ms) * 0.99))] if ms else None
st["max_ms"] = ms[-1] if ms else None
json.dump(st, open(out, "w"))
PY

# sample_rss: "epoch_seconds VmRSS_kB" every second while the server lives.
sample_rss() {
  local rss
  while rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$SERVER_PID/status" 2>/dev/null) && [[ -n $rss ]]; do
    echo "$(now) $rss"
    sleep 1
  done
}

# tcp_drops: this host's listen-queue overflows and SYN retransmits so far (/proc/net/netstat):
# a connect the server's accept queue dropped is retried after 1 s, so these explain timeouts.
tcp_drops() {
  python3 -c '
rows = [l.split() for l in open("/proc/net/netstat")]
c = {k: v for i in range(0, len(rows) - 1, 2) if rows[i][0] == "TcpExt:" for k, v in zip(rows[i], rows[i + 1])}
print(c.get("ListenOverflows", 0), c.get("TCPSynRetrans", 0))'
}

# db_mib: the database file and its WAL, in MiB ("DB WAL").
db_mib() { python3 -c 'import os, sys; print(*("%.1f" % (os.path.getsize(f) / 2**20 if os.path.exists(f) else 0) for f in sys.argv[1:]))' "$work/soak.sqlite" "$work/soak.sqlite-wal"; }

server_threads=${threads:-$(python3 -c "import os; print(max(8, os.cpu_count()))")}
echo "== soak: $nparts parts, $nshapes shapes; ${duration}s of wrk -t2 -c64 (reads) and ${#clients[@]} clients" \
  "(${clients[*]}); server threads $server_threads, log warn; warm-up ${warmup}s"
idle_rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$SERVER_PID/status")
db_start=$(db_mib)
tcp_start=$(tcp_drops)
sample_rss >"$work/rss" &
sampler_pid=$!
# run_load SECONDS PREFIX: wrk and the clients for SECONDS; their results in $work/PREFIX*.
run_load() {
  local deadline
  deadline=$(python3 -c "print($(now) + $1)")
  for mode in "${clients[@]}"; do
    python3 "$work/loop.py" "$mode" "$SERVER_URL" "$deadline" "$work/$2loop.$mode.json" "$work/ids.json" \
      2>"$work/$2loop.$mode.err" &
    loop_pids+=($!)
  done
  wrk -t2 -c64 -d"$1s" --latency -s "$work/reads.lua" "$SERVER_URL" >"$work/$2wrk.out" 2>&1 || true
  for p in "${loop_pids[@]}"; do wait "$p" || true; done
  loop_pids=()
}
# The warm-up runs the same load first (caches, SQLite's page caches, the allocator's arenas and
# the evaluation grids fill up there: RSS still rose 20-25 s into a run, and in a three-minute run
# with 20 s of warm-up it rose by 6 MiB in the next 15 s and 5% in the 2.5 minutes after); its answers are
# checked too (below), but the numbers reported are those of the measured run after it.
run_load "$warmup" warm.
t0=$(now)
run_load "$duration" ""
t1=$(now)
end_rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$SERVER_PID/status" 2>/dev/null || echo "")
db_end=$(db_mib)
tcp_end=$(tcp_drops)
kill "$sampler_pid" 2>/dev/null || true
wait "$sampler_pid" 2>/dev/null || true
sampler_pid=
alive=0
kill -0 "$SERVER_PID" 2>/dev/null && alive=1
# A graceful stop (SIGTERM) must exit 0 once the requests in flight are answered.
kill -TERM "$SERVER_PID" 2>/dev/null || true
stop_rc=0
wait "$SERVER_PID" 2>/dev/null || stop_rc=$?
SERVER_PID=

python3 - "$work" "$t0" "$t1" "$warmup" "$idle_rss" "$end_rss" "$alive" "$stop_rc" "$db_start" "$db_end" \
  "$tcp_start" "$tcp_end" "${clients[@]}" <<'PY'
import json, os, re, sys
work, t0, t1, warmup = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
idle_rss, end_rss, alive, stop_rc = sys.argv[5], sys.argv[6], sys.argv[7] == "1", int(sys.argv[8])
db_start, db_end, clients = sys.argv[9], sys.argv[10], sys.argv[13:]
tcp = [int(b) - int(a) for a, b in zip(sys.argv[11].split(), sys.argv[12].split())]
errors = fives = 0

wrk = open(os.path.join(work, "wrk.out")).read()
def ms(label):
    m = re.search(r"^\s*" + label + r"\s+([\d.]+)(us|ms|s)\s*$", wrk, re.M)
    return float(m.group(1)) * {"us": 0.001, "ms": 1, "s": 1000}[m.group(2)] if m else float("nan")
m = re.search(r"^Requests/sec:\s+([\d.]+)", wrk, re.M)
if not m:
    print("wrk failed:\n" + wrk)
    sys.exit(1)
rps = float(m.group(1))
total = int(re.search(r"^\s*(\d+) requests in", wrk, re.M).group(1))
non2xx = int((re.search(r"Non-2xx or 3xx responses:\s+(\d+)", wrk) or [0, 0])[1])
sock = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", wrk)
sock = [int(x) for x in sock.groups()] if sock else [0, 0, 0, 0]
lua = re.search(r"^lua: 4xx (\d+) 5xx (\d+) first ?(.*)$", wrk, re.M)
w4, w5, wfirst = (int(lua.group(1)), int(lua.group(2)), lua.group(3)) if lua else (0, 0, "")
errors += non2xx + sum(sock)
fives += w5
print("reads  wrk -t2 -c64: %d requests, %.0f req/s, p50 %.2f ms, p99 %.2f ms, non-2xx %d (4xx %d, 5xx %d), "
      "socket errors connect %d read %d write %d timeout %d" % (total, rps, ms("50%"), ms("99%"), non2xx, w4, w5, *sock))
if wfirst: print("       first non-2xx answer: " + wfirst)
print("       host TCP during the run: %d listen-queue overflows, %d SYN retransmits" % tuple(tcp))

for mode in clients:
    path = os.path.join(work, "loop.%s.json" % mode)
    if not os.path.exists(path):
        print("%-6s client died: %s" % (mode, open(os.path.join(work, "loop.%s.err" % mode)).read()[-1000:]))
        errors += 1
        continue
    s = json.load(open(path))
    bad = s["4xx"] + s["5xx"] + s["other"] + s["conn_errors"] + s["bad_answers"]
    errors += bad
    fives += s["5xx"]
    ops = " ".join("%s %d" % kv for kv in sorted(s["ops"].items()))
    fmt = lambda v: "%.1f" % v if v is not None else "-"
    print("%-6s %5d requests (%s), p50 %s ms, p99 %s ms, max %s ms; errors %d: 4xx %d, 5xx %d, other %d, "
          "connection %d, bad answers %d" % (mode, s["requests"], ops, fmt(s["p50_ms"]), fmt(s["p99_ms"]),
                                             fmt(s["max_ms"]), bad, s["4xx"], s["5xx"], s["other"], s["conn_errors"],
                                             s["bad_answers"]))
    for f in s["failures"]:
        print("       %s (at %s): %s body %s -> %s %s" % (f["what"], f["at"], f["request"], f["body"], f["status"], f["answer"]))

# The warm-up's answers count as errors too; its rates are not reported.
werr = w5xx = wreq = 0
wwrk = open(os.path.join(work, "warm.wrk.out")).read()
for label in (r"Non-2xx or 3xx responses:\s+(\d+)",):
    werr += sum(int(x) for x in re.findall(label, wwrk))
wsock = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", wwrk)
werr += sum(int(x) for x in wsock.groups()) if wsock else 0
wlua = re.search(r"^lua: 4xx (\d+) 5xx (\d+)", wwrk, re.M)
w5xx += int(wlua.group(2)) if wlua else 0
for mode in clients:
    path = os.path.join(work, "warm.loop.%s.json" % mode)
    if not os.path.exists(path):
        werr += 1
        continue
    w = json.load(open(path))
    wreq += w["requests"]
    werr += w["4xx"] + w["5xx"] + w["other"] + w["conn_errors"] + w["bad_answers"]
    w5xx += w["5xx"]
    for f in w["failures"]:
        print("warm-up %s %s (at %s): %s body %s -> %s %s" % (mode, f["what"], f["at"], f["request"], f["body"], f["status"], f["answer"]))
print("warm-up %.0f s: wrk and %d client requests, errors %d, 5xx %d" % (warmup, wreq, werr, w5xx))
errors += werr
fives += w5xx

rows = [l.split() for l in open(os.path.join(work, "rss")) if len(l.split()) == 2]
samples = [(float(t) - t0, int(kb)) for t, kb in rows if float(t) >= t0]
if end_rss: samples.append((t1 - t0, int(end_rss)))
# One sample swings by up to ~10% with the evaluations in flight (their grids come and go), so the
# warm-up and end values are medians of five samples: those around the end of the warm-up, and the
# last five (the last taken once every client had stopped).
med = lambda xs: sorted(xs)[len(xs) // 2] if xs else None
warm = med([kb for _, kb in samples[:5]])  # the first five seconds after the warm-up
end = med([kb for _, kb in samples[-5:]])
peak = max(kb for _, kb in samples) if samples else None
growth = (end - warm) / warm * 100 if warm and end else float("nan")
mib = lambda kb: "%.1f MiB" % (kb / 1024) if kb else "-"
print("rss    idle %s, after the %.0f s warm-up %s, end (%.0f s later) %s, growth %+.1f%%, peak %s (%d samples; after warm-up and end: medians of 5)"
      % (mib(int(idle_rss)), warmup, mib(warm), t1 - t0, mib(end), growth, mib(peak), len(samples)))
trace = [next((kb for t, kb in samples if t >= (t1 - t0) * k / 10), samples[-1][1]) for k in range(1, 11)] if samples else []
(d0, w0), (d1, w1) = db_start.split(), db_end.split()
print("       every 10%%: %s MiB; database file %s MiB, WAL %s MiB at the start; %s MiB, WAL %s MiB at the end"
      % (" ".join("%.0f" % (kb / 1024) for kb in trace), d0, w0, d1, w1))

log = open(os.path.join(work, "serve.log")).read().splitlines()
noisy = [l for l in log if not l.startswith("listening on")]
print("server %s, stop exit %d, %d log lines at warn or above%s" % (
    "alive at the end" if alive else "DIED during the run", stop_rc, len(noisy), ":" if noisy else ""))
for l in noisy[:10]: print("       " + l[:400])
if not alive or stop_rc != 0: errors += 1
print("soak: errors=%d 5xx=%d rss_growth=%.1f%%" % (errors, fives, growth))
sys.exit(1 if errors or fives or not growth < 10 else 0)
PY
