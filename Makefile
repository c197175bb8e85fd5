# fsdb: the two commands a fresh machine needs are `make serve` and `make test` (see README).
BUILD ?= build
JOBS ?= 2
HOST ?= 127.0.0.1
PORT ?= 8080

.PHONY: deps configure build serve test bench clean

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

bench: build
	scripts/run-benchmarks $(BUILD)

clean:
	rm -rf $(BUILD)
