# The two commands a new machine needs (README): `make demo` and `make test`.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: demo test build deps clean fuzz-build fuzz-smoke fuzz test-sanitize bench-compare

deps:
	@scripts/install-deps.sh

$(BUILD)/Makefile: CMakeLists.txt | deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > /dev/null

build: deps $(BUILD)/Makefile
	@cmake --build $(BUILD) -j $(JOBS)

# Release build, then the main case: the paper's §7.2 fluid-structure case.
demo: build
	@$(BUILD)/app/fsicontact run $(DEMO_CASE)
	@echo "demo: results in $(DEMO_OUT)"

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory fuzz-smoke

# libFuzzer targets (clang, ASan + UBSan, the whole program instrumented): a short
# run of each is part of `make test`; `make fuzz` runs each for FUZZ_RUNS inputs
# (docs/reliability.md). fuzz_cli works in its own scratch directory: its corpus
# paths must be absolute.
FUZZ_RUNS ?= 200000
FUZZ_LSAN = LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0
fuzz-build: deps
	@cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ > /dev/null
	@cmake --build build-fuzz -j $(JOBS)

fuzz-smoke: fuzz-build
	@cd build-fuzz && ctest --output-on-failure

fuzz: fuzz-build
	@mkdir -p build-fuzz/long-case build-fuzz/long-msh build-fuzz/long-cli
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) build-fuzz/fuzz_case -runs=$(FUZZ_RUNS) -max_len=4096 -timeout=60 build-fuzz/long-case cases tests/data/fuzz-regressions
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) build-fuzz/fuzz_msh -runs=$(FUZZ_RUNS) -max_len=20000 -timeout=60 build-fuzz/long-msh cases/meshes tests/data/fuzz-msh
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) build-fuzz/fuzz_cli -runs=$(FUZZ_RUNS) -max_len=65536 -timeout=60 \
	  -artifact_prefix=$(CURDIR)/build-fuzz/ $(CURDIR)/build-fuzz/long-cli $(CURDIR)/fuzz/seeds/cli

# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer.
test-sanitize: deps
	@cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFSICONTACT_SANITIZE=ON \
	  -DFSICONTACT_BUILD_BENCH=OFF > /dev/null
	@cmake --build build-sanitize -j $(JOBS)
	@cd build-sanitize && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS)

# FreeFem++ (the same algorithm, bench/freefem/) against fsicontact on Table 1's rows, run
# interleaved; prints iterations, times, memory and speed-ups (bench/compare_freefem.sh;
# all 19 rows take ~20 minutes). Options pass through, e.g.
#   make bench-compare COMPARE_ARGS="--rows 1,2 --out /tmp/compare"
COMPARE_ARGS ?=
bench-compare:
	@scripts/install-deps.sh --with-freefem
	@$(MAKE) --no-print-directory build
	@FSICONTACT=$(BUILD)/app/fsicontact bench/compare_freefem.sh $(COMPARE_ARGS)

clean:
	rm -rf $(BUILD) build-fuzz build-sanitize out

DEMO_CASE ?= cases/paper-7.2.toml
DEMO_OUT ?= out/paper-7.2/ (summary.json, history.csv, fsi.png, structure.png, fsi.pvd opens fluid.vtu and structure.vtu in ParaView)
