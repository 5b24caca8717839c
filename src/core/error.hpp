// The two kinds of failure the program distinguishes, mapped to exit codes by app/.
#pragma once

#include <stdexcept>
#include <string>

namespace cortex {

// Bad input: a config key, a mesh file, an impossible parameter. Exit code 2.
// The message names the file, the key (or line) and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A failure during the run (NaN forces, a diverging energy). Exit code 1.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A stop request (a signal) that abandons the window in progress, which went on too long
// to be finished first: the run ends with exit code 3 like any stop, keeping its last
// checkpoint, from which a resume redoes the abandoned window.
class RunStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cortex
