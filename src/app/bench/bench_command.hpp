// `granule bench`: fixed workloads timed on one core (collisions per second, bytes per particle).
#pragma once

#include <CLI/CLI.hpp>

namespace granule::app {

void add_bench_command(CLI::App& root);

}  // namespace granule::app
