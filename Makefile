# Two user commands:  make repro  (every figure + the claims report)  and  make test.
# Both first install what is missing (Debian packages, as root), then build.
# Generated files go to $(OUT)/ (ignored by git); the build tree is $(BUILD)/.
# CI (.ci/run) runs make test, then make sanitize.

BUILD      ?= build
OUT        ?= out
BUILD_TYPE ?= Release
PY         := /usr/bin/python3
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
FUZZ_CASES ?= 1000000
# Link-time optimisation of the library (CMake option DDA_LTO, on by default
# for a plain cmake build). Off here: with it every executable's link
# recompiles the library (~10 CPU-seconds per link, ~40 executables), which
# would dominate make test after a change to one library file. Same bits
# either way; LTO=ON makes a collapse step 2-4 % faster (docs/performance.md).
LTO        ?= OFF
PREFIX     ?= /usr/local

# Debian packages the project needs (tool chain first, then libraries, then Python).
DEB_PKGS := g++ cmake make libeigen3-dev catch2 librapidcheck-dev libcgal-dev \
            libbenchmark-dev libbox2d-dev nlohmann-json3-dev python3-numpy python3-matplotlib python3-pil \
            python3-vtk9 python3-dev pybind11-dev python3-pybind11 python3-pytest python3-hypothesis \
            python3-shapely python3-distributed valgrind

BIN := $(BUILD)/bin

.PHONY: all deps configure build test sanitize repro fuzz bench bench-scale profile clean figures report verdicts verdict-run \
        expected-verdicts install

all: build

# Install only what is missing; 'apt-get update' runs once, before the first install.
deps:
	@missing=""; for p in $(DEB_PKGS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "== installing missing Debian packages:$$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi; \
	  $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q && \
	  $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	else echo "== all Debian packages present"; fi

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DDDA_LTO=$(LTO) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# ctest (unit, scene-file, CDEM, property, example and install tests), then
# the verdicts. The sanitizer run is make sanitize (CI runs it after this).
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory verdicts

# Headers, libraries, the dda command and the CMake package into $(PREFIX)
# (find_package(dda CONFIG REQUIRED) with CMAKE_PREFIX_PATH=$(PREFIX)).
install: configure
	@cmake --build $(BUILD) -j $(JOBS) --target dda dda_cdem dda_io dda_cli
	cmake --install $(BUILD) --prefix $(PREFIX)

# The unit, scene-file (io), CDEM and property tests once more, built with
# AddressSanitizer + UndefinedBehaviorSanitizer (DDA_SANITIZE, no recovery:
# any report fails the test) in a separate build tree; property tests with
# SANITIZE_PROPERTY_CASES cases each. No repro drivers, no benchmarks.
# Not part of make test (a second, instrumented build of the library and the
# CGAL tests); .ci/run runs it after make test.
SANITIZE_BUILD          ?= $(BUILD)-asan
SANITIZE_PROPERTY_CASES ?= 2000
SANITIZE_TARGETS        := unit_tests io_tests io_scene_fuzz dda_cli cdem_tests property_tests
SANITIZE_TESTS          := ^(unit_tests|io_tests|io_scene_fuzz|cdem_tests|property_.*)$$
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DDDA_SANITIZE=ON -DDDA_BUILD_BENCH=OFF \
	  -DDDA_PROPERTY_CASES=$(SANITIZE_PROPERTY_CASES) > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target $(SANITIZE_TARGETS)
	cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) -R '$(SANITIZE_TESTS)'

# ---------------------------------------------------------------------------
# Verdicts: every driver with its default arguments into $(VERDICT_OUT), then
# each row's kind and verdict against repro/expected_verdicts.csv (fails
# listing the rows that changed). 'make expected-verdicts' rewrites the list
# from such a run: commit it on its own, saying why a verdict changed.
# The longest drivers come first so that the $(JOBS) parallel runs end together.
# ---------------------------------------------------------------------------
DRIVERS := work_precision collapse toppling_slumping stability_maps extreme_cases \
           segmentation B_7_contact_comparison B_8_bar_waves B_9_impact_study extreme_geometry potential_fields \
           previous_potential two_squares symmetric_stack incline bouncing_block \
           small_angles small_edges B_6_two_prisms penetration_map contact_statements \
           geometry_claims
