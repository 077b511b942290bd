#include "analysis/impact_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace granule {

double impact_parameter(const CollisionRecord& r, double diameter) {
  const Vec2 k = r.contact_normal, v = r.relative_velocity;
  return diameter * std::abs(k.x * v.y - k.y * v.x) / std::sqrt(v.x * v.x + v.y * v.y);
}

ImpactParameterStatistics::ImpactParameterStatistics(double diameter, int bins, std::int64_t window_collisions,
                                                     std::vector<DensityWindow> density_windows,
                                                     const LocalDensity* density)
    : diameter_(diameter),
      bins_{0.0, 1.0, bins},
      window_collisions_(window_collisions),
      density_windows_(std::move(density_windows)),
      density_(density),
      total_(static_cast<std::size_t>(bins)),
      by_density_(density_windows_.size(), std::vector<double>(static_cast<std::size_t>(bins))) {
  open_.counts.assign(static_cast<std::size_t>(bins), 0.0);
}

void ImpactParameterStatistics::on_collision(const CollisionRecord& r) {
  if (open_.collisions == 0) open_.t_start = r.time;
  // b = σ exactly (a perfectly grazing contact) belongs to the last bin.
  const double x = impact_parameter(r, diameter_) / diameter_;
  const int k = x >= 1.0 ? bins_.bins - 1 : bins_.bin(x);
  if (k >= 0) {
    const auto bin = static_cast<std::size_t>(k);
    open_.counts[bin] += 1.0;
    total_[bin] += 1.0;
    if (density_ != nullptr) {
      const double rho = density_->at(r.contact_point.x, r.contact_point.y);
      for (std::size_t w = 0; w < density_windows_.size(); ++w) {
        if (density_windows_[w].contains(rho)) by_density_[w][bin] += 1.0;
      }
    }
  }
  open_.t_end = r.time;
  if (++open_.collisions == window_collisions_) {
    windows_.push_back(open_);
    open_.collisions = 0;
    std::fill(open_.counts.begin(), open_.counts.end(), 0.0);
  }
}

}  // namespace granule
