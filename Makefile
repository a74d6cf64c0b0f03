# Quick start:  make run   (install deps, build, route designs/demo.xml into out/)
#               make test  (install deps, build release and ASan/UBSan trees, run every test)
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
BUILD ?= build
ASAN_BUILD ?= build-asan
CMAKE_FLAGS ?=

.PHONY: all deps build build-asan build-tests build-asan-tests run test test-release test-asan test-long bench rdl install clean

all: build

deps:
	@scripts/deps.sh

$(BUILD)/CMakeCache.txt: | deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null

build: deps $(BUILD)/CMakeCache.txt
	@cmake --build $(BUILD) -j $(JOBS) -- --no-print-directory

$(ASAN_BUILD)/CMakeCache.txt: | deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DTAUT_SANITIZE=ON -DTAUT_BUILD_BENCH=OFF $(CMAKE_FLAGS) >/dev/null

build-asan: deps $(ASAN_BUILD)/CMakeCache.txt
	@cmake --build $(ASAN_BUILD) -j $(JOBS) -- --no-print-directory

# What make test needs: the command and the tests (not the benchmarks).
# cmake_check_build_system first: a tree configured before taut_tests existed learns of it.
build-tests: deps $(BUILD)/CMakeCache.txt
	@cmake --build $(BUILD) --target cmake_check_build_system -- --no-print-directory
	@cmake --build $(BUILD) -j $(BUILD_JOBS) --target taut_tests -- --no-print-directory

build-asan-tests: deps $(ASAN_BUILD)/CMakeCache.txt
	@cmake --build $(ASAN_BUILD) --target cmake_check_build_system -- --no-print-directory
	@cmake --build $(ASAN_BUILD) -j $(BUILD_JOBS) --target taut_tests -- --no-print-directory

run: build
	@mkdir -p out
	$(BUILD)/tools/taut route designs/demo.xml -o out/demo.routed.xml --svg out/demo.svg --stats out/demo.stats.json
	@# the nets are routed together with the rules' width and spacing: the whole check must pass
	$(BUILD)/tools/taut check out/demo.routed.xml -q --json > out/demo.check.json
	@# octilinear wires: every net routed (bump's diamond pin too), the whole check passes
	$(BUILD)/tools/taut route designs/demo.xml --orientations octilinear -q -o out/demo.oct.routed.xml --svg out/demo.oct.svg
	$(BUILD)/tools/taut check out/demo.oct.routed.xml -q
	@# clk by an octilinear Steiner tree (22,405 DBU against its shortest-path tree's 39,331); the file passes taut check
	$(BUILD)/tools/taut route designs/demo.xml --orientations octilinear --tree steiner -q -o out/demo.oct.steiner.xml --svg out/demo.oct.steiner.svg --stats out/demo.oct.steiner.json
	$(BUILD)/tools/taut check out/demo.oct.steiner.xml -q
	$(BUILD)/tools/taut voronoi designs/demo.xml -q -o out/demo.cells.xml --svg out/demo.voronoi.svg > out/demo.voronoi.txt
	$(BUILD)/tools/taut tighten designs/wind.xml -q --clearance --min-link -o out/wind.tightened.xml --svg out/wind.svg --stats out/wind.stats.json
	$(BUILD)/tools/taut route designs/bends.xml -q --metric combined --bend-cost 0 -o out/bends.c0.xml --svg out/bends.c0.svg
	$(BUILD)/tools/taut route designs/bends.xml -q --metric combined --bend-cost 5000 -o out/bends.c5000.xml --svg out/bends.c5000.svg
	$(BUILD)/tools/taut diameter designs/diameter.xml --json --svg out/diameter.svg > out/diameter.json
	$(BUILD)/tools/taut route designs/demo.xml -q --metric combined --bend-cost 1000 -o out/demo.bends.xml --svg out/demo.bends.svg
	$(BUILD)/tools/taut route designs/demo.xml -q --tighten -o out/demo.tight.xml --svg out/demo.tight.svg
	$(BUILD)/tools/taut check out/demo.tight.xml -q
	@# any-angle wires: routed octilinear, then tightened together into any angle (bump by its sketch); the whole check passes
	$(BUILD)/tools/taut route designs/demo.xml -q --orientations any -o out/demo.any.xml --svg out/demo.any.svg
	$(BUILD)/tools/taut check out/demo.any.xml -q
	$(BUILD)/tools/taut tighten designs/wind.xml -q --clearance --orientations c:45,135 -o out/wind.diagonal.xml --svg out/wind.diagonal.svg
	@# FORMAT.md's own set, c:0,60,120: every net routed in it (vertices rounded to integers); the whole check passes
	$(BUILD)/tools/taut route designs/demo.xml -q --orientations c:0,60,120 -o out/demo.hex.xml --svg out/demo.hex.svg
	$(BUILD)/tools/taut check out/demo.hex.xml -q
	$(BUILD)/tools/taut tighten designs/wind.xml -q --clearance --min-link --orientations octilinear -o out/wind.oct.xml --svg out/wind.oct.svg --stats out/wind.oct.stats.json
	$(BUILD)/tools/taut tighten designs/wind.xml -q --clearance --min-link --orientations c:0,60,120 -o out/wind.hex.xml --svg out/wind.hex.svg --stats out/wind.hex.stats.json
	@# four nets through a channel exactly four tracks wide (tracks at exactly the clearance and the pitch)
	$(BUILD)/tools/taut route designs/pitch.xml -q -o out/pitch.routed.xml --svg out/pitch.svg --stats out/pitch.stats.json
	$(BUILD)/tools/taut check out/pitch.routed.xml -q
	@echo "wrote out/demo.routed.xml, out/demo.svg, out/demo.stats.json, out/demo.check.json, octilinear wires in out/demo.oct.routed.xml, out/demo.oct.svg, with clk as an octilinear Steiner tree in out/demo.oct.steiner.xml, out/demo.oct.steiner.svg, out/demo.oct.steiner.json, the pins' Voronoi diagram in out/demo.cells.xml, out/demo.voronoi.svg, designs/wind.xml's sketches tightened in out/wind.tightened.xml, out/wind.svg, out/wind.stats.json, and designs/bends.xml routed with bend costs 0 and 5000 in out/bends.c0.xml, out/bends.c0.svg, out/bends.c5000.xml, out/bends.c5000.svg, and designs/diameter.xml's link diameter in out/diameter.json, out/diameter.svg, and designs/demo.xml routed with length + 1000 x bends (shape pins included) in out/demo.bends.xml, out/demo.bends.svg, routed and tightened together (bump by its sketch) in out/demo.tight.xml, out/demo.tight.svg, with any-angle wires in out/demo.any.xml, out/demo.any.svg, and designs/wind.xml tightened in the diagonals only (c:45,135) in out/wind.diagonal.xml, out/wind.diagonal.svg, designs/demo.xml routed in c:0,60,120 in out/demo.hex.xml, out/demo.hex.svg, and in octilinear with each wire's minimum-link octilinear path (dash-dotted) in out/wind.oct.xml, out/wind.oct.svg, out/wind.oct.stats.json, the same in c:0,60,120 (minimum-link paths exact in Q(sqrt3)) in out/wind.hex.xml, out/wind.hex.svg, out/wind.hex.stats.json, and designs/pitch.xml's four nets on four tracks at exactly the pitch in out/pitch.routed.xml, out/pitch.svg, out/pitch.stats.json"

