#!/usr/bin/env bash
# SQLite against PostgreSQL (bench/bench_backends.cpp) on a throwaway PostgreSQL cluster
# (scripts/pg-test-cluster), stopped afterwards whatever happens.
#   bench/bench_backends.sh BUILD_DIR [bench_backends arguments: --parts N --trees M --reps R ...]
set -euo pipefail
build=${1:?usage: bench/bench_backends.sh BUILD_DIR [arguments]}
shift
here=$(cd "$(dirname "$0")/.." && pwd)
cluster=$(mktemp -d /tmp/fsdb-bench-pg.XXXXXX)
trap '"$here/scripts/pg-test-cluster" stop "$cluster"' EXIT
# fsync on: PostgreSQL as durable as the SQLite file (WAL, synchronous=NORMAL): neither waits for
# the disk at each commit, both survive a crash of the process.
url=$(FSDB_PG_FSYNC=on "$here/scripts/pg-test-cluster" start "$cluster")
"$build/bench/bench_backends" --postgres "$url" --dir "$build/bench-data" "$@"
