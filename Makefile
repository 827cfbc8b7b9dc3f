# The two commands of the README:
#   make demo   installs dependencies, builds (Release; the CLI and the Python module) and runs
#               the built-in demo
#   make test   installs dependencies, builds and runs every test, then again under ASan+UBSan
#               (a Debug build at -O1, so assertions are checked too)
#   make fuzz   builds the libFuzzer targets with clang 16 and runs each FUZZ_SECONDS (60)
JOBS   ?= $(shell nproc)
OUT    ?= out/demo
CMAKE  := cmake
RELEASE_DIR  := build/release
SANITIZE_DIR := build/sanitize
FUZZ_DIR     := build/fuzz
FUZZ_SECONDS ?= 60

.PHONY: deps test-deps fuzz-deps build demo viewer test test-release test-sanitize fuzz bench clean

deps:
	bash scripts/install-deps.sh

build: deps
	$(CMAKE) -S . -B $(RELEASE_DIR) -DCMAKE_BUILD_TYPE=Release
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS)

demo: deps
	$(CMAKE) -S . -B $(RELEASE_DIR) -DCMAKE_BUILD_TYPE=Release
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit-cli animkit_python
	$(RELEASE_DIR)/apps/cli/animkit demo --out $(OUT)

# Opens animkit-viewer in a window (needs a display; see the README for --capture without one).
viewer: deps
	$(CMAKE) -S . -B $(RELEASE_DIR) -DCMAKE_BUILD_TYPE=Release
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS) --target animkit-viewer
	$(RELEASE_DIR)/apps/viewer/animkit-viewer

test-deps:
	bash scripts/install-deps.sh --tests

test-release: deps test-deps
	$(CMAKE) -S . -B $(RELEASE_DIR) -DCMAKE_BUILD_TYPE=Release
	$(CMAKE) --build $(RELEASE_DIR) -j $(JOBS)
	cd $(RELEASE_DIR) && ctest --output-on-failure -j $(JOBS)

test-sanitize: deps
	$(CMAKE) -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
	  -DANIMKIT_SANITIZE=ON \
	  -DANIMKIT_BUILD_BENCHMARKS=OFF -DANIMKIT_BUILD_PYTHON=OFF
	$(CMAKE) --build $(SANITIZE_DIR) -j $(JOBS)
	# A failing test gets a second run: LeakSanitizer's exit-time tracer has crashed once (signal
	# 11 inside the sanitizer, with Mesa loaded) on a passing test. A real failure fails twice.
	# The built-in scenes' whole-run audits (minutes each in Release) and the tree IK solvers'
	# reach statistics (hundreds of solves to 1000 iterations each) run in test-release only;
	# the sanitizer still runs every solver's limit, bone and determinism tests.
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) --repeat until-pass:2 \
	  -E 'BuiltinSceneAudit|ReachesJointlyReachableTargets'

test: test-release test-sanitize

fuzz-deps:
	bash scripts/install-deps.sh --fuzz

# The library and the fuzz targets only (a Debug build at -O1: assertions are checked too),
# with libFuzzer, ASan and UBSan; then every target runs FUZZ_SECONDS over its corpus and kept
# crash inputs (scripts/run-fuzzers.sh), failing on any crash.
fuzz: deps fuzz-deps
	$(CMAKE) -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++-16 \
	  -DANIMKIT_BUILD_FUZZERS=ON -DANIMKIT_BUILD_TESTS=OFF -DANIMKIT_BUILD_CLI=OFF \
	  -DANIMKIT_BUILD_VIEWER=OFF -DANIMKIT_BUILD_BENCHMARKS=OFF -DANIMKIT_BUILD_PYTHON=OFF
	$(CMAKE) --build $(FUZZ_DIR) -j $(JOBS)
	bash scripts/run-fuzzers.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

bench: build
	$(RELEASE_DIR)/bench/ik_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	$(RELEASE_DIR)/bench/cloth_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

clean:
	rm -rf build out
