#include "analysis/free_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
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

}  // namespace

FreePathStatistics::FreePathStatistics(std::int64_t particles, FreePathSettings settings, const LocalDensity* density)
    : settings_(std::move(settings)),
      length_{0.0, settings_.max_length, settings_.length_bins},
      angle_{0.0, 2.0 * std::numbers::pi, settings_.angle_bins},
      density_(density),
      last_(static_cast<std::size_t>(particles), LastCollision{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}),
      total_(empty_histogram(settings_)),
      by_density_(settings_.density_windows.size(), empty_histogram(settings_)),
      by_speed_(settings_.speed_windows.size(), empty_histogram(settings_)) {}

void FreePathStatistics::on_collision(const CollisionRecord& r) {
  record_path(r.first, r.time, r.contact_point, r.first_velocity_after);
  record_path(r.second, r.time, r.contact_point, r.second_velocity_after);
}

void FreePathStatistics::record_path(std::int32_t disk, double time, Vec2 end, Vec2 velocity_after) {
  const auto i = static_cast<std::size_t>(disk);
  LastCollision& last = last_[i];
  if (recording_ && !std::isnan(last.t)) {
    const double dt = time - last.t;
    const Vec2 v{last.vx, last.vy};
    const double speed = std::sqrt(v.x * v.x + v.y * v.y);
    const double length = speed * dt;
    double alpha = std::atan2(v.y, v.x);
    if (alpha < 0.0) alpha += 2.0 * std::numbers::pi;
    const int a = std::max(0, angle_.bin(alpha));  // α = 2π after rounding: the first bin
    const int l = length_.bin(length);
    add(total_, l, a, settings_.angle_bins, length, speed);
    if (density_ != nullptr) {
      const double rho = density_->at(end.x, end.y);
      for (std::size_t w = 0; w < by_density_.size(); ++w) {
        if (settings_.density_windows[w].contains(rho)) add(by_density_[w], l, a, settings_.angle_bins, length, speed);
      }
    }
    for (std::size_t w = 0; w < by_speed_.size(); ++w) {
      if (settings_.speed_windows[w].contains(speed)) add(by_speed_[w], l, a, settings_.angle_bins, length, speed);
    }
  }
  last = {time, velocity_after.x, velocity_after.y};
}

}  // namespace granule
