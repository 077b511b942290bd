// Typed, range-checked reading of a parsed TOML run configuration ("section.key" paths).  Every
// failure is a ConfigError whose message names the key, the value as written and what is allowed.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "io/input_ranges.hpp"

namespace granule {

// A validation failure: the message is complete ("key = value ...: allowed ...").
struct ConfigError {
  std::string message;
};

// The accepted keys of each section ("" is the top level).
using ConfigSchema = std::map<std::string, std::set<std::string>>;

class ConfigReader {
 public:
  explicit ConfigReader(const toml::table& root) : root_(root) {}

  // Unknown sections and keys, and sections that are not tables, are errors.
  void check_known_keys(const ConfigSchema& schema) const;

  bool has(const std::string& path) const { return find(path) != nullptr; }

  // A number (integer or float) in `range`; `why` is appended to the message.
  std::optional<double> number(const std::string& path, const NumberRange& range, const std::string& why = {}) const;
  // A finite number for which `allowed` holds, described by `allowed_text` in the message.
  std::optional<double> number_if(const std::string& path, const std::function<bool(double)>& allowed,
                                  const std::string& allowed_text) const;
  std::optional<std::int64_t> integer(const std::string& path, std::int64_t low, std::int64_t high) const;
  std::optional<std::string> text(const std::string& path, const std::set<std::string>& allowed) const;
  // A non-empty string (a file or directory path).
  std::optional<std::string> path_text(const std::string& path) const;
  // A list of exactly `count` numbers, each in `range`; `shape` names them in the message
  // ("[Lx, Ly, Lz]") and `why` is appended to it.
  std::optional<std::vector<double>> number_list(const std::string& path, std::size_t count, const NumberRange& range,
                                                 const std::string& shape, const std::string& why = {}) const;
  // Whether the value at `path` is a string (for keys that take a word or a list).
  bool holds_text(const std::string& path) const;
  // Whether the value at `path` is a list (for keys that take a number or a list).
  bool holds_list(const std::string& path) const;
  // A non-empty list of distinct strings, each among `allowed`; `why` is appended to the message.
  std::optional<std::vector<std::string>> text_list(const std::string& path, const std::set<std::string>& allowed,
                                                    const std::string& why = {}) const;
  std::optional<bool> boolean(const std::string& path) const;
  // A list of windows [[low, high], ...] with 0 ≤ low < high, both finite.
  std::vector<std::pair<double, double>> windows(const std::string& path) const;
  // [nx, ny], integers in [low, high].
  std::optional<std::pair<int, int>> int_pair(const std::string& path, int low, int high) const;
  // A list of points [[a, b], ...] of finite numbers (`what` names them in the message: "[t, U]").
  std::vector<std::pair<double, double>> number_pairs(const std::string& path, const std::string& what) const;
  // An inline table at `path` whose keys must be among `allowed`; false when absent.
  bool table_with_keys(const std::string& path, const std::set<std::string>& allowed) const;

 private:
  const toml::node* find(const std::string& path) const;
  const toml::table& root_;
};

// A value as the user wrote it, for messages: numbers in their shortest exact form ("0.8", not the
// 17 digits toml++ prints), strings in double quotes, lists in brackets, a table as "a table".
std::string toml_value_text(const toml::node& node);

// Applies `--set section.key=value` (the value is one TOML value; a bare word is a string).
void apply_override(toml::table& root, const std::string& assignment);

}  // namespace granule
