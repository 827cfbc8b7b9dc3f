#pragma once
// strtod signals overflow ("1e999") by raising the floating-point overflow flag on purpose;
// held while a parser runs, so a caller that traps floating-point exceptions (the tests do)
// gets an error value, not SIGFPE.
#include <cfenv>

namespace animkit {

class HeldFloatingPointExceptions {
 public:
  HeldFloatingPointExceptions() { std::feholdexcept(&saved_); }
  ~HeldFloatingPointExceptions() { std::fesetenv(&saved_); }
  HeldFloatingPointExceptions(const HeldFloatingPointExceptions&) = delete;
  HeldFloatingPointExceptions& operator=(const HeldFloatingPointExceptions&) = delete;

 private:
  std::fenv_t saved_;
};

}  // namespace animkit
