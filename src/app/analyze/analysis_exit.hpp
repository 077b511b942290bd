// How every `granule analyze` command ends (README, "Exit codes"): a refused input says why on
// stderr and writes nothing (exit 2); a file that cannot be written and memory that runs out go to
// main (exits 4 and 5); any other failure is reported (exit 1).
#pragma once

#include <fmt/format.h>

#include <new>
#include <string>
#include <string_view>

#include "app/exit_codes.hpp"
#include "io/io_error.hpp"

namespace granule::app {

// "granule analyze ANALYSIS: error: MESSAGE" on stderr; kExitBadInput.
inline int refuse_analysis_input(std::string_view analysis, const std::string& message) {
  fmt::print(stderr, "granule analyze {}: error: {}\n", analysis, message);
  return kExitBadInput;
}

// The exit code of `body` (the analysis proper, after its inputs were checked), or of the failure
// it throws: a damaged or malformed input (InputError) refused, nothing written.
template <typename Body>
int run_analysis(std::string_view analysis, Body&& body) {
  try {
    return body();
  } catch (const InputError& refused) {
    return refuse_analysis_input(analysis, refused.what());
  } catch (const IoError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& failure) {
    fmt::print(stderr, "granule analyze {}: error: {}\n", analysis, failure.what());
    return kExitInternalError;
  }
}

}  // namespace granule::app
