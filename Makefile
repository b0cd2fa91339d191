# ydry: set-up, build, run, test. Everything below wraps CMake; `make run` and `make test`
# are the two commands a newcomer needs (README).
BUILD    ?= build
JOBS     ?= $(shell nproc)
DECK     ?= inputs/peron/peron.toml
OUTDIR   ?= runs/$(basename $(notdir $(DECK)))
PYTHON   ?= /usr/bin/python3
SWEEPS_OUT ?= runs/sweeps
SWEEPS   ?= inputs/sweeps/young.toml inputs/sweeps/alpha.toml inputs/sweeps/thickness.toml
THREADS  ?=
# Test time on CI: ctest runs its cases on every core.
CTEST_FLAGS ?= --output-on-failure -j $(JOBS)

.PHONY: all deps configure build run test verify bench sweeps clean

all: build

deps:
	@scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	$(BUILD)/ydry $(DECK) -o $(OUTDIR)
	@echo "Outputs in $(OUTDIR)/ (open $(OUTDIR)/*.pvd in ParaView)"
	$(PYTHON) scripts/plot_run.py $(OUTDIR)

test: build
	cd $(BUILD) && ctest $(CTEST_FLAGS)

# The paraview case needs ParaView's pvpython: installed before the build is configured, so that
# ctest finds it too.
verify:
	@scripts/install-deps.sh --with-paraview
	$(MAKE) build
	$(PYTHON) verification/run_all.py --ydry $(BUILD)/ydry

# Throughput figures, appended to bench/RESULTS.md (2 to 5 minutes on this 2-core machine).
# PERON_RUN=DIR adds the end-to-end figures of a completed run of the Peron deck;
# PERON=1 makes that run first, into runs/peron_bench (about 30 minutes on 2 cores).
bench: build
	$(PYTHON) bench/run_bench.py --build $(BUILD) $(if $(PERON_RUN),--peron-run $(PERON_RUN)) \
	  $(if $(filter 1,$(PERON)),--peron)

# The paper's three sweeps (section 6: E, alpha, thickness), JOBS runs at a time with THREADS
# threads each (default: the cores shared out), then their figures and tables in
# $(SWEEPS_OUT)/plots (README "Sweeps": hours). Run it again after an interruption: completed
# runs are skipped.
sweeps: build
	$(PYTHON) scripts/sweep.py $(SWEEPS) --out $(SWEEPS_OUT) --ydry $(BUILD)/ydry --jobs $(JOBS) \
	  $(if $(THREADS),--threads $(THREADS))
	$(PYTHON) scripts/plot_sweep.py $(SWEEPS_OUT) --out $(SWEEPS_OUT)/plots

clean:
	rm -rf $(BUILD)
