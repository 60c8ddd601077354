#pragma once
// Error types. Input errors are the user's to fix and carry a message that names the key,
// the value and what is allowed; numerical errors name the step where things went wrong.
#include <stdexcept>
#include <string>

namespace picdem::core {

/// Bad input: case file, command line, checkpoint file. The message is shown as is.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical failure during a run (linear solver breakdown, NaN, blown-up step).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace picdem::core
