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

// A command line that cannot be read: an unknown option, or one without the value it needs. Front ends
// exit with status 2 for it (1 for every other Error), as command-line tools conventionally do.
class UsageError : public Error {
  public:
    using Error::Error;
};

}  // namespace fp
