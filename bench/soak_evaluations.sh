#!/usr/bin/env bash
# Soak of concurrent evaluations under the memory budget: `fsdb serve --max-memory-mb BUDGET
# --max-eval-ms 0` gets ROUNDS rounds of 16 evaluations sent at once (a part fuzzy in two sizes,
# RESOLUTION voxels across: about 160 MiB of grid each at 384, so 16 need twice the budget),
# while a probe asks GET /health every 0.2 s. The server's VmRSS is sampled every 0.2 s.
# Checks (exit 1 on any): every evaluation is answered 200 or 503 `overloaded` with Retry-After
# (no other status, no connection error); at least one per round is 200 (the oldest finish); the
# peak RSS stays under the budget plus the idle RSS plus 25 % of the budget (grid overhead the
# leaf accounting does not see); the RSS 20 s after the load is back within 150 MiB of the idle
# RSS (memory is given back); every /health probe is answered, within 1 s.
# Before the budget, 16 evaluations at 512 reached 8.2 GB and were still rising, and the server
# kept 3.8 GB afterwards.
# Usage: bench/soak_evaluations.sh [BUILD_DIR]   (SOAK_EVAL_BUDGET_MB=1024, SOAK_EVAL_RESOLUTION=384,
#        SOAK_EVAL_ROUNDS=2)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
budget=${SOAK_EVAL_BUDGET_MB:-1024}
resolution=${SOAK_EVAL_RESOLUTION:-384}
rounds=${SOAK_EVAL_ROUNDS:-2}
work=$(mktemp -d)
sampler_pid=
cleanup() {
  [[ -n $sampler_pid ]] && kill "$sampler_pid" 2>/dev/null || true
  stop_server
  rm -rf "$work"
}
trap cleanup EXIT

start_server "$work/serve.log" "$build/fsdb" --log-level warn serve --port 0 --db "$work/e.sqlite" \
  --max-eval-ms 0 --max-memory-mb "$budget"
sleep 1
idle=$(awk '/VmRSS/{print $2}' "/proc/$SERVER_PID/status")
( while kill -0 "$SERVER_PID" 2>/dev/null; do
    awk '/VmRSS/{print $2}' "/proc/$SERVER_PID/status" 2>/dev/null >> "$work/rss" || true
    sleep 0.2
  done ) &
sampler_pid=$!

python3 - "$SERVER_URL" "$resolution" "$rounds" "$work/load.json" <<'PY'
import json, sys, threading, time, urllib.request, urllib.error
url, resolution, rounds, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
body = json.dumps({"shape": {"kind": "part", "params": {"a1": {"tri": [0.8, 1, 1.2]}, "a2": {"tri": [0.8, 1, 1.2]}}},
                   "resolution": resolution}).encode()
answers, probes, done = [], [], threading.Event()

def evaluate():
    req = urllib.request.Request(url + "/evaluate", data=body, headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(req, timeout=600) as r:
            answers.append({"status": r.status, "code": "", "retry": ""})
    except urllib.error.HTTPError as e:
        code = ""
        try: code = json.loads(e.read())["error"]["code"]
        except Exception: pass
        answers.append({"status": e.code, "code": code, "retry": e.headers.get("Retry-After", "")})
    except Exception as e:
        answers.append({"status": 0, "code": str(e)[:200], "retry": ""})

def probe():
    while not done.is_set():
        t = time.time()
        try:
            with urllib.request.urlopen(url + "/health", timeout=10) as r: ok = r.status == 200
        except Exception: ok = False
        probes.append((ok, time.time() - t))
        time.sleep(0.2)

p = threading.Thread(target=probe); p.start()
per_round, t0 = [], time.time()
for _ in range(rounds):
    before = len(answers)
    threads = [threading.Thread(target=evaluate) for _ in range(16)]
    for t in threads: t.start()
    for t in threads: t.join()
    per_round.append(sum(1 for a in answers[before:] if a["status"] == 200))
done.set(); p.join()
json.dump({"answers": answers, "per_round": per_round, "seconds": time.time() - t0,
           "probes": len(probes), "probe_failures": sum(1 for ok, _ in probes if not ok),
           "probe_max_s": max((s for _, s in probes), default=0)}, open(out, "w"))
PY
sleep 20
after=$(awk '/VmRSS/{print $2}' "/proc/$SERVER_PID/status")
kill "$sampler_pid" 2>/dev/null || true
sampler_pid=

python3 - "$work" "$idle" "$after" "$budget" <<'PY'
import json, os, sys
work, idle, after, budget = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
s = json.load(open(os.path.join(work, "load.json")))
rss = [int(l) for l in open(os.path.join(work, "rss")) if l.strip()]
peak = max(rss) if rss else 0
errors = []
statuses = {}
for a in s["answers"]:
    key = "%d %s" % (a["status"], a["code"])
    statuses[key] = statuses.get(key, 0) + 1
    if a["status"] == 200: continue
    if a["status"] == 503 and a["code"] == "overloaded" and a["retry"]: continue
    errors.append("answer %s" % a)
if any(n == 0 for n in s["per_round"]): errors.append("a round with no evaluation answered 200: %s" % s["per_round"])
limit_kb = idle + budget * 1024 * 1.25
if peak > limit_kb: errors.append("peak RSS %.0f MiB over %.0f MiB" % (peak / 1024, limit_kb / 1024))
if after > idle + 150 * 1024: errors.append("RSS 20 s after the load %.0f MiB, idle %.0f MiB" % (after / 1024, idle / 1024))
if s["probe_failures"] or s["probe_max_s"] > 1.0:
    errors.append("/health: %d of %d probes failed, slowest %.2f s" % (s["probe_failures"], s["probes"], s["probe_max_s"]))
print("evaluations: %d rounds of 16 in %.0f s: %s; 200s per round %s" % (
    len(s["per_round"]), s["seconds"], ", ".join("%s x%d" % kv for kv in sorted(statuses.items())), s["per_round"]))
print("rss: idle %.0f MiB, peak %.0f MiB (budget %d MiB), 20 s after %.0f MiB; /health %d probes, slowest %.3f s" % (
    idle / 1024, peak / 1024, budget, after / 1024, s["probes"], s["probe_max_s"]))
for e in errors[:10]: print("  " + e)
print("soak_evaluations: errors=%d" % len(errors))
sys.exit(1 if errors else 0)
PY
