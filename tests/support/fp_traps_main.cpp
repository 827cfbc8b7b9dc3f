// Test runner entry point that traps floating-point exceptions: an invalid operation (NaN
// produced), a division by zero or an overflow anywhere in a test aborts it with SIGFPE.
#include <fenv.h>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
  return RUN_ALL_TESTS();
}
