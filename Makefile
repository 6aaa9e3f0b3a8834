# The two commands a new machine needs (README): `make demo` and `make test`.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: demo test build deps clean

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

clean:
	rm -rf $(BUILD) out

DEMO_CASE ?= cases/paper-7.2.toml
DEMO_OUT ?= out/paper-7.2/ (summary.json, history.csv, fsi.png, structure.png, fsi.pvd opens fluid.vtu and structure.vtu in ParaView)
