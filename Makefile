# partet: the quick-start and developer targets. Each installs what it needs.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps build demo test test-asan fuzz bench-steps bench bench-large corpus-check stress-check clean

all: build

deps:
	@scripts/install-deps

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@scripts/demo $(BUILD)

test: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DPARTET_WERROR=ON $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-asan: deps
	@cmake -S . -B $(BUILD)-asan -DCMAKE_BUILD_TYPE=Debug -DPARTET_SANITIZE=ON -DPARTET_WERROR=ON >/dev/null
	@cmake --build $(BUILD)-asan -j $(JOBS)
	@cd $(BUILD)-asan && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -E '^mpi_'

bench-steps: build
	@bench/steps $(BUILD)

# partet against TetGen, Gmsh and Netgen (installed from Debian when missing);
# BENCH_ARGS passes options, e.g. BENCH_ARGS=--quick (see bench/README.md).
bench: build
	@bench/run --build $(BUILD) $(BENCH_ARGS)

bench-large: build
	@bench/large --build $(BUILD) $(BENCH_ARGS)

corpus-check: build
	@scripts/corpus-check $(BUILD) $(or $(ROUNDS),3)

stress-check: build
	@scripts/stress-check $(BUILD) $(or $(COUNT),200) $(or $(SEED),1)

fuzz:
	@PARTET_FUZZ_DEPS=1 scripts/install-deps
	@scripts/fuzz $(or $(SECONDS),60)

clean:
	rm -rf $(BUILD) $(BUILD)-asan build-fuzz
