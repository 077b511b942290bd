// The contents of a checkpoint: named arrays of numbers, each object of a run (the engine, the
// observers, the run's schedules) saving what determines its future under its own prefix.  Plain
// data, no I/O: io/checkpoint_file.hpp writes an archive to HDF5 and reads it back.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace granule {

class StateArchive {
 public:
  using Array = std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::int32_t>,
                             std::vector<std::uint32_t>, std::vector<std::uint8_t>>;
  // An array not copied into the archive: `fill(first, out)` writes its entries first, first + 1, ...
  // into `out`, block by block, when the archive is written.
  template <typename T>
  struct Producer {
    std::size_t size = 0;
    std::function<void(std::size_t first, std::span<T> out)> fill;
  };
  using DeferredArray = std::variant<Producer<double>, Producer<std::int64_t>, Producer<std::int32_t>,
                                     Producer<std::uint32_t>, Producer<std::uint8_t>>;

  StateArchive() = default;
  // An archive that keeps the large arrays (one entry per particle or per cell) as views of the
  // saved objects' own memory instead of copies, so that the checkpoint of 10^8 disks needs no
  // second copy of the state: it must be written (io/checkpoint_file.hpp) before any saved object
  // changes, and its large entries cannot be read back.
  static StateArchive streaming() {
    StateArchive archive;
    archive.streaming_ = true;
    return archive;
  }

  template <typename T>
  void put(const std::string& name, std::vector<T> values) {
    deferred_.erase(name);
    arrays_[name] = std::move(values);
  }
  // A large array that the caller keeps unchanged until the archive is written (see streaming()).
  template <typename T, typename Allocator>
  void put_view(const std::string& name, const std::vector<T, Allocator>& values) {
    put_generated<T>(name, values.size(), [&values](std::size_t first, std::span<T> out) {
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
    });
  }
  // A large array computed entry by entry (a field of the particle records, say).
  template <typename T, typename Fill>
  void put_generated(const std::string& name, std::size_t size, Fill fill) {
    if (!streaming_) {
      std::vector<T> values(size);
      fill(std::size_t{0}, std::span<T>(values));
      put(name, std::move(values));
      return;
    }
    arrays_.erase(name);
    deferred_[name] = Producer<T>{size, std::move(fill)};
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
    if (deferred_.count(name) > 0) throw std::logic_error("the streamed checkpoint entry " + name + " cannot be read");
    const auto found = arrays_.find(name);
    if (found == arrays_.end()) throw std::runtime_error("checkpoint has no entry " + name);
    const auto* values = std::get_if<std::vector<T>>(&found->second);
    if (!values) throw std::runtime_error("checkpoint entry " + name + " has an unexpected type");
    return *values;
  }
  double scalar(const std::string& name) const { return single(get<double>(name), name); }
  std::int64_t integer(const std::string& name) const { return single(get<std::int64_t>(name), name); }
  // A single integer that counts something (frames, collisions): never negative.
  std::int64_t count(const std::string& name) const {
    const std::int64_t value = integer(name);
    if (value < 0) throw std::runtime_error("checkpoint entry " + name + " is " + std::to_string(value) + ", not a count");
    return value;
  }
  bool contains(const std::string& name) const { return arrays_.count(name) > 0 || deferred_.count(name) > 0; }
  std::vector<std::vector<double>> rows(const std::string& name) const {
    const auto& flat = get<double>(name);
    const std::int64_t count = integer(name + "_rows");
    // Rows of at least one entry (a row count larger than the entries would come from a damaged file).
    if (count < 0 || static_cast<std::uint64_t>(count) > flat.size() ||
        (count == 0 ? !flat.empty() : flat.size() % static_cast<std::size_t>(count) != 0)) {
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
  const std::map<std::string, DeferredArray>& deferred() const { return deferred_; }

 private:
  template <typename T>
  static T single(const std::vector<T>& values, const std::string& name) {
    if (values.size() != 1) throw std::runtime_error("checkpoint entry " + name + " is not a single value");
    return values[0];
  }
  std::map<std::string, Array> arrays_;
  std::map<std::string, DeferredArray> deferred_;
  bool streaming_ = false;
};

}  // namespace granule
