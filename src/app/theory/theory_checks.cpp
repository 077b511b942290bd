#include "app/theory/theory_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

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

void require_finite(const CLI::App& command, const std::vector<std::string>& names, const std::vector<double>& values) {
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (!std::isfinite(values[j])) {
      refuse(command, fmt::format("these options give {} = {}, beyond double precision: bring them nearer to "
                                  "ordinary values", names[j], values[j]));
    }
  }
}

}  // namespace granule::app::theory_checks
