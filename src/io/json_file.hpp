// A small JSON file that Granule wrote and reads back (a sweep point's record, a run's
// summary.json), read as untrusted input: every refusal is an InputError naming the file, the key
// and what is allowed, and ends with what the user can do about it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace granule {

class JsonFile {
 public:
  // The object in `path`; std::nullopt when there is no such file.  Refused: a path that is not a
  // readable file, a file over `max_bytes` (Granule's are far smaller, so no allocation is sized
  // by a damaged file), text that is not JSON, containers nested more than `max_depth` deep (the
  // top object is depth 1), or a top value that is not an object.  `remedy` ends every refusal.
  static std::optional<JsonFile> read(const std::filesystem::path& path, std::size_t max_bytes, int max_depth,
                                      std::string remedy);

  const nlohmann::json& json() const { return json_; }

  // The value of `key`, refused when it is missing or not what is asked.
  const std::string& string(const char* key) const;
  const std::string& one_of(const char* key, const std::vector<std::string>& allowed) const;
  std::int64_t integer(const char* key, std::int64_t low, std::int64_t high) const;
  // Finite, in [low, high]; a `high` of the largest double reads "a finite number >= LOW".
  double number(const char* key, double low, double high) const;

  // "PATH: "KEY" is VALUE, expected EXPECTED; REMEDY"
  [[noreturn]] void refuse(const char* key, const std::string& expected) const;

 private:
  JsonFile(std::filesystem::path path, nlohmann::json json, std::string remedy)
      : path_(std::move(path)), json_(std::move(json)), remedy_(std::move(remedy)) {}

  const nlohmann::json& value(const char* key, const std::string& expected) const;

  std::filesystem::path path_;
  nlohmann::json json_;
  std::string remedy_;
};

}  // namespace granule
