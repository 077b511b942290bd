#include "io/json_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <system_error>

#include "io/io_error.hpp"

namespace granule {

namespace {

// A value as the user would see it in the file, cut short: a damaged file may hold anything.
std::string shown(const nlohmann::json& value) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

}  // namespace

std::optional<JsonFile> JsonFile::read(const std::filesystem::path& path, std::size_t max_bytes, int max_depth,
                                       std::string remedy) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) return std::nullopt;
  const auto refuse_file = [&](const std::string& why) {
    return InputError(fmt::format("{}: {}; {}", path.string(), why, remedy));
  };
  if (error || status.type() != std::filesystem::file_type::regular) throw refuse_file("not a readable file");
  std::ifstream file(path, std::ios::binary);
  std::string text(max_bytes + 1, '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (file.bad() || !file.is_open()) throw refuse_file("cannot be read");
  text.resize(static_cast<std::size_t>(file.gcount()));
  if (text.size() > max_bytes) throw refuse_file(fmt::format("larger than {} bytes", max_bytes));

  // Depth is watched while parsing, so that nothing downstream recurses into a hostile nesting.
  bool too_deep = false;
  const nlohmann::json::parser_callback_t watch_depth = [&](int depth, nlohmann::json::parse_event_t event,
                                                             nlohmann::json&) {
    const bool opens = event == nlohmann::json::parse_event_t::object_start ||
                       event == nlohmann::json::parse_event_t::array_start;
    if (opens && depth >= max_depth) too_deep = true;
    return !too_deep;
  };
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text, watch_depth);
  } catch (const nlohmann::json::exception& parse_error) {  // syntax, invalid UTF-8, a number out of range
    throw refuse_file(fmt::format("not JSON ({})", parse_error.what()));
  }
  if (too_deep) throw refuse_file(fmt::format("nested more than {} deep", max_depth));
  if (!json.is_object()) throw refuse_file("not a JSON object");
  return JsonFile(path, std::move(json), std::move(remedy));
}

void JsonFile::refuse(const char* key, const std::string& expected) const {
  const auto found = json_.find(key);
  const std::string value = found == json_.end() ? "missing" : "is " + shown(*found);
  throw InputError(fmt::format("{}: \"{}\" {}, expected {}; {}", path_.string(), key, value, expected, remedy_));
}

const nlohmann::json& JsonFile::value(const char* key, const std::string& expected) const {
  const auto found = json_.find(key);
  if (found == json_.end()) refuse(key, expected);
  return *found;
}

const std::string& JsonFile::string(const char* key) const {
  const nlohmann::json& v = value(key, "a string");
  if (!v.is_string()) refuse(key, "a string");
  return v.get_ref<const std::string&>();
}

const std::string& JsonFile::one_of(const char* key, const std::vector<std::string>& allowed) const {
  const std::string expected = fmt::format("one of \"{}\"", fmt::join(allowed, "\", \""));
  const nlohmann::json& v = value(key, expected);
  if (!v.is_string() || std::find(allowed.begin(), allowed.end(), v.get_ref<const std::string&>()) == allowed.end()) {
    refuse(key, expected);
  }
  return v.get_ref<const std::string&>();
}

std::int64_t JsonFile::integer(const char* key, std::int64_t low, std::int64_t high) const {
  const std::string expected = fmt::format("an integer in [{}, {}]", low, high);
  const nlohmann::json& v = value(key, expected);
  // JSON keeps integers above 2^63 − 1 as unsigned: those are out of any range asked here.
  if (!v.is_number_integer() || (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(high))) {
    refuse(key, expected);
  }
  const std::int64_t n = v.get<std::int64_t>();
  if (n < low || n > high) refuse(key, expected);
  return n;
}

double JsonFile::number(const char* key, double low, double high) const {
  const std::string expected = high == std::numeric_limits<double>::max()
                                   ? fmt::format("a finite number >= {}", low)
                                   : fmt::format("a number in [{}, {}]", low, high);
  const nlohmann::json& v = value(key, expected);
  if (!v.is_number()) refuse(key, expected);
  const double x = v.get<double>();
  if (!(std::isfinite(x) && x >= low && x <= high)) refuse(key, expected);
  return x;
}

}  // namespace granule
