// What `granule run` says on the console about the run it starts and the files it wrote: the
// configuration in words (io/config_description.hpp), where it came from, the pre-run, and at the
// end every file the invocation wrote.
#pragma once

#include <filesystem>
#include <string>

#include "io/config.hpp"

namespace granule::app {

// The opening lines of a run; `built_in_example` when no CONFIG was given, with `overrides` --set.
void print_header(const RunConfig& config, bool built_in_example, std::size_t overrides);

// "files written in OUT: a, b, …": every regular file under `out` (paths relative to it, sorted)
// modified since `since`.
std::string files_written_text(const std::string& out, std::filesystem::file_time_type since);

}  // namespace granule::app
