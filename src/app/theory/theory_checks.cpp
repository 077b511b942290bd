#include "app/theory/theory_checks.hpp"

#include <fmt/format.h>

#include "app/exit_codes.hpp"

namespace granule::app::theory_checks {

[[noreturn]] void refuse(const CLI::App& command, const std::string& message) {
  fmt::print(stderr, "granule theory {}: error: {}\n", command.get_name(), message);
  throw CLI::RuntimeError(kExitBadInput);
}

void require(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
             const std::string& why) {
  if (!range.contains(value)) refuse(command, fmt::format("{} = {} is out of range: allowed {}{}", option, value, range.text(), why));
}

void require_if_given(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
                      const std::string& why) {
  if (command.count(option) > 0) require(command, option, value, range, why);
}

void print_table(const CLI::App& command, const theory::PredictionTable& table, bool csv) {
  if (const auto entry = theory::first_non_finite(table)) {
    refuse(command, fmt::format("these options give {} = {}, beyond double precision: bring them nearer to ordinary values",
                                entry->name, entry->value));
  }
  fmt::print("{}", csv ? theory::table_csv(table) : theory::table_text(table));
}

}  // namespace granule::app::theory_checks
