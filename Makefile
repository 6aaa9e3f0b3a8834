# The two commands a new machine needs (README): `make demo` and `make test`.
# Budgets, measured on a fresh 2-core machine (docs/performance.md, "Build and test
# budgets"): make demo 5 min with the packages, make test after it 5 min, .ci/run 30 min.
BUILD ?= build
INSTRUMENTED ?= build-instrumented
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
# Ninja when it is there (scripts/install-deps.sh installs it): a full build takes what
# make's takes (103 against 108 s, within the machine's noise), a rebuild with nothing to
# do 0.05 s instead of 0.5 s, and its .ninja_log keeps each file's compile time.
GENERATOR := $(if $(shell command -v ninja),-G Ninja,)
# A test of the Release suite over this many seconds is a study or a benchmark.
TEST_BUDGET ?= 20
INSTRUMENTED_TEST_BUDGET ?= 120

.PHONY: demo test build program tests configure deps clean check-instrumented instrumented-build instrumented-suite \
        fuzz-smoke fuzz test-sanitize bench-compare install package

deps:
	@scripts/install-deps.sh

# Configured once (until its build files exist: a configuration that failed is redone);
# later CMakeLists changes re-run CMake from the build itself.
configured = test -f $(1)/build.ninja || test -f $(1)/Makefile
configure: deps
	@$(call configured,$(BUILD)) || \
	  cmake -S . -B $(BUILD) $(GENERATOR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > /dev/null

# The program and the Gmsh plugin it loads: all that `make demo` needs.
program: configure
	@cmake --build $(BUILD) -j $(JOBS) --target fsicontact

# The program and the test suite.
tests: configure
	@cmake --build $(BUILD) -j $(JOBS) --target fsicontact_tests

# Everything: the program, the tests and the benchmarks (bench/).
build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Release build of the program, then the main case: the paper's §7.2 fluid-structure case.
demo: program
	@$(BUILD)/app/fsicontact run $(DEMO_CASE)
	@echo "demo: results in $(DEMO_OUT)"

# The program, its Gmsh plugin, the Python module, the example cases, the docs and the man page under
# PREFIX (CMakeLists.txt's install rules; the same as cmake --install build --prefix P).
PREFIX ?= /usr/local
install: program
	@cmake --build $(BUILD) -j $(JOBS) --target fsicontact_python
	@cmake --install $(BUILD) --prefix $(PREFIX)

# A Debian package of the same install under /usr (CPack, CMakeLists.txt): its
# dependencies computed from the libraries it links (dpkg-shlibdeps). Checked by
# scripts/check-deb.sh; install it with apt-get install ./$(BUILD)/fsicontact_*.deb.
package: program
	@cmake --build $(BUILD) -j $(JOBS) --target fsicontact_python
	@cd $(BUILD) && cpack -G DEB > /dev/null && ls fsicontact_*.deb

# The whole suite in Release, then its time budget (cmake/TestBudget.cmake).
test: tests
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --output-junit junit.xml
	@cmake -DJUNIT=$(BUILD)/junit.xml -DBUDGET=$(TEST_BUDGET) -DWHAT=Release -P cmake/TestBudget.cmake

# One clang build with AddressSanitizer, UBSan and libFuzzer's coverage over everything
# of ours (cmake/Instrumentation.cmake), file by file (no unity batches): the whole
# suite under the sanitizers, then a short run of each fuzz target. CI runs it after
# make test (docs/reliability.md).
ASAN_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
instrumented-build: deps
	@$(call configured,$(INSTRUMENTED)) || cmake -S . -B $(INSTRUMENTED) $(GENERATOR) \
	  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Instrumented -DFSICONTACT_FUZZ=ON \
	  -DFSICONTACT_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(INSTRUMENTED) -j $(JOBS)

# The suite but its studies (tests/CMakeLists.txt) under the sanitizers, and its budget;
# INSTRUMENTED_LABEL=. runs the studies too.
INSTRUMENTED_LABEL ?= unit
instrumented-suite: instrumented-build
	@rm -rf $(INSTRUMENTED)/tests/gtest-xml
	@cd $(INSTRUMENTED) && $(ASAN_ENV) ctest --output-on-failure -j $(JOBS) -L '$(INSTRUMENTED_LABEL)' \
	  -LE fuzz --output-junit junit.xml
	@cmake -DJUNIT=$(INSTRUMENTED)/junit.xml -DXML_DIR=$(INSTRUMENTED)/tests/gtest-xml -DBUDGET=$(INSTRUMENTED_TEST_BUDGET) \
	  -DWHAT="the instrumented build" -P cmake/TestBudget.cmake

check-instrumented: instrumented-suite fuzz-smoke

# The name it had before the two instrumented builds became one.
test-sanitize: check-instrumented

# The three side by side: they took 4.6 + 67 + 121 s one after the other.
fuzz-smoke: instrumented-build
	@cd $(INSTRUMENTED) && ctest --output-on-failure -j $(JOBS) -L fuzz

# libFuzzer targets (fuzz/): make fuzz runs each for FUZZ_RUNS inputs
# (docs/reliability.md). fuzz_cli works in its own scratch directory: its corpus
# paths must be absolute.
FUZZ_RUNS ?= 200000
FUZZ_LSAN = LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0
FUZZ_DIR = $(abspath $(INSTRUMENTED)/fuzz)
fuzz: instrumented-build
	@mkdir -p $(FUZZ_DIR)/long-case $(FUZZ_DIR)/long-msh $(FUZZ_DIR)/long-cli
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) $(FUZZ_DIR)/fuzz_case -runs=$(FUZZ_RUNS) -max_len=4096 -timeout=60 $(FUZZ_DIR)/long-case cases tests/data/fuzz-regressions
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) $(FUZZ_DIR)/fuzz_msh -runs=$(FUZZ_RUNS) -max_len=20000 -timeout=60 $(FUZZ_DIR)/long-msh cases/meshes tests/data/fuzz-msh
	ASAN_OPTIONS=detect_leaks=1 $(FUZZ_LSAN) $(FUZZ_DIR)/fuzz_cli -runs=$(FUZZ_RUNS) -max_len=65536 -timeout=60 \
	  -artifact_prefix=$(FUZZ_DIR)/ $(FUZZ_DIR)/long-cli $(CURDIR)/fuzz/seeds/cli

# FreeFem++ (the same algorithm, bench/freefem/) against fsicontact on Table 1's rows, run
# interleaved; prints iterations, times, memory and speed-ups (bench/compare_freefem.sh;
# all 19 rows take ~20 minutes). Options pass through, e.g.
#   make bench-compare COMPARE_ARGS="--rows 1,2 --out /tmp/compare"
COMPARE_ARGS ?=
bench-compare:
	@scripts/install-deps.sh --with-freefem
	@$(MAKE) --no-print-directory program
	@FSICONTACT=$(BUILD)/app/fsicontact bench/compare_freefem.sh $(COMPARE_ARGS)

clean:
	rm -rf $(BUILD) $(INSTRUMENTED) out

DEMO_CASE ?= cases/paper-7.2.toml
DEMO_OUT ?= out/paper-7.2/ (summary.json, history.csv, fsi.png, structure.png, fsi.pvd opens fluid.vtu and structure.vtu in ParaView)
