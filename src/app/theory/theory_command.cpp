#include "app/theory/theory_command.hpp"

#include "app/theory/theory_subcommands.hpp"

namespace granule::app {

void add_theory_command(CLI::App& root) {
  auto* theory = root.add_subcommand(
      "theory", "Kinetic-theory predictions of Tan (1995): cooling, stability, steady shear");
  theory->require_subcommand(1);
  add_cooling_theory(*theory);
  add_shear_theory(*theory);
  add_shear_start(*theory);
}

}  // namespace granule::app
