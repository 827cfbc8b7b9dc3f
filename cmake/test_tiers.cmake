# Test tiers. Every test carries one of these labels and a timeout:
#   fast     the library's unit tests (GoogleTest, animkit_tests and the allocation counts):
#            `make check`, the edit loop
#   slow     whole-scene audits and solver statistics that take minutes: any GoogleTest suite
#            whose name ends in "Slow" (TEST(FabrikTreeSlow, ...)); run in the Release suite
#            only, in parallel with the rest
#   cli, render, python, blender, fuzz
#            the behaviour tests of the shells, pictures, the Python module, the Blender
#            add-on, and the fuzz corpora replayed
# A test that is not slow must finish inside ANIMKIT_TEST_TIMEOUT seconds: 60 in a Release
# build, ANIMKIT_SANITIZE_TIMEOUT_FACTOR times that under the sanitizers (the same code runs
# several times slower there). A test that grows past it fails until it is made faster or is
# labelled slow. tests/support/check_test_tiers.py checks that every test has a tier and a
# timeout within its tier's bound.
# https://cmake.org/cmake/help/v3.25/module/GoogleTest.html
include(GoogleTest)

set(ANIMKIT_SANITIZE_TIMEOUT_FACTOR 10)
set(ANIMKIT_TEST_TIMEOUT 60)
set(ANIMKIT_SLOW_TEST_TIMEOUT 1200)
if(ANIMKIT_SANITIZE)
  math(EXPR ANIMKIT_TEST_TIMEOUT "${ANIMKIT_TEST_TIMEOUT} * ${ANIMKIT_SANITIZE_TIMEOUT_FACTOR}")
  math(EXPR ANIMKIT_SLOW_TEST_TIMEOUT "${ANIMKIT_SLOW_TEST_TIMEOUT} * ${ANIMKIT_SANITIZE_TIMEOUT_FACTOR}")
endif()

set(ANIMKIT_SLOW_TEST_FILTER "*Slow.*")
# ctest -j starts the costliest tests first: the slow ones then run beside the many short
# ones instead of alone at the end (ctest's own timings replace this after the first run).
set(ANIMKIT_SLOW_TEST_COST 1000)
# The same for the few tests outside `slow` that run a whole scene or start Blender (tens of
# seconds, a minute under the sanitizers): on a fresh tree ctest knows no timings yet and starts
# tests in the order they were added, and these came last, so each suite ended with one of them
# running alone on one core (the sanitizer suite's last 69 s were example.cpp_drape_to_gltf;
# the Release suite's last 54 s blender.cloth_modal).
set(ANIMKIT_LONG_TEST_COST 100)

# One thread a test (OMP_NUM_THREADS, include/animkit/core/threads.h): ctest -j already gives
# every core a test, and a second thread per test only waits for a core
# (MultigridPcg.CouplingsInTheHierarchySaveIterations, two copies at once under the sanitizers,
# with OpenMP: 62 s each with two threads, 42 s with one). The results are the same bits for
# any thread count (tests/cloth/parallel_determinism_test.cpp, which sets its own counts and so
# still runs the loops on two threads).
set(ANIMKIT_TEST_THREADS ENVIRONMENT_MODIFICATION OMP_NUM_THREADS=set:1)

# Registers the GoogleTest tests of `target` under `label`, its *Slow suites under `slow`, each
# with its tier's timeout. Extra arguments are more test properties for both (ENVIRONMENT ...).
function(animkit_discover_tests target label)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 120 TEST_FILTER "-${ANIMKIT_SLOW_TEST_FILTER}"
                       PROPERTIES LABELS ${label} TIMEOUT ${ANIMKIT_TEST_TIMEOUT}
                                  ${ANIMKIT_TEST_THREADS} ${ARGN})
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 120 TEST_FILTER "${ANIMKIT_SLOW_TEST_FILTER}"
                       PROPERTIES LABELS slow TIMEOUT ${ANIMKIT_SLOW_TEST_TIMEOUT}
                                  COST ${ANIMKIT_SLOW_TEST_COST} ${ANIMKIT_TEST_THREADS} ${ARGN})
endfunction()

# Marks tests registered with add_test that take tens of seconds: ctest -j starts them early.
function(animkit_start_early)
  set_tests_properties(${ARGN} PROPERTIES COST ${ANIMKIT_LONG_TEST_COST})
endfunction()

# Labels the tests registered with add_test by name: `label` and its tier's timeout.
function(animkit_test_tier label)
  set(timeout ${ANIMKIT_TEST_TIMEOUT})
  if(label STREQUAL "slow")
    set(timeout ${ANIMKIT_SLOW_TEST_TIMEOUT})
  endif()
  set_tests_properties(${ARGN} PROPERTIES LABELS ${label} TIMEOUT ${timeout} ${ANIMKIT_TEST_THREADS})
endfunction()
