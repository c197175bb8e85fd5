#!/usr/bin/env bash
# Bulk import rate (docs/s): `fsdb import FILE --db` (default --batch, and --batch 500),
# `fsdb import FILE --server` (a running `fsdb serve`) and, as the baseline, the sqlite3 shell
# importing the same lines into a comparable table (id, unique name, JSON document checked by
# json()) in one transaction. A second reference: the sqlite3 shell writing the rows fsdb itself
# stores for these lines (objects, versions, descriptor index and values, change log: copied from
# an fsdb import into an empty fsdb database, with fsdb's pragmas, in one transaction), which is
# what the engine alone needs for fsdb's rows and indexes. Each is run REPS times, alternating;
# medians and ratios of medians.
# Usage: bench/bench_import.sh [BUILD_DIR] [N] [REPS]   (default build, 20000, 3)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/service_lib.sh"
build=$(cd "${1:-build}" && pwd)
n=${2:-20000}
reps=${3:-3}
fsdb="$build/fsdb"
work=$(mktemp -d)
trap 'stop_server; rm -rf "$work"' EXIT

gen_parts "$n" "$work/parts.jsonl"
echo "== bulk import of $n part documents ($(du -h "$work/parts.jsonl" | cut -f1)), $reps runs each"

# timed NAME CMD...: runs CMD (after removing the databases), appends its rate to $work/NAME.
timed() {
  local name=$1
  shift
  rm -f "$work"/*.sqlite*
  local t0 t1
  t0=$(now)
  "$@" >"$work/$name.out" 2>"$work/$name.log"
  t1=$(now)
  grep -q "^imported $n, failed 0" "$work/$name.out" || { echo "$name: $(cat "$work/$name.out")" >&2; exit 1; }
  rate "$n" "$t0" "$t1" >>"$work/$name.rates"
}

shell_import() {
  # The lines into a staging table (.import, tab mode: a line is one field), then into a table
  # like fsdb's objects in the same transaction.
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
  echo "imported $(sqlite3 "$work/shell.sqlite" 'SELECT count(*) FROM objects'), failed 0"
}

# The rows fsdb stores for these lines (an untimed import), and an empty database of fsdb's
# schema to copy them into; kept apart from the databases `timed` removes.
mkdir -p "$work/keep"
"$fsdb" import "$work/parts.jsonl" --db "$work/keep/rows.sqlite" >/dev/null 2>&1
"$fsdb" import /dev/null --db "$work/keep/empty.sqlite" >/dev/null 2>&1

engine_copy() {
  cp "$work/keep/empty.sqlite" "$work/engine.sqlite"
  sqlite3 "$work/engine.sqlite" >/dev/null <<SQL
PRAGMA journal_mode=WAL;
PRAGMA foreign_keys=ON;
PRAGMA synchronous=NORMAL;
PRAGMA cache_size=-65536;
PRAGMA temp_store=MEMORY;
ATTACH '$work/keep/rows.sqlite' AS src;
BEGIN;
INSERT INTO objects SELECT * FROM src.objects ORDER BY id;
INSERT INTO versions SELECT * FROM src.versions ORDER BY object_id, version;
INSERT INTO descriptor_classes SELECT * FROM src.descriptor_classes;
INSERT INTO descriptor_index SELECT * FROM src.descriptor_index ORDER BY object_id, component, descriptor;
INSERT INTO descriptor_values SELECT * FROM src.descriptor_values ORDER BY object_id, component;
INSERT INTO change_log SELECT * FROM src.change_log ORDER BY seq;
COMMIT;
SQL
  echo "imported $(sqlite3 "$work/engine.sqlite" 'SELECT count(*) FROM objects'), failed 0"
}

served_import() {
  start_server "$work/serve.log" "$fsdb" --log-level warn serve --port 0 --db "$work/served.sqlite"
  "$fsdb" import "$work/parts.jsonl" --server "$SERVER_URL" "$@"
  stop_server
}

for _ in $(seq 1 "$reps"); do
  timed direct "$fsdb" import "$work/parts.jsonl" --db "$work/direct.sqlite"
  timed direct500 "$fsdb" import "$work/parts.jsonl" --db "$work/direct.sqlite" --batch 500
  timed served served_import
  timed shell shell_import
  timed engine engine_copy
done

median() { sort -n "$work/$1.rates" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
shell=$(median shell)
report() {
  local m
  m=$(median "$1")
  printf '%-36s %7s docs/s (median; runs: %s)   %.3fx the sqlite3 shell\n' "$2" "$m" \
    "$(paste -sd' ' "$work/$1.rates")" "$(python3 -c "print($m / $shell)")"
}
report direct "fsdb import --db"
report direct500 "fsdb import --db --batch 500"
report served "fsdb import --server"
printf '%-36s %7s docs/s (median; runs: %s)\n' "sqlite3 shell" "$shell" "$(paste -sd' ' "$work/shell.rates")"
engine=$(median engine)
printf '%-36s %7s docs/s (median; runs: %s)   fsdb import --db is %.3fx this\n' "sqlite3 shell, fsdb's own rows" "$engine" \
  "$(paste -sd' ' "$work/engine.rates")" "$(python3 -c "print($(median direct) / $engine)")"
