# fsdb: the two commands a fresh machine needs are `make serve` and `make test` (see README).
BUILD ?= build
JOBS ?= 2
HOST ?= 127.0.0.1
PORT ?= 8080

SANITIZE_BUILD ?= build-sanitize
FUZZ_SECONDS ?= 60

.PHONY: deps configure build serve test bench soak clean sanitize-build test-sanitize fuzz

deps:
	scripts/install-deps

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j$(JOBS)

serve: build
	mkdir -p data
	$(BUILD)/fsdb serve --host $(HOST) --port $(PORT) --db data/fsdb.sqlite --demo schema/demo --warm-thumbnails

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)

# The suite again under AddressSanitizer and UndefinedBehaviorSanitizer (clang), with the fuzz
# targets' regression inputs; the PostgreSQL reruns of the server suites are left out (the same
# code as their SQLite runs; the db/ suites still run on both backends).
sanitize-build: deps
	CC=clang CXX=clang++ cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DFSDB_FUZZ=ON -DFSDB_BUILD_BENCH=OFF
	cmake --build $(SANITIZE_BUILD) -j$(JOBS)

test-sanitize: sanitize-build
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=$(CURDIR)/tests/sanitize/ubsan.supp \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j$(JOBS) -E '^postgresql\.'

# Every fuzz target for FUZZ_SECONDS each (scripts/fuzz; crashes are kept under tests/fuzz/regressions).
fuzz: sanitize-build
	scripts/fuzz $(FUZZ_SECONDS) $(SANITIZE_BUILD)

bench: build
	scripts/run-benchmarks $(BUILD)

# 60 s of reads under wrk -c64 beside writes, evaluations and both searches (bench/soak.sh); exit 1
# on any error, any 5xx, or RSS growth of 10% or more after the warm-up. Then rounds of 16
# evaluations at once under a 1 GiB memory budget (bench/soak_evaluations.sh): exit 1 on any answer
# but 200 or 503 overloaded, an RSS past the budget or not given back, or a slow /health. Then 200
# clients sending their headers or bodies a byte a second for 30 s (bench/soak_slow_clients.sh):
# exit 1 when a normal client's request fails or its p99 reaches 100 ms.
SOAK_SECONDS ?= 60
soak: build
	bench/soak.sh $(BUILD) $(SOAK_SECONDS)
	bench/soak_evaluations.sh $(BUILD)
	bench/soak_slow_clients.sh $(BUILD) 200 30

clean:
	rm -rf $(BUILD)
