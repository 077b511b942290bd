// The two exceptions of Granule's files.  IoError: a file Granule writes could not be created,
// written, flushed, synced, closed or renamed (disk full); `granule` exits with code 4.
// InputError: input that an analysis, an export, a picture or a run refuses before it writes
// anything — a file that is missing, unreadable, damaged, foreign or not what its schema says, a
// frame out of range, a choice the file cannot serve; `granule` exits with code 2.  Both messages
// name the file, and InputError the dataset, attribute or option and what is allowed.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>

namespace granule {

class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "<what>: <strerror(error_number)>", or just `what` when the system gave no reason (0).
inline IoError io_error(const std::string& what, int error_number) {
  return IoError(error_number != 0 ? what + ": " + std::strerror(error_number) : what);
}

}  // namespace granule
