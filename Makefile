# The two commands of the README (docs/getting-started.md):
#   make demo   installs dependencies, builds (Release; the CLI and the Python module) and runs
#               the built-in demo
#   make test   installs dependencies, builds and runs every test in Release, then every test
#               that is not `slow` again under ASan + UBSan (clang 16, a Debug build at -O1, so
#               assertions are checked too)
# and the edit loop and the rest:
#   make check  the library's unit tests (label `fast`) in Release, after an incremental build
#   make blender  the Python module and the Blender add-on into your own Blender (no root)
#   make docs   the documentation site (docs/, mkdocs.yml, the API references) into build/site
#   make fuzz   builds the libFuzzer targets in the sanitizer tree and runs each FUZZ_SECONDS (60)
# Test tiers and timeouts: cmake/test_tiers.cmake.
JOBS   ?= $(shell nproc)
OUT    ?= out/demo
CMAKE  := cmake
RELEASE_DIR  := build/release
SANITIZE_DIR := build/sanitize
FUZZ_SECONDS ?= 60
# Ninja for new build trees (a tree made earlier with another generator keeps it).
GENERATOR = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)
CONFIGURE_RELEASE = $(CMAKE) -S . -B $(RELEASE_DIR) $(call GENERATOR,$(RELEASE_DIR)) \
	-DCMAKE_BUILD_TYPE=Release
# The sanitizer tree holds the tests and the fuzz targets: one compile of the library under
# ASan + UBSan serves both. clang 16, because libFuzzer is clang's, and because it compiles
# this code under the sanitizers in about two thirds of GCC 12's time (psd_projection.cpp 75 s
# against 122 s, friction_test.cpp 52 s against 77 s). Line tables only (-g1), not full debug
# information: the sanitizers' reports still name file and line, and the tree compiles
# faster. No benchmarks and no Python module there (an extension under ASan needs the runtime
# preloaded into the interpreter). The test programs' own code gets ASan without UBSan, and
# UBSan leaves Eigen's headers alone (top-level CMakeLists.txt, ANIMKIT_SANITIZE;
# cmake/ubsan_ignorelist.txt).
CONFIGURE_SANITIZE = $(CMAKE) -S . -B $(SANITIZE_DIR) $(call GENERATOR,$(SANITIZE_DIR)) \
	-DCMAKE_CXX_COMPILER=clang++-16 -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
	-DANIMKIT_SANITIZE=ON -DANIMKIT_BUILD_FUZZERS=ON \
	-DANIMKIT_BUILD_BENCHMARKS=OFF -DANIMKIT_BUILD_PYTHON=OFF

.PHONY: deps test-deps build demo viewer blender docs test test-release test-sanitize check fuzz bench clean

deps:
	bash scripts/install-deps.sh

# Everything, the benchmark programs included (they are not in `all`: `make test` skips them).
build: deps
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target all animkit_benchmarks

demo: deps
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit-cli animkit_python
	$(RELEASE_DIR)/apps/cli/animkit demo --out $(OUT)

# Opens animkit-viewer in a window (needs a display; see docs/viewer.md for --capture without one).
viewer: deps
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit-viewer
	$(RELEASE_DIR)/apps/viewer/animkit-viewer

# The module and the add-on into your own Blender (no root): scripts/install-blender.sh.
blender: deps
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit_python
	bash scripts/install-blender.sh $(RELEASE_DIR)

# The documentation site into build/site (mkdocs.yml): warnings are errors (--strict fails on a
# link to a missing page), and every link to a heading is checked too. The Python API page is
# written from the built module's docstrings and the performance page from the benchmarks'
# JSON (bench/results) first; Doxygen then writes the C++ API reference into build/site/api
# and fails on any public symbol without a comment (Doxyfile).
docs: deps
	bash scripts/install-deps.sh --docs
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit_python
	/usr/bin/python3 python/tools/generate_api_page.py $(RELEASE_DIR)/python docs/python-api.md
	python3 scripts/performance-page.py bench/results docs/performance.md
	mkdocs build --strict --site-dir build/site
	doxygen Doxyfile
	python3 scripts/check-doc-links.py build/site

test-deps:
	bash scripts/install-deps.sh --tests

# Every test, the slow tier included (the costliest start first, beside the short ones). The
# test packages install while the Release tree compiles (scripts/with-test-deps.sh).
test-release: deps
	bash scripts/with-test-deps.sh sh -c '$(CONFIGURE_RELEASE) && $(CMAKE) --build $(RELEASE_DIR) -j $(JOBS)'
	cd $(RELEASE_DIR) && ctest --output-on-failure -j $(JOBS)

# Every test but the slow tier: the whole-scene audits and the reach statistics take minutes in
# Release and would take an hour here; every solver's limit, bone and determinism tests still
# run. A failing test gets a second run: LeakSanitizer's exit-time tracer has crashed once
# (signal 11 inside the sanitizer, with Mesa loaded) on a passing test. A real failure fails
# twice.
test-sanitize: deps test-deps
	$(CONFIGURE_SANITIZE)
	$(CMAKE) --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) --repeat until-pass:2 -LE slow

test: test-release test-sanitize

# The edit loop: builds only what the fast tier runs, then runs it.
check: deps
	$(CONFIGURE_RELEASE)
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit_tests animkit_allocation_tests
	cd $(RELEASE_DIR) && ctest --output-on-failure -j $(JOBS) -L fast

# The fuzz targets, built in the sanitizer tree (libFuzzer, ASan and UBSan; see
# CONFIGURE_SANITIZE); then every target runs FUZZ_SECONDS over its corpus and kept crash inputs
# (scripts/run-fuzzers.sh), failing on any crash.
fuzz: deps test-deps
	$(CONFIGURE_SANITIZE)
	$(CMAKE) --build $(SANITIZE_DIR) -j $(JOBS) --target animkit_fuzzers
	bash scripts/run-fuzzers.sh $(SANITIZE_DIR) $(FUZZ_SECONDS)

bench: build
	bash scripts/run-benchmarks.sh $(RELEASE_DIR)

clean:
	rm -rf build out