# A driver's arguments in the verdict run besides --out: options that change
# only its timings, never a row's verdict (S1's timed runs serve its
# work-precision figure; its errors come from the monitored runs: with
# --timing-repeats 0 it times those instead of running each dt again).
VERDICT_ARGS_work_precision := --timing-repeats 0 --jobs $(JOBS)
VERDICT_OUT ?= $(BUILD)/verdicts_out
EXPECTED    := repro/expected_verdicts.csv

verdict-run: configure
	@cmake --build $(BUILD) -j $(JOBS) --target $(DRIVERS)
	@rm -rf $(VERDICT_OUT) && mkdir -p $(VERDICT_OUT)/logs
	@echo "== verdicts: running $(words $(DRIVERS)) drivers ($(JOBS) at a time) into $(VERDICT_OUT)"
	@start=$$(date +%s); \
	printf '%s\n' $(foreach d,$(DRIVERS),"$(strip $(d) $(VERDICT_ARGS_$(d)))") | xargs -P $(JOBS) -L 1 sh -c \
	  '$(BIN)/$$0 --out $(VERDICT_OUT) "$$@" > $(VERDICT_OUT)/logs/$$0.log 2>&1 || { echo "driver $$0 failed: $(VERDICT_OUT)/logs/$$0.log"; exit 1; }' \
	  || exit 1; \
	echo "== verdicts: drivers took $$(( $$(date +%s) - start )) s"

# Every "repro_controls: <name>" a row names must be a test case (Catch2 v2
# exits with the number of names it listed).
verdicts: verdict-run
	@cmake --build $(BUILD) -j $(JOBS) --target repro_controls_tests
	@$(BIN)/repro_controls_tests --list-test-names-only > $(VERDICT_OUT)/control_tests.txt || \
	  test -s $(VERDICT_OUT)/control_tests.txt
	$(PY) repro/common/verdicts.py compare $(VERDICT_OUT)/claims $(EXPECTED) $(VERDICT_OUT)/control_tests.txt

expected-verdicts: verdict-run
	$(PY) repro/common/verdicts.py write $(VERDICT_OUT)/claims $(EXPECTED)

# Property tests with random seeds and FUZZ_CASES cases per property.
# Then the scene-file mutation fuzzer: SCENE_FUZZ_CASES mutated scene files
# read in-process, SCENE_FUZZ_CLI_RUNS of them also through `dda check` and
# `dda run` (random seed; the seed is printed for replay).
SCENE_FUZZ_CASES    ?= 200000
SCENE_FUZZ_CLI_RUNS ?= 500
fuzz: build
	@cmake --build $(BUILD) -j $(JOBS) --target property_fuzz
	FUZZ_CASES=$(FUZZ_CASES) $(BIN)/property_fuzz
	$(BIN)/io_scene_fuzz --cases $(SCENE_FUZZ_CASES) --cli-runs $(SCENE_FUZZ_CLI_RUNS) --seed random

# First the instruction counts (callgrind, lib/bench/instructions.py: the
# Sect. 6.1 collapse's first 0.2 s, the guards' share of it, and the full
# normal contact per overlapping pair against Box2D 2.4's manifold, each
# beside the same count on commit 48051c9, counted with LTO: run
# make bench LTO=ON to compare like with like; ~3 min), then the wall times:
# the geometry kernel per polygon pair (Google Benchmark) and our pair cost
# against Box2D 2.4's, then the Sect. 6.1 collapse (case 1) with 1 and 2
# threads and as two independent 1-thread runs at once (the host's ceiling):
# its contact-heavy start (600 warm-up steps, then 5000 timed, 3 rounds, the
# median shown) and its whole run (600 warm-up steps, then the other
# BENCH_COLLAPSE_STEPS = 74,400 of its 75,000 timed, one round: ~30 s on an
# idle 2-core machine), what a scene skips, and
# the block-count scaling table to BENCH_MAX_BLOCKS blocks (10^4: ~1.5 min in
# all on an idle 2-core machine; BENCH_MAX_BLOCKS=100000 adds the 3 x 10^4
# and 10^5 rows, ~2 more minutes idle, ~5 shared). Prints its own run time at the end.
BENCH_MAX_BLOCKS     ?= 10000
BENCH_COLLAPSE_STEPS ?= 74400
bench: build
	@start=$$(date +%s); \
	$(PY) lib/bench/instructions.py $(BIN) && \
	$(BIN)/bench_geometry && \
	$(BIN)/bench_pair_cost && \
	$(BIN)/bench_collapse --steps 5000 && \
	$(BIN)/bench_collapse --steps $(BENCH_COLLAPSE_STEPS) --rounds 1 && \
	$(BIN)/bench_collapse --skips && \
	mkdir -p $(OUT)/bench && \
	$(BIN)/bench_collapse --scaling --max-blocks $(BENCH_MAX_BLOCKS) --csv $(OUT)/bench/scaling.csv && \
	$(PY) figures/bench_scaling.py $(OUT)/bench/scaling.csv $(OUT)/bench/scaling.png && \
	echo "== make bench: $$(( $$(date +%s) - start )) s (figure $(OUT)/bench/scaling.png)"

