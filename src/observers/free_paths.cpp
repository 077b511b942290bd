#include "observers/free_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>
#include <utility>

namespace granule {

namespace {

PathHistogram empty_histogram(const FreePathSettings& s) {
  PathHistogram h;
  h.counts.assign(static_cast<std::size_t>(s.length_bins) * static_cast<std::size_t>(s.angle_bins), 0.0);
  h.overflow.assign(static_cast<std::size_t>(s.angle_bins), 0.0);
  return h;
}

void add(PathHistogram& h, int length_bin, int angle_bin, int angle_bins, double length, double speed) {
  const auto a = static_cast<std::size_t>(angle_bin);
  if (length_bin < 0) {
    h.overflow[a] += 1.0;
  } else {
    h.counts[static_cast<std::size_t>(length_bin) * static_cast<std::size_t>(angle_bins) + a] += 1.0;
  }
  h.paths += 1.0;
  h.sum_length += length;
  h.sum_length_squared += length * length;
  h.sum_speed += speed;
}

// The histogram on bins twice as wide: new bin b holds old bins 2b and 2b + 1 (a path in [l_b, l_b+1)
// stays in the new bin that contains that interval), the upper half is empty.
void merge_length_pairs(PathHistogram& h, int length_bins, int angle_bins) {
  const auto width = static_cast<std::size_t>(angle_bins);
  std::vector<double> merged(h.counts.size(), 0.0);
  for (std::size_t old = 0; old < static_cast<std::size_t>(length_bins); ++old) {
    for (std::size_t a = 0; a < width; ++a) merged[(old / 2) * width + a] += h.counts[old * width + a];
  }
  h.counts = std::move(merged);
}

}  // namespace

UniformBins free_path_angle_bins(int dimension, int bins) {
  return dimension == 3 ? UniformBins{-1.0, 1.0, bins} : UniformBins{0.0, 2.0 * std::numbers::pi, bins};
}

template <int D>
FreePathStatistics<D>::FreePathStatistics(std::int64_t particles, FreePathSettings settings, const LocalDensity* density)
    : settings_(std::move(settings)),
      length_{0.0, settings_.max_length, settings_.length_bins},
      angle_(free_path_angle_bins(D, settings_.angle_bins)),
      density_(density),
      last_(static_cast<std::size_t>(particles), LastCollision{std::numeric_limits<double>::quiet_NaN(), Vec<D>{}}),
      total_(empty_histogram(settings_)),
      by_density_(settings_.density_windows.size(), empty_histogram(settings_)),
      by_speed_(settings_.speed_windows.size(), empty_histogram(settings_)) {}

template <int D>
void FreePathStatistics<D>::on_collision(const CollisionRecord<D>& r) {
  record_path(r.first, r.time, r.contact_point, r.first_velocity_after);
  record_path(r.second, r.time, r.contact_point, r.second_velocity_after);
}

template <int D>
int FreePathStatistics<D>::angle_bin(const Vec<D>& v, double speed) const {
  if constexpr (D == 2) {
    double alpha = std::atan2(v.y, v.x);
    if (alpha < 0.0) alpha += 2.0 * std::numbers::pi;
    return std::max(0, angle_.bin(alpha));  // α = 2π after rounding: the first bin
  } else {
    const double cos_theta = v.x / speed;
    return cos_theta >= 1.0 ? angle_.bins - 1 : std::max(0, angle_.bin(cos_theta));  // a flight at rest: the first bin
  }
}

template <int D>
void FreePathStatistics<D>::record_path(std::int32_t particle, double time, const Vec<D>& end, const Vec<D>& velocity_after) {
  const auto i = static_cast<std::size_t>(particle);
  LastCollision& last = last_[i];
  if (recording_ && !std::isnan(last.t)) {
    const double dt = time - last.t;
    const Vec<D> v = last.v;
    const double speed = std::sqrt(norm2(v));
    const double length = speed * dt;
    const int a = angle_bin(v, speed);
    if (settings_.widen && length >= length_.high) widen_to(length);
    const int l = length_.bin(length);
    add(total_, l, a, settings_.angle_bins, length, speed);
    if (density_ != nullptr) {
      const double rho = density_->at(end);
      for (std::size_t w = 0; w < by_density_.size(); ++w) {
        if (settings_.density_windows[w].contains(rho)) add(by_density_[w], l, a, settings_.angle_bins, length, speed);
      }
    }
    for (std::size_t w = 0; w < by_speed_.size(); ++w) {
      if (settings_.speed_windows[w].contains(speed)) add(by_speed_[w], l, a, settings_.angle_bins, length, speed);
    }
  }
  last = {time, velocity_after};
}

template <int D>
void FreePathStatistics<D>::widen_to(double length) {
  while (length >= length_.high && range_doublings_ < kMaxRangeDoublings) {
    merge_length_pairs(total_, length_.bins, settings_.angle_bins);
    for (auto* list : {&by_density_, &by_speed_}) {
      for (PathHistogram& h : *list) merge_length_pairs(h, length_.bins, settings_.angle_bins);
    }
    length_.high *= 2.0;
    ++range_doublings_;
  }
}

template <int D>
double FreePathStatistics<D>::dropped_fraction() const {
  double dropped = 0.0;
  for (const double count : total_.overflow) dropped += count;
  return total_.paths > 0.0 ? dropped / total_.paths : 0.0;
}

namespace {
// A histogram's fields, in one list for saving and restoring.
template <typename Histogram, typename Visit>
void for_each_part(Histogram& h, Visit&& visit) {
  visit("counts", h.counts);
  visit("overflow", h.overflow);
  visit("paths", h.paths);
  visit("sum_length", h.sum_length);
  visit("sum_length_squared", h.sum_length_squared);
  visit("sum_speed", h.sum_speed);
}

void save_histograms(StateArchive& archive, const std::string& prefix, const std::vector<PathHistogram>& list) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    for_each_part(list[k], [&](const char* name, const auto& value) {
      if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) {
        archive.put_scalar(prefix + std::to_string(k) + "/" + name, value);
      } else {
        archive.put(prefix + std::to_string(k) + "/" + name, value);
      }
    });
  }
}