# The two trees build and test side by side: one's serial tails (a big file compiling alone,
# links, a slow test) overlap the other's work. Each compiles with half the JOBS (one job each
# on two cores): each with all of them (four compilers on two cores) cost 20-40 % more CPU per
# compile (router/check.cpp: 8.5 s of CPU alone, 10.2-12.2 s each of four at once; 2026-12-05).
# ctest keeps all the JOBS: the tree that ends its tests last runs them alone. Output is kept
# per step.
BUILD_JOBS ?= $(JOBS)
test: deps
	@$(MAKE) --no-print-directory -j 2 --output-sync=target BUILD_JOBS=$(shell echo $$(( ($(JOBS) + 1) / 2 ))) test-release test-asan

# A fresh tree has no timings of its own yet: ctest would start the slowest tests last and end
# on one of them alone. tests/cost/ holds timings measured here (the format of ctest's
# CTestCostData.txt), so ctest starts them first; a tree that has run keeps its own.
COSTS = Testing/Temporary/CTestCostData.txt

test-release: build-tests
	@mkdir -p $(BUILD)/Testing/Temporary && (test -f $(BUILD)/$(COSTS) || cp tests/cost/release.txt $(BUILD)/$(COSTS))
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE long

# ASan's quarantine (freed memory held back so a use after free is caught) is 256 MB by default,
# and every test is a process of its own that pages it in: 16 MB made the sanitizer tests 20 %
# faster here (50 router tests 57.6 -> 46.0 s, 2026-12-04). A use after free is still caught
# until 16 MB more has been freed. Options of your own in ASAN_OPTIONS come after it (the later
# one wins), so they keep their effect and may set the quarantine too.
SANITIZER_TEST_OPTIONS := quarantine_size_mb=16$(if $(ASAN_OPTIONS),:$(ASAN_OPTIONS))

test-asan: build-asan-tests
	@mkdir -p $(ASAN_BUILD)/Testing/Temporary && (test -f $(ASAN_BUILD)/$(COSTS) || cp tests/cost/asan.txt $(ASAN_BUILD)/$(COSTS))
	cd $(ASAN_BUILD) && ASAN_OPTIONS='$(SANITIZER_TEST_OPTIONS)' ctest --output-on-failure -j $(JOBS) -LE long

test-long: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L long

bench: build
	$(BUILD)/bench/bench_foundation
	$(BUILD)/bench/bench_wavefront
	$(BUILD)/bench/bench_oct_wavefront
	$(BUILD)/bench/bench_spm
	$(BUILD)/bench/bench_voronoi
	$(BUILD)/bench/bench_net_tree
	$(BUILD)/bench/bench_bends
	$(BUILD)/bench/bench_diameter
	$(BUILD)/bench/bench_diameter_approx
	$(BUILD)/bench/bench_check
	$(BUILD)/bench/bench_import
	$(BUILD)/bench/bench_steiner
	$(BUILD)/bench/bench_net_router --threads 2 --tighten
	$(BUILD)/bench/bench_net_router --sizes 10000 --nets 300,1000 --threads 1 --orientations any
	$(BUILD)/bench/bench_net_router --sizes 10000 --nets 300,1000 --threads 1 --orientations c:0,45,90

# OpenROAD's flip-chip RDL test case (../shared/data/openroad-rdl): imported, routed, checked,
# and compared with OpenROAD's own routing of it (README, "A real layout").
rdl: build
	@command -v python3 >/dev/null || { echo "make rdl needs python3 (apt-get install python3)" >&2; exit 2; }
	python3 scripts/rdl_openroad.py --taut $(BUILD)/tools/taut --out out/rdl

install: build
	cmake --install $(BUILD) --prefix $(or $(PREFIX),/usr/local)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
