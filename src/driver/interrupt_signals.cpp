#include "driver/interrupt_signals.hpp"

namespace granule::driver {

namespace {

volatile std::sig_atomic_t received_signal = 0;
struct sigaction previous_int, previous_term;

extern "C" void on_signal(int number) {
  received_signal = number;
  // The next one takes the default action: a user who presses Ctrl-C twice means it.
  std::signal(number, SIG_DFL);
}

}  // namespace

InterruptSignals::InterruptSignals() {
  received_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  // Restart interrupted system calls: a signal arriving while an output is being written must not
  // turn into a write error (EINTR).
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

InterruptSignals::~InterruptSignals() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

const volatile std::sig_atomic_t* InterruptSignals::flag() { return &received_signal; }

}  // namespace granule::driver
