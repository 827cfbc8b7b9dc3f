// AddressSanitizer's defaults for the test programs (the ANIMKIT_SANITIZE tree): ASan reads
// them before ASAN_OPTIONS, which still overrides them.
// https://github.com/google/sanitizers/wiki/AddressSanitizerFlags
//
// detect_stack_use_after_return=0: clang 15 turned this check on by default; it moves every
// function's stack locals onto a heap-like fake stack, and this code's many small Eigen
// temporaries made the suite's contact and solver tests about 30% slower for it
// (Aerodynamics.WindBlowsAFlagDownwind: 33.6 s with it, 23.5 s without, one run each, same
// build). The test programs run without it, as GCC's ASan and clang before 15 did; the fuzz
// targets, the CLI and the viewer the tests start keep clang's default, and the compilers warn
// about a returned address of a local (-Wreturn-stack-address, -Wreturn-local-addr).
extern "C" const char* __asan_default_options() {  // NOLINT(readability-identifier-naming)
  return "detect_stack_use_after_return=0";
}
