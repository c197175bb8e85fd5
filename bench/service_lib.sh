# Helpers shared by the service benchmarks (sourced, not run).

# now: seconds since the epoch with nanoseconds.
now() { date +%s.%N; }

# rate COUNT START END: COUNT / (END - START), rounded.
rate() { python3 -c "import sys; print(round($1 / ($3 - $2)))"; }

# start_server LOG CMD...: starts CMD (which prints "listening on http://H:P" first on stdout) in
# the background; sets SERVER_PID and SERVER_URL. The server's stdout and stderr go to LOG.
start_server() {
  local log=$1
  shift
  "$@" >"$log" 2>&1 &
  SERVER_PID=$!
  SERVER_URL=
  for _ in $(seq 1 200); do
    SERVER_URL=$(sed -n 's/^listening on \(http:[^ ]*\).*/\1/p' "$log" | head -1)
    [[ -n $SERVER_URL ]] && return 0
    kill -0 "$SERVER_PID" 2>/dev/null || break
    sleep 0.05
  done
  echo "server did not start: $*" >&2
  cat "$log" >&2
  return 1
}

# stop_server: SIGTERM to the server started last (graceful stop), then wait for it.
stop_server() {
  [[ -n ${SERVER_PID:-} ]] || return 0
  kill -TERM "$SERVER_PID" 2>/dev/null || true
  wait "$SERVER_PID" 2>/dev/null || true
  SERVER_PID=
}

# gen_parts N FILE: N part documents as JSON Lines, names part-000001..., every fuzzy number form.
gen_parts() {
  python3 - "$1" "$2" <<'PY'
import json, random, sys
n, path = int(sys.argv[1]), sys.argv[2]
rnd = random.Random(4)
def fuzzy(lo, hi):
    m = rnd.uniform(lo, hi)
    s = rnd.uniform(0.01, 0.1) * m
    form = rnd.randrange(5)
    if form == 0: return round(m, 4)
    if form == 1: return {"tri": [round(m - s, 4), round(m, 4), round(m + s, 4)]}
    if form == 2: return {"trap": [round(m - s, 4), round(m - s / 2, 4), round(m + s / 2, 4), round(m + s, 4)]}
    if form == 3: return {"about": round(m, 4), "spread": round(s, 4)}
    return {"points": [[round(m - s, 4), 0], [round(m, 4), 1], [round(m + s, 4), 0]]}
with open(path, "w") as out:
    for i in range(1, n + 1):
        doc = {"kind": "part", "name": "part-%06d" % i,
               "descriptors": rnd.sample(["round", "slightly bent", "long", "flat", "thin", "boxy"], 2),
               "params": {"eps1": fuzzy(0.3, 2.0), "eps2": fuzzy(0.3, 2.0), "a1": fuzzy(0.5, 3.0),
                          "a2": fuzzy(0.5, 2.0), "a3": fuzzy(0.5, 2.0), "kx": round(rnd.uniform(-0.3, 0.3), 3),
                          "ky": 0, "kv": {"tri": [0.0, 0.02, 0.04]}, "t": 0},
               "transform": {"translate": [fuzzy(1, 5), 0, round(rnd.uniform(-2, 2), 3)],
                             "rotate": {"axis": [0, 0, 1], "deg": fuzzy(10, 80)}, "scale": 1},
               "meta": {"batch": i // 1000}}
        out.write(json.dumps(doc, separators=(",", ":")) + "\n")
PY
}
