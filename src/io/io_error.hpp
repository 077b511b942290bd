// The two exceptions of Granule's files.  IoError: a file Granule writes could not be created,
// written, flushed, synced, closed or renamed (disk full); `granule` exits with code 4.
// InputError: a file Granule reads is missing, unreadable, damaged or not what its schema says;
// `granule` refuses it with code 2, before anything is written.  Both messages name the file, and
// InputError the dataset or attribute and what was expected.
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
