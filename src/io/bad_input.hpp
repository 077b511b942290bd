// Input that an analysis, an export or a picture refuses before it writes anything: a missing or
// foreign file, a frame out of range, a choice the file cannot serve.  The message names the file
// or the option and what is allowed; `granule` reports it and exits with code 2.
#pragma once

#include <stdexcept>

namespace granule {

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace granule
