// Exit codes of the granule command (README.md, "Exit codes").
#pragma once

#include <string>

namespace granule::app {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitInternalError = 1;   // a bug: reported, never an abort
inline constexpr int kExitBadInput = 2;        // config, command line, resume mismatch: nothing written
inline constexpr int kExitCollapse = 3;        // the run stopped on inelastic collapse: outputs written
inline constexpr int kExitIoError = 4;         // an output could not be written: nothing incomplete published
inline constexpr int kExitOutOfMemory = 5;     // refused before the run, or memory ran out during it
inline constexpr int kExitSweepIncomplete = 6; // granule sweep: some points failed or did not run; the others' results written
inline constexpr int kExitInterruptedBase = 128;  // + the signal (130 SIGINT, 143 SIGTERM): checkpoint written

// A failure a command reports with its exit code (the message is complete).
struct CommandFailure {
  int code;
  std::string message;
};

}  // namespace granule::app
