#include "observers/impact_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace granule {

namespace {
// |k̂ × v|² / |v|² = sin² of the angle between k̂ and v: (b/σ)², without the cancellation of
// 1 − (k̂·v̂)² near head-on contacts.
double squared_sine(const Vec3& k, const Vec3& v) {
  const Vec3 c{k.y * v.z - k.z * v.y, k.z * v.x - k.x * v.z, k.x * v.y - k.y * v.x};
  return norm2(c) / norm2(v);
}
}  // namespace

template <int D>
double impact_parameter(const CollisionRecord<D>& r, double diameter) {
  const Vec<D> k = r.contact_normal, v = r.relative_velocity;
  if constexpr (D == 2) {
    return diameter * std::abs(k.x * v.y - k.y * v.x) / std::sqrt(v.x * v.x + v.y * v.y);
  } else {
    return diameter * std::sqrt(squared_sine(k, v));
  }
}

template <int D>
double uniform_impact_variable(const CollisionRecord<D>& r, double diameter) {
  if constexpr (D == 2) {
    return impact_parameter(r, diameter) / diameter;
  } else {
    return squared_sine(r.contact_normal, r.relative_velocity);
  }
}

template <int D>
ImpactParameterStatistics<D>::ImpactParameterStatistics(std::optional<double> diameter, int bins, std::int64_t window_collisions,
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

template <int D>
void ImpactParameterStatistics<D>::on_collision(const CollisionRecord<D>& r) {
  if (open_.collisions == 0) open_.t_start = r.time;
  // b = σ exactly (a perfectly grazing contact) belongs to the last bin.
  const double x = uniform_impact_variable(r, diameter_.value_or(r.contact_distance));
  const int k = x >= 1.0 ? bins_.bins - 1 : bins_.bin(x);
  if (k >= 0) {
    const auto bin = static_cast<std::size_t>(k);
    open_.counts[bin] += 1.0;
    total_[bin] += 1.0;
    if (density_ != nullptr) {
      const double rho = density_->at(r.contact_point);
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

template <int D>
void ImpactParameterStatistics<D>::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<ImpactParameterWindow> all = windows_;
  all.push_back(open_);  // the open window last
  std::vector<double> t_start, t_end;
  std::vector<std::int64_t> collisions;
  std::vector<std::vector<double>> counts;
  for (const ImpactParameterWindow& w : all) {
    t_start.push_back(w.t_start);
    t_end.push_back(w.t_end);
    collisions.push_back(w.collisions);
    counts.push_back(w.counts);
  }
  archive.put(prefix + "window_t_start", std::move(t_start));
  archive.put(prefix + "window_t_end", std::move(t_end));
  archive.put(prefix + "window_collisions", std::move(collisions));
  archive.put_rows(prefix + "window_counts", counts);
  archive.put(prefix + "total", total_);
  archive.put_rows(prefix + "by_density", by_density_);
}

template <int D>
void ImpactParameterStatistics<D>::restore(const StateArchive& archive, const std::string& prefix) {
  const auto bins = static_cast<std::size_t>(bins_.bins);
  const auto counts = archive.rows(prefix + "window_counts");
  const auto& t_start = archive.get_sized<double>(prefix + "window_t_start", counts.size());
  const auto& t_end = archive.get_sized<double>(prefix + "window_t_end", counts.size());
  const auto& collisions = archive.get_sized<std::int64_t>(prefix + "window_collisions", counts.size());
  if (counts.empty() || counts[0].size() != bins) throw std::runtime_error("checkpoint impact-parameter windows do not fit the bins");
  windows_.clear();
  for (std::size_t w = 0; w < counts.size(); ++w) windows_.push_back({t_start[w], t_end[w], collisions[w], counts[w]});
  open_ = windows_.back();
  windows_.pop_back();
  total_ = archive.get_sized<double>(prefix + "total", bins);
  by_density_ = archive.rows(prefix + "by_density");
  if (by_density_.size() != density_windows_.size()) throw std::runtime_error("checkpoint density windows do not fit the configuration");
}

template double impact_parameter(const CollisionRecord<2>&, double);
template double impact_parameter(const CollisionRecord<3>&, double);
template double uniform_impact_variable(const CollisionRecord<2>&, double);
template double uniform_impact_variable(const CollisionRecord<3>&, double);
template class ImpactParameterStatistics<2>;
template class ImpactParameterStatistics<3>;

}  // namespace granule
