#!/usr/bin/env bash
# Bulk import rate (docs/s): `fsdb import FILE --db`, `fsdb import FILE --server` (a running
# `fsdb serve`) and, as the baseline, the sqlite3 shell importing the same lines into a comparable
# table (id, unique name, JSON document checked by json()) in one transaction.
# Usage: bench/bench_import.sh [BUILD_DIR] [N]   (default build, 20000); one run each.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
n=${2:-20000}
fsdb="$build/fsdb"
work=$(mktemp -d)
trap 'stop_server; rm -rf "$work"' EXIT

gen_parts "$n" "$work/parts.jsonl"
echo "== bulk import of $n part documents ($(du -h "$work/parts.jsonl" | cut -f1))"

t0=$(now)
"$fsdb" import "$work/parts.jsonl" --db "$work/direct.sqlite" 2>"$work/direct.log" | tail -1
t1=$(now)
direct=$(rate "$n" "$t0" "$t1")

start_server "$work/serve.log" "$fsdb" serve --port 0 --db "$work/served.sqlite"
t0=$(now)
"$fsdb" import "$work/parts.jsonl" --server "$SERVER_URL" 2>"$work/served.log" | tail -1
t1=$(now)
stop_server
served=$(rate "$n" "$t0" "$t1")

# The baseline: the lines into a staging table (.import, tab mode: a line is one field), then
# into a table like fsdb's objects in the same transaction.
t0=$(now)
sqlite3 "$work/shell.sqlite" >/dev/null <<SQL
PRAGMA journal_mode=WAL;
CREATE TABLE objects(id INTEGER PRIMARY KEY AUTOINCREMENT, kind TEXT NOT NULL, name TEXT NOT NULL,
                     document TEXT NOT NULL, created_at TEXT NOT NULL, UNIQUE(kind, name));
BEGIN;
CREATE TEMP TABLE staging(line TEXT);
.mode tabs
.import $work/parts.jsonl staging
INSERT INTO objects(kind, name, document, created_at)
  SELECT json_extract(line, '\$.kind'), json_extract(line, '\$.name'), json(line),
         strftime('%Y-%m-%dT%H:%M:%fZ', 'now') FROM staging;
COMMIT;
SQL
t1=$(now)
rows=$(sqlite3 "$work/shell.sqlite" 'SELECT count(*) FROM objects')
[[ $rows == "$n" ]] || { echo "sqlite3 baseline imported $rows rows, expected $n" >&2; exit 1; }
shell=$(rate "$n" "$t0" "$t1")

echo "fsdb import --db:     $direct docs/s"
echo "fsdb import --server: $served docs/s"
echo "sqlite3 shell:        $shell docs/s"
python3 -c "print('ratios: sqlite3 / --db = %.1f, sqlite3 / --server = %.1f' % ($shell / $direct, $shell / $served))"
