// A point's summary.json (the one its run wrote, README.md "summary.json"), read back by the sweep
// to learn how a run whose record is missing ended and to fill results.csv: as untrusted as every
// file Granule reads.
#pragma once

#include <optional>

#include "io/json_file.hpp"
#include "sweep/sweep_directory.hpp"

namespace granule::sweep {

// std::nullopt when the point's run has written no summary.  A summary that is not a JSON object
// of the size and nesting a run writes is refused (InputError), telling to delete the run
// directory to run the point again.
std::optional<JsonFile> read_point_summary(const SweepDirectory& dir, const SweepPoint& point);

}  // namespace granule::sweep
