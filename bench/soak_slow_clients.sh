#!/usr/bin/env bash
# Soak of slow clients: `fsdb serve` (default workers) while CLIENTS connections each send a
# request a byte a second for DURATION seconds, half of them its headers (a 4 KB header: none
# ends), half a POST's body after a whole head (Content-Length 100000), and a normal
# client asks GET /health every 0.1 s on a new connection. Reports the normal client's p50, p99
# and slowest answer and the server's open connections; exit 1 when a normal request fails or its
# p99 reaches 100 ms. Before the connection front (server/http/connection_front.h), when workers
# read requests themselves, 16 such clients left /health unanswered (1 of 20 probes answered),
# and 200 did with 32 workers.
# Usage: bench/soak_slow_clients.sh [BUILD_DIR] [CLIENTS] [DURATION_S]   (default build, 200, 30)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
clients=${2:-200}
duration=${3:-30}
work=$(mktemp -d)
cleanup() {
  stop_server
  rm -rf "$work"
}
trap cleanup EXIT
start_server "$work/serve.log" "$build/fsdb" --log-level warn serve --port 0 --db "$work/s.sqlite"
port=${SERVER_URL##*:}
python3 - "$port" "$clients" "$duration" "$SERVER_URL" <<'PY'
import socket, sys, threading, time, urllib.request
port, n, duration, url = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
heads = [b"GET /health HTTP/1.1\r\nHost: x\r\nX-Slow: " + b"a" * 4000 + b"\r\n\r\n",
         b"POST /query HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 100000\r\n\r\n"]
stop = time.time() + duration + 2
def slow(k):
    slowly = heads[0] if k % 2 == 0 else b" " * 100000
    while time.time() < stop:
        try:
            s = socket.create_connection(("127.0.0.1", port), timeout=5)
            if k % 2: s.sendall(heads[1])  # the head at once, then the body a byte a second
            for i in range(len(slowly)):
                if time.time() >= stop: break
                s.sendall(slowly[i:i + 1]); time.sleep(1)
            s.close()
        except Exception:
            time.sleep(0.2)
for k in range(n): threading.Thread(target=slow, args=(k,), daemon=True).start()
time.sleep(2)
lat, fails = [], []
while time.time() < stop:
    t = time.time()
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=5)
        s.settimeout(5)
        s.sendall(b"GET /health HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        d = b""
        while True:
            c = s.recv(4096)
            if not c: break
            d += c
        s.close()
        if d.startswith(b"HTTP/1.1 200"): lat.append(time.time() - t)
        else: fails.append(d[:80])
    except Exception as e:
        fails.append(str(e))
    time.sleep(0.1)
conns = ""
try:
    metrics = urllib.request.urlopen(url + "/metrics", timeout=5).read().decode()
    conns = next((l.split()[1] for l in metrics.splitlines() if l.startswith("fsdb_http_connections_open ")), "?")
except Exception as e:
    fails.append("metrics: %s" % e)
lat.sort()
q = lambda p: lat[min(len(lat) - 1, int(p * len(lat)))] * 1000 if lat else float("inf")
p99 = q(.99)
print("slow clients %d for %.0f s: normal requests %d answered, %d failed; p50 %.1f ms, p99 %.1f ms, slowest %.1f ms; "
      "open connections at the end %s" % (n, duration, len(lat), len(fails), q(.5), p99, lat[-1] * 1000 if lat else float("inf"), conns))
for f in fails[:5]: print("  failed: %s" % f)
ok = not fails and p99 < 100
print("soak_slow_clients: %s" % ("ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
PY
