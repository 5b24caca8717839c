// SIGTERM and SIGINT as requests to stop a run gracefully: the first one is noted (the
// loop finishes its window, writes a checkpoint and exits with code 3); a second one
// kills the process at once (the default action is restored after the first).
#pragma once

namespace cortex {

class StopSignals {
 public:
  StopSignals();   // installs the handlers
  ~StopSignals();  // restores the previous ones
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  bool requested() const;
  int signal() const;  // the signal received, 0 if none
};

}  // namespace cortex
