#!/usr/bin/env python3
"""Round trips of parts made from words (docs/performance.md, "Search quality").

For every noun with geometry, adjective and intensity of the server's vocabulary (GET
/vocabulary), in a catalogue of the demo objects: make a part from "a [intensity] adjective
noun" (POST /parts), search the same words (POST /query), and count it a round trip when that
part ranks first (ties broken against it: an object of the same score listed before it fails)
with a score of at least 0.9. Texts the server refuses to make are counted apart.

  bench/round_trip.py --fsdb build/fsdb [--sample N] [--seed S] [--show-failures K]
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def call(base, method, path, body=None):
    data = None if body is None else json.dumps(body).encode()
    req = urllib.request.Request(base + path, data=data, method=method, headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(req) as r:
            return r.status, json.loads(r.read() or b"null")
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"null")


def start(fsdb, folder):
    p = subprocess.Popen([fsdb, "--log-level", "warn", "serve", "--port", "0", "--db", os.path.join(folder, "db.sqlite"),
                          "--demo", os.path.join(ROOT, "schema/demo")], stdout=subprocess.PIPE, text=True)
    for line in p.stdout:
        if "listening on" in line:
            return p, line.split("listening on ")[1].split()[0]
    raise SystemExit("fsdb serve did not start")


def texts(vocabulary):
    nouns = [n for n, e in vocabulary["nouns"].items()
             if e.get("same_as") or e.get("params") is not None]
    adjectives = sorted(vocabulary["adjectives"])
    intensities = [""] + list(vocabulary["intensities"]["order"])
    for noun in sorted(nouns):
        for adjective in adjectives:
            for intensity in intensities:
                yield " ".join(w for w in ("a", intensity, adjective, noun) if w), intensity != ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--fsdb", default=os.path.join(ROOT, "build/fsdb"))
    ap.add_argument("--sample", type=int, default=0, help="this many texts at random (0: all)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--show-failures", type=int, default=0)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        server, base = start(args.fsdb, folder)
        try:
            _, vocabulary = call(base, "GET", "/vocabulary")
            all_texts = list(texts(vocabulary))
            if args.sample:
                random.Random(args.seed).shuffle(all_texts)
                all_texts = all_texts[:args.sample]
            made = passed = first = 0
            refused = 0
            failures = []
            groups = {True: [0, 0], False: [0, 0]}  # with an intensity or plain: [made, round trips]
            started = time.time()
            for i, (text, intense) in enumerate(all_texts):
                status, part = call(base, "POST", "/parts", {"name": "rt%d" % i, "text": text})
                if status != 201 and status != 200:
                    refused += 1
                    continue
                made += 1
                groups[intense][0] += 1
                status, answer = call(base, "POST", "/query", {"text": text, "limit": 100})
                results = answer.get("results", []) if status == 200 else []
                own = next((k for k, r in enumerate(results) if r.get("id") == part["id"]), None)
                score = results[own]["score"] if own is not None else 0.0
                if own == 0:
                    first += 1
                if own == 0 and score >= 0.9:
                    passed += 1
                    groups[intense][1] += 1
                else:
                    failures.append((text, own, round(score, 3),
                                     [(r.get("name"), round(r.get("score", 0), 3)) for r in results[:2]]))
                call(base, "DELETE", "/parts/%d" % part["id"])
            print(json.dumps({"texts": len(all_texts), "made": made, "refused": refused, "first": first,
                              "round_trips": passed, "share": round(passed / max(made, 1), 4),
                              "with_intensity": "%d of %d" % (groups[True][1], groups[True][0]),
                              "plain": "%d of %d" % (groups[False][1], groups[False][0]),
                              "seconds": round(time.time() - started, 1)}))
            for f in failures[:args.show_failures]:
                print(f)
        finally:
            server.terminate()
            server.wait()


if __name__ == "__main__":
    main()