void restore_histograms(const StateArchive& archive, const std::string& prefix, std::vector<PathHistogram>& list) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    for_each_part(list[k], [&](const char* name, auto& value) {
      if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) {
        value = archive.scalar(prefix + std::to_string(k) + "/" + name);
      } else {
        value = archive.get_sized<double>(prefix + std::to_string(k) + "/" + name, value.size());
      }
    });
  }
}
}  // namespace

// The name of the saved last collisions: t and the velocity after, per particle.
constexpr const char* kLastCollisionName[] = {"", "", "last_collision_t_vx_vy", "last_collision_t_vx_vy_vz"};

template <int D>
void FreePathStatistics<D>::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_integer(prefix + "recording", recording_ ? 1 : 0);
  archive.put_integer(prefix + "length_range_doublings", range_doublings_);
  std::vector<double> last;
  last.reserve((D + 1) * last_.size());
  for (const LastCollision& c : last_) {
    last.push_back(c.t);
    for (int a = 0; a < D; ++a) last.push_back(c.v[a]);
  }
  archive.put(prefix + kLastCollisionName[D], std::move(last));
  save_histograms(archive, prefix + "total/", {total_});
  save_histograms(archive, prefix + "by_density/", by_density_);
  save_histograms(archive, prefix + "by_speed/", by_speed_);
}

template <int D>
void FreePathStatistics<D>::restore(const StateArchive& archive, const std::string& prefix) {
  recording_ = archive.integer(prefix + "recording") != 0;
  // Checkpoints written before the range could widen have none: their range is the starting one.
  const std::string doublings = prefix + "length_range_doublings";
  range_doublings_ = archive.contains(doublings) ? static_cast<int>(archive.integer(doublings)) : 0;
  length_.high = std::ldexp(settings_.max_length, range_doublings_);
  const auto& last = archive.get_sized<double>(prefix + kLastCollisionName[D], (D + 1) * last_.size());
  for (std::size_t i = 0; i < last_.size(); ++i) {
    last_[i].t = last[(D + 1) * i];
    for (int a = 0; a < D; ++a) last_[i].v[a] = last[(D + 1) * i + 1 + static_cast<std::size_t>(a)];
  }
  std::vector<PathHistogram> total{total_};
  restore_histograms(archive, prefix + "total/", total);
  total_ = total[0];
  restore_histograms(archive, prefix + "by_density/", by_density_);
  restore_histograms(archive, prefix + "by_speed/", by_speed_);
}

template class FreePathStatistics<2>;
template class FreePathStatistics<3>;

}  // namespace granule
