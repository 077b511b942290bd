// The one exception for a failed input/output operation on a file Granule writes (cannot create,
// write, flush, sync, close or rename it; disk full).  `granule` reports it and exits with code 4;
// its message names the file and what failed, with the system's reason when there is one.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>

namespace granule {

class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "<what>: <strerror(error_number)>", or just `what` when the system gave no reason (0).
inline IoError io_error(const std::string& what, int error_number) {
  return IoError(error_number != 0 ? what + ": " + std::strerror(error_number) : what);
}

}  // namespace granule
