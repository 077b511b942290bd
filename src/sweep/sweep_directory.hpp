// The files of a sweep under its output directory DIR (README.md, "Sweeps"): the spec it runs,
// the base configuration every point starts from, one run directory per point, one record and
// log per point, and results.csv.
#pragma once

#include <filesystem>
#include <string>

#include "io/io_error.hpp"
#include "sweep/sweep_spec.hpp"

namespace granule::sweep {

// Bad input to a sweep command (exit code 2): the message is complete and nothing was written.
struct BadSweepInput : InputError {
  using InputError::InputError;
};

struct SweepDirectory {
  std::filesystem::path root;

  std::filesystem::path spec() const { return root / "sweep.toml"; }        // the spec, normalised
  std::filesystem::path base_config() const { return root / "base.toml"; }  // the spec without [sweep]
  std::filesystem::path results() const { return root / "results.csv"; }
  // The point's `granule run --out` directory: its resolved config.toml and the usual outputs.
  std::filesystem::path run(const SweepPoint& p) const { return root / "runs" / p.name; }
  // How the point's last attempt ended (point_record.hpp) and what its runs printed.
  std::filesystem::path record(const SweepPoint& p) const { return root / "points" / (p.name + ".json"); }
  std::filesystem::path log(const SweepPoint& p) const { return root / "points" / (p.name + ".log"); }
};

// Creates DIR for `spec`, or accepts a DIR that already holds this very sweep (a restart, or
// another array task of it).  A DIR holding anything else is refused (BadSweepInput).
void prepare_sweep_directory(const SweepDirectory& dir, const SweepSpec& spec);

// The spec of the sweep in DIR (for --collect); BadSweepInput if DIR holds none.
SweepSpec sweep_in_directory(const SweepDirectory& dir);

}  // namespace granule::sweep
