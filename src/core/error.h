#pragma once
// The one exception type for problems the user can fix (bad input files, bad flags, no GL context).
// Front ends catch it, print its message and exit non-zero; anything else escaping is a bug.
#include <stdexcept>
#include <string>

namespace fp {

class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace fp
