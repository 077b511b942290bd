// Option checks shared by the `granule theory` subcommands, and how they print a prediction
// (theory/prediction_table.hpp).  Every numeric option is checked before anything is printed: a
// value outside the range its formulas hold in (NaN, ±∞, e = 2, a negative length) is bad input,
// exit 2, with a message naming the option and the range.  Lengths, speeds and rates share the
// ranges of `granule run` (io/input_ranges.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "init/initial_state.hpp"
#include "io/input_ranges.hpp"
#include "theory/prediction_table.hpp"

namespace granule::app::theory_checks {

// ε = 1 − e² > 0: the cooling and steady-shear formulas divide by ε (e = 1 neither cools nor
// reaches a steady sheared state).
inline constexpr NumberRange kDissipativeRestitution{0.0, 1.0, true, true};
inline constexpr NumberRange kInelasticity{0.0, 1.0, true, false};
inline constexpr NumberRange kAreaFraction{0.0, kClosePacking, true, true};
inline constexpr NumberRange kParticles{2.0, 2147483647.0};
inline constexpr NumberRange kPoints{1.0, 10000.0};

// Prints "granule theory <command>: error: <message>" and ends the command with exit 2.
[[noreturn]] void refuse(const CLI::App& command, const std::string& message);

void require(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
             const std::string& why = {});

// An option whose default means "not given" (derived from the others): checked only when given.
void require_if_given(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
                      const std::string& why = {});

// Aligned columns with `# ` summary lines above them, or CSV.  Refuses (exit 2) a table whose
// derived values or rows hold an infinite or NaN value, before printing anything.
void print_table(const CLI::App& command, const theory::PredictionTable& table, bool csv);

}  // namespace granule::app::theory_checks
