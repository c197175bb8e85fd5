#!/usr/bin/env python3
"""Rank quality of fsdb's search box (POST /query) on the phrasings of bench/query_corpus/.

    python3 bench/query_rank.py --fsdb build/fsdb [--heldout] [--second] [--show-failures] [--json OUT]

Starts `fsdb serve` on a free loopback port with a fresh SQLite file, imports
bench/query_corpus/catalogue/{parts,shapes}.jsonl, waits for /health, runs every phrasing of
dev.jsonl (and, with --heldout, of heldout.jsonl, reported apart) as
POST /query {"text": ..., "limit": 10}, stops the server and prints, per writer kind and overall:
count, RR@1, RR@5, NDCG@5 and the number of non-200 answers.

Results are mapped to catalogue objects by name. Grades: 3 = what the writer means, 2 = a good
answer, 1 = acceptable, anything else 0. RR@1 is 1 when the first result has grade 3; RR@5 is
1/rank of the first grade-3 result within the top 5 (else 0); NDCG@5 uses gain 2^grade - 1 and a
log2(rank + 1) discount, normalised by the best ordering of the phrasing's graded objects. A
non-200 answer counts as an empty result list. The numbers are a measurement, not a gate: the
exit status is 0 whenever the benchmark ran (2 when the server could not be started or the
catalogue not imported). heldout.jsonl is reported only as aggregates; see
bench/query_corpus/README.md for the rule about it. --second runs the second corpus, written
later the same way (dev2.jsonl, and with --heldout heldout2.jsonl, aggregates only too).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections import Counter, OrderedDict

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "query_corpus")
sys.dont_write_bytecode = True  # leave no __pycache__ in the client's folder
sys.path.insert(0, os.path.join(HERE, os.pardir, "clients", "python"))
from fsdb import Client, FsdbError  # noqa: E402  (standard library only)

WRITERS = ["engineer", "designer", "child", "nonnative", "hurry"]
LIMIT = 10
K = 5


def load_jsonl(path):
    items = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line:
                continue
            try:
                items.append(json.loads(line))
            except ValueError as e:
                raise SystemExit(f"{path}:{number}: not JSON: {e}")
    return items


# ---------------------------------------------------------------- the server

class Server:
    """`fsdb serve` on 127.0.0.1, port 0 (the server picks a free one), fresh SQLite file."""

    def __init__(self, binary, workdir):
        self.binary = binary
        self.workdir = workdir
        self.log_path = os.path.join(workdir, "server.log")
        self.proc = None
        self.url = None

    def start(self, timeout=30.0):
        db = os.path.join(self.workdir, "rank.sqlite")
        cmd = [self.binary, "serve", "--host", "127.0.0.1", "--port", "0", "--db", db]
        self._log = open(self.log_path, "wb")
        self.proc = subprocess.Popen(cmd, stdout=self._log, stderr=subprocess.STDOUT,
                                     stdin=subprocess.DEVNULL)
        deadline = time.monotonic() + timeout
        pattern = re.compile(rb"^listening on (http://\S+)", re.M)
        while time.monotonic() < deadline:
            with open(self.log_path, "rb") as f:
                m = pattern.search(f.read())
            if m:
                self.url = m.group(1).decode()
                return self.url
            if self.proc.poll() is not None:
                break
            time.sleep(0.05)
        raise RuntimeError("fsdb serve did not start:\n" + self.log_tail())

    def log_tail(self, lines=20):
        try:
            with open(self.log_path, "rb") as f:
                return "\n".join(f.read().decode("utf-8", "replace").splitlines()[-lines:])
        except OSError:
            return ""

    def stop(self):
        if self.proc is None or self.proc.poll() is not None:
            return
        self.proc.send_signal(signal.SIGTERM)
        try:
            self.proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self._log.close()


def wait_healthy(client, parts, shapes, timeout=30.0):
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        try:
            last = client.health()
            if last.get("status") == "ok" and last.get("parts") == parts and last.get("shapes") == shapes:
                return last
        except FsdbError as e:
            last = str(e)
        time.sleep(0.1)
    raise RuntimeError(f"server not healthy with {parts} parts and {shapes} shapes: {last}")


def import_catalogue(client, descriptions=True):
    parts = load_jsonl(os.path.join(CORPUS, "catalogue", "parts.jsonl"))
    shapes = load_jsonl(os.path.join(CORPUS, "catalogue", "shapes.jsonl"))
    if not descriptions:
        # The catalogue's descriptions were written by the corpus's author, in words close to the
        # phrasings: without them the numbers say what the geometry and the names find.
        for d in parts + shapes:
            d.pop("meta", None)
            d.pop("descriptors", None)
    for collection, docs in ((client.parts, parts), (client.shapes, shapes)):
        answer = collection.bulk(docs)
        if answer.get("failed") or answer.get("imported") != len(docs):
            raise RuntimeError(f"import of {collection.kind}s failed: "
                               + json.dumps(answer.get("errors", answer))[:2000])
    names = [d["name"] for d in parts + shapes]
    if len(set(names)) != len(names):
        raise RuntimeError("catalogue names are not unique")
    return parts, shapes, set(names)


# ---------------------------------------------------------------- the measures

def rr_at(grades, k):
    for rank, g in enumerate(grades[:k], 1):
        if g == 3:
            return 1.0 / rank
    return 0.0


def dcg(grades):
    return sum((2 ** g - 1) / math.log2(rank + 1) for rank, g in enumerate(grades, 1))


def ndcg_at(grades, ideal, k):
    best = dcg(sorted(ideal, reverse=True)[:k])
    return dcg(grades[:k]) / best if best > 0 else 0.0


def score_phrasing(client, item, catalogue_names):
    relevant = item["relevant"]
    status, code, names, search, read = 200, "", [], None, None
    try:
        answer = client.query(item["text"], limit=LIMIT)
        names = [r.get("name") for r in answer.get("results", [])]
        search = answer.get("search")
        read = answer.get("read_text") or (answer.get("parsed") or {}).get("read_as")
    except FsdbError as e:
        status, code = e.status, e.code or "unknown"
        read = e.message
    # each object counts once, at its first rank (a repeated name gains nothing more)
    grades, seen = [], set()
    for n in names:
        grades.append(relevant.get(n, 0) if n not in seen else 0)
        seen.add(n)
    unknown = [n for n in names if n not in catalogue_names]
    return {
        "id": item["id"], "writer": item["writer"], "status": status, "code": code,
        "search": search, "read": read, "names": names, "unknown_names": unknown,
        "rr1": 1.0 if grades[:1] == [3] else 0.0,
        "rr5": rr_at(grades, K),
        "ndcg5": ndcg_at(grades, list(relevant.values()), K),
    }


def aggregate(rows):
    table = OrderedDict()
    for writer in WRITERS + ["overall"]:
        sel = [r for r in rows if writer == "overall" or r["writer"] == writer]
        n = len(sel)
        errors = Counter(f'{r["status"]} {r["code"]}' for r in sel if r["status"] != 200)
        table[writer] = OrderedDict([
            ("count", n),
            ("rr1", round(sum(r["rr1"] for r in sel) / n, 4) if n else None),
            ("rr5", round(sum(r["rr5"] for r in sel) / n, 4) if n else None),
            ("ndcg5", round(sum(r["ndcg5"] for r in sel) / n, 4) if n else None),
            ("non200", sum(errors.values())),
            ("errors", dict(errors)),
        ])
    return table


def print_table(title, table):
    print(f"\n{title}")
    print(f"  {'writer':<10} {'count':>5} {'RR@1':>6} {'RR@5':>6} {'NDCG@5':>7} {'non-200':>8}")
    for writer, row in table.items():
        if writer == "overall":
            print("  " + "-" * 46)
        fmt = lambda v: "    -" if v is None else f"{v:.3f}"
        print(f"  {writer:<10} {row['count']:>5} {fmt(row['rr1']):>6} {fmt(row['rr5']):>6} "
              f"{fmt(row['ndcg5']):>7} {row['non200']:>8}")
    errors = table["overall"]["errors"]
    if errors:
        print("  non-200 answers: " + ", ".join(f"{k} x{v}" for k, v in sorted(errors.items())))


def print_failures(items, rows):
    by_id = {it["id"]: it for it in items}
    failures = [r for r in rows if r["rr1"] == 0]
    print(f"\ndev failures (RR@1 = 0): {len(failures)} of {len(rows)}")
    for r in failures:
        it = by_id[r["id"]]
        want = ", ".join(sorted(n for n, g in it["relevant"].items() if g == 3))
        if r["status"] != 200:
            got = f'error {r["status"]} {r["code"]}'
        elif not r["names"]:
            got = "no results"
        else:
            got = ", ".join(
                f'{n}({it["relevant"].get(n, 0)})' for n in r["names"][:3])
        print(f'  {r["id"]:<8} "{it["text"]}"')
        print(f'           want: {want}')
        print(f'           got:  {got}' + (f'   [{r["search"]}]' if r["search"] else ""))
        if r["read"]:
            read = r["read"] if len(r["read"]) <= 160 else r["read"][:157] + "..."
            print(f'           read: {read}')


# ---------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fsdb", required=True, help="the fsdb binary (e.g. build/fsdb)")
    ap.add_argument("--heldout", action="store_true",
                    help="also run heldout.jsonl and report it separately (aggregates only)")
    ap.add_argument("--second", action="store_true",
                    help="also run the second corpus: dev2.jsonl, and with --heldout heldout2.jsonl")
    ap.add_argument("--show-failures", action="store_true",
                    help="list dev phrasings whose RR@1 is 0, with the top 3 names they got")
    ap.add_argument("--json", metavar="OUT", help="also write the table as JSON to OUT")
    ap.add_argument("--no-descriptions", action="store_true",
                    help="import the catalogue without meta and descriptors (no search by description)")
    args = ap.parse_args()

    binary = os.path.abspath(args.fsdb)
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        print(f"query_rank: not an executable: {args.fsdb}", file=sys.stderr)
        return 2

    splits = [("dev", load_jsonl(os.path.join(CORPUS, "dev.jsonl")))]
    if args.heldout:
        splits.append(("heldout", load_jsonl(os.path.join(CORPUS, "heldout.jsonl"))))
    if args.second:
        splits.append(("dev2", load_jsonl(os.path.join(CORPUS, "dev2.jsonl"))))
        if args.heldout:
            splits.append(("heldout2", load_jsonl(os.path.join(CORPUS, "heldout2.jsonl"))))

    workdir = tempfile.mkdtemp(prefix="fsdb-query-rank-")
    server = Server(binary, workdir)
    results = OrderedDict()
    try:
        try:
            url = server.start()
            client = Client(url, timeout=120)
            parts, shapes, names = import_catalogue(client, not args.no_descriptions)
            health = wait_healthy(client, len(parts), len(shapes))
        except (RuntimeError, FsdbError) as e:
            print(f"query_rank: {e}", file=sys.stderr)
            tail = server.log_tail()
            if tail:
                print(tail, file=sys.stderr)
            return 2
        print(f"fsdb {health.get('version')} at {url}: {len(parts)} parts, {len(shapes)} shapes")
        for split, items in splits:
            started = time.monotonic()
            rows = [score_phrasing(client, it, names) for it in items]
            results[split] = (items, rows, time.monotonic() - started)
    finally:
        server.stop()
        shutil.rmtree(workdir, ignore_errors=True)

    out = OrderedDict([("fsdb", binary), ("catalogue", {"parts": len(parts), "shapes": len(shapes)}),
                       ("limit", LIMIT), ("k", K)])
    for split, (items, rows, seconds) in results.items():
        table = aggregate(rows)
        title = {"heldout": "held-out", "heldout2": "held-out (second)", "dev2": "dev (second)"}.get(split, split)
        print_table(f"{title}: {len(rows)} phrasings, {seconds:.1f} s", table)
        out[split] = table
        unknown = sorted({n for r in rows for n in r["unknown_names"]})
        if unknown:
            print(f"  note: results named objects outside the catalogue: {', '.join(unknown)}")
    if args.show_failures:
        for split in ("dev", "dev2"):
            if split in results:
                items, rows, _ = results[split]
                print_failures(items, rows)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(out, f, indent=2)
            f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