# The scaling table on to a million blocks (joint-set rock mass, 50 m high,
# widening): the rows from 10^4 to 10^6 blocks with 1 thread, 200 warm-up
# steps (the biggest scenes are minutes per step count), into
# $(OUT)/bench/scaling_1e6.{csv,png}. ~2.3 GB of heap at 10^6 blocks; ~20 min
# on a 2-core machine shared with other work.
bench-scale: build
	@mkdir -p $(OUT)/bench && start=$$(date +%s); \
	$(BIN)/bench_collapse --scaling --min-blocks 10000 --max-blocks 1000000 --max-threads 1 --warmup 200 \
	  --csv $(OUT)/bench/scaling_1e6.csv && \
	$(PY) figures/bench_scaling.py $(OUT)/bench/scaling_1e6.csv $(OUT)/bench/scaling_1e6.png && \
	echo "== make bench-scale: $$(( $$(date +%s) - start )) s (figure $(OUT)/bench/scaling_1e6.png)"

# Where the Sect. 6.1 collapse's (case 1) time goes, by phase of the step,
# with 1 and 2 threads: perf's cpu-clock samples (no hardware counters
# needed) summed by lib/bench/perf_phases.py. Needs perf (Debian: linux-perf,
# not installed by deps: only this target uses it).
PROFILE_DURATION ?= 7.5
profile: build
	@command -v perf > /dev/null || { echo "make profile: perf not found (Debian package linux-perf)"; exit 2; }
	@mkdir -p $(OUT)/profile && for t in 1 2; do \
	  perf record -q -e cpu-clock -o $(OUT)/profile/collapse_t$$t.data $(BIN)/collapse --case 1 --threads $$t \
	    --duration $(PROFILE_DURATION) --out $(OUT)/profile/run_t$$t > /dev/null && \
	  perf report -i $(OUT)/profile/collapse_t$$t.data --no-children --sort symbol --percent-limit 0.01 --stdio 2> /dev/null | \
	  $(PY) lib/bench/perf_phases.py \
	    --title "== 6.1 collapse, case 1, $$t thread(s), $(PROFILE_DURATION) s simulated: CPU samples by phase" || exit 1; \
	done

# 'repro' builds the tools, then a sub-make rebuilds only the figures whose
# driver binary, data or script changed (one rule per figure below). The
# report gives the wall time since REPRO_START: when this make started (the
# sub-make gets the top-level value), so a 'make repro' counts its build too.
ifndef REPRO_START
REPRO_START := $(shell date +%s)
endif
repro: build
	@$(MAKE) --no-print-directory figures report REPRO_START=$(REPRO_START)

clean:
	rm -rf $(BUILD) $(OUT)

# ---------------------------------------------------------------------------
# Figures: one rule per data set and one per figure.
# ---------------------------------------------------------------------------
FIGS :=
include repro/figures.mk

figures: $(FIGS)

report: $(OUT)/report.md
$(OUT)/report.md: figures/report.py $(wildcard $(OUT)/claims/*.csv) $(FIGS)
	$(PY) figures/report.py --build $(BUILD) --started $(REPRO_START) $(OUT)/claims $@ $(OUT)/claims.json
	@echo "== report: $@"
