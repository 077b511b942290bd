// The contents of a checkpoint: named arrays of numbers, each object of a run (the engine, the
// observers, the run's schedules) saving what determines its future under its own prefix.  Plain
// data, no I/O: io/checkpoint_file.hpp writes an archive to HDF5 and reads it back.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace granule {

class StateArchive {
 public:
  using Array = std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::int32_t>,
                             std::vector<std::uint32_t>, std::vector<std::uint8_t>>;

  template <typename T>
  void put(const std::string& name, std::vector<T> values) {
    arrays_[name] = std::move(values);
  }
  void put_scalar(const std::string& name, double value) { put(name, std::vector<double>{value}); }
  void put_integer(const std::string& name, std::int64_t value) { put(name, std::vector<std::int64_t>{value}); }
  // Rows of equal length (histograms per window), stored end to end.
  void put_rows(const std::string& name, const std::vector<std::vector<double>>& rows) {
    std::vector<double> flat;
    for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
    put(name, std::move(flat));
    put_integer(name + "_rows", static_cast<std::int64_t>(rows.size()));
  }

  // Throws std::runtime_error naming the entry when it is missing or of another type.
  template <typename T>
  const std::vector<T>& get(const std::string& name) const {
    const auto found = arrays_.find(name);
    if (found == arrays_.end()) throw std::runtime_error("checkpoint has no entry " + name);
    const auto* values = std::get_if<std::vector<T>>(&found->second);
    if (!values) throw std::runtime_error("checkpoint entry " + name + " has an unexpected type");
    return *values;
  }
  double scalar(const std::string& name) const { return single(get<double>(name), name); }
  std::int64_t integer(const std::string& name) const { return single(get<std::int64_t>(name), name); }
  bool contains(const std::string& name) const { return arrays_.count(name) > 0; }
  std::vector<std::vector<double>> rows(const std::string& name) const {
    const auto& flat = get<double>(name);
    const std::int64_t count = integer(name + "_rows");
    if (count < 0 || (count == 0 ? !flat.empty() : flat.size() % static_cast<std::size_t>(count) != 0)) {
      throw std::runtime_error("checkpoint entry " + name + " does not hold whole rows");
    }
    const std::size_t length = count == 0 ? 0 : flat.size() / static_cast<std::size_t>(count);
    std::vector<std::vector<double>> out;
    for (std::int64_t r = 0; r < count; ++r) {
      const auto begin = flat.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(r) * length);
      out.emplace_back(begin, begin + static_cast<std::ptrdiff_t>(length));
    }
    return out;
  }
  // An array that must have `size` entries, as the object restoring it was configured.
  template <typename T>
  const std::vector<T>& get_sized(const std::string& name, std::size_t size) const {
    const auto& values = get<T>(name);
    if (values.size() != size) throw std::runtime_error("checkpoint entry " + name + " has the wrong length");
    return values;
  }

  const std::map<std::string, Array>& arrays() const { return arrays_; }
  std::map<std::string, Array>& arrays() { return arrays_; }

 private:
  template <typename T>
  static T single(const std::vector<T>& values, const std::string& name) {
    if (values.size() != 1) throw std::runtime_error("checkpoint entry " + name + " is not a single value");
    return values[0];
  }
  std::map<std::string, Array> arrays_;
};

}  // namespace granule
