# ydry: set-up, build, run, test. Everything below wraps CMake; `make run` and `make test`
# are the two commands a newcomer needs (README).
BUILD    ?= build
JOBS     ?= $(shell nproc)
DECK     ?= inputs/peron/peron.toml
OUTDIR   ?= runs/$(basename $(notdir $(DECK)))
PYTHON   ?= /usr/bin/python3
SWEEPS_OUT ?= runs/sweeps
SWEEPS   ?= inputs/sweeps/young.toml inputs/sweeps/alpha.toml inputs/sweeps/thickness.toml
ROBUSTNESS_OUT ?= runs/robustness
ROBUSTNESS ?= verification/peron/robustness/seed.toml verification/peron/robustness/relaxation.toml \
              verification/peron/robustness/penalty.toml verification/peron/robustness/mesh.toml
THREADS  ?=
# Test time on CI: ctest runs its cases on every core.
CTEST_FLAGS ?= --output-on-failure -j $(JOBS)

.PHONY: all deps configure build run test verify bench sweeps robustness fuzz sanitize clean

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
# PERON=1 makes that run first, into runs/peron_bench (8-9 minutes on 2 cores).
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

# The Peron figures' robustness (verification/peron/README.md "Robustness"): the shipped
# deck, three heterogeneity seeds, the relaxation tolerance ten times tighter, the penalties ten
# times stiffer and the element size halved (its mesh made by gmsh), JOBS at a time, then the
# verdicts against the shipped run. Several hours of one core; run it again after an
# interruption: runs go on from their checkpoints.
inputs/peron/peron_fine.msh: inputs/peron/peron.geo
	gmsh -2 -format msh41 -setnumber h 0.00075 -o $@ $< > $@.log
	@! grep -q Error $@.log || (cat $@.log; rm -f $@; exit 1)
	@rm -f $@.log

robustness: build inputs/peron/peron_fine.msh
	$(PYTHON) scripts/sweep.py $(ROBUSTNESS) --out $(ROBUSTNESS_OUT) --ydry $(BUILD)/ydry --jobs $(JOBS) \
	  $(if $(THREADS),--threads $(THREADS))
	$(PYTHON) verification/peron/robustness.py $(ROBUSTNESS_OUT) --ydry $(BUILD)/ydry

# libFuzzer on the deck reader (with --set overrides) and the Gmsh reader, built with clang,
# ASan and UBSan in their own folder; FUZZ_RUNS executions per target from tests/fuzz/corpus,
# each target stopped after FUZZ_MAX_TIME seconds at most (then it fails). README: reproduce
# one input with `build-fuzz/fuzz_NAME FILE`.
FUZZ_BUILD    ?= build-fuzz
FUZZ_RUNS     ?= 100000
FUZZ_MAX_TIME ?= 1800
fuzz:
	@scripts/install-deps.sh --with-clang
	cmake -S . -B $(FUZZ_BUILD) -DYDRY_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug
	cmake --build $(FUZZ_BUILD) -j $(JOBS)
	tests/fuzz/run_fuzz.sh $(FUZZ_BUILD) $(FUZZ_RUNS) $(FUZZ_MAX_TIME)

# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (GCC, -O1);
# any report fails the test it happens in. -Wno-maybe-uninitialized: GCC warns falsely under
# the sanitizers (its manual says so), here in libstdc++'s <regex> that Catch2 includes.
SANITIZE_BUILD ?= build-sanitize
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -g
sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS) -Wno-maybe-uninitialized" -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE_FLAGS)" \
	  -DYDRY_SCRIPT_TEST_TIMEOUT=1200
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  ctest $(CTEST_FLAGS)

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) $(SANITIZE_BUILD)
