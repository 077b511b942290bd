#include "app/analyze/analyze_command.hpp"

namespace granule::app {

void add_analyze_command(CLI::App& root) {
  CLI::App* analyze = root.add_subcommand("analyze", "Measure from the saved outputs of a run (snapshots.h5)");
  analyze->require_subcommand(1);
  add_analyze_fields(*analyze);
  add_analyze_collisions(*analyze);
  add_analyze_spectra(*analyze);
  add_analyze_f1(*analyze);
  add_analyze_spins(*analyze);
}

}  // namespace granule::app
