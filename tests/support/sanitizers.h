#pragma once
// Whether this test binary runs under AddressSanitizer (the ANIMKIT_SANITIZE build, `make
// test-sanitize`), where the same code runs about 20 times slower than in Release (the tree IK
// property checks: 206 s against 11 s). GCC defines
// __SANITIZE_ADDRESS__ under -fsanitize=address; Clang answers __has_feature.
// https://gcc.gnu.org/onlinedocs/cpp/Common-Predefined-Macros.html

namespace animkit::test_support {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

// The number of random trials of a property test: all of them in Release, a tenth (at least
// one) under the sanitizers. Those look for memory errors and undefined behaviour along the
// code paths the trials take, which a tenth of the trials already takes; the Release run keeps
// the statistics whole.
constexpr int trials_for_this_build(int release_trials) {
  if (!kUnderSanitizers) return release_trials;
  return release_trials >= 10 ? release_trials / 10 : 1;
}

}  // namespace animkit::test_support
