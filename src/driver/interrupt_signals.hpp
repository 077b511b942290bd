// SIGINT and SIGTERM during a run: the first one raises a flag that the engine checks before each
// event, so the run stops after a whole event, writes its checkpoint and outputs, and exits with
// 128 + the signal number; a second one ends the process at once (the default action).
#pragma once

#include <csignal>

namespace granule::driver {

class InterruptSignals {
 public:
  InterruptSignals();   // installs the handlers
  ~InterruptSignals();  // restores the previous ones
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;

  // Non-zero once a signal arrived: the signal number.
  static const volatile std::sig_atomic_t* flag();
  static int received() { return *flag(); }
};

}  // namespace granule::driver
