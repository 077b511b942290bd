// Impact parameters b = σ |k̂ × v₁₂| / |v₁₂| of thesis eq (3.19) (Fig 1.3): the distance of closest
// approach of the straight relative trajectory, b = 0 a head-on collision, b = σ a grazing one
// (σ = σ_ij in a polydisperse run).  Recorded over consecutive windows of W collisions (the thesis
// uses W = N, §2.3, Fig 2.16) and accumulated over the whole measurement, globally and inside
// density windows (Fig 3.30).  The histogrammed variable is the one uniform on [0, 1] under
// isotropic molecular chaos: b/σ for disks (a partner is met anywhere on a strip of width 2σ,
// §3.2.2), (b/σ)² for spheres (anywhere on a disk of radius σ: the rate at b is ∝ 2πb db).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "analysis/density_windows.hpp"
#include "analysis/histogram.hpp"
#include "engine/observer.hpp"
#include "archive/state_archive.hpp"

namespace granule {

template <int D>
double impact_parameter(const CollisionRecord<D>& record, double diameter);
// b/σ in 2D, (b/σ)² in 3D: uniform on [0, 1] under molecular chaos (header).
template <int D>
double uniform_impact_variable(const CollisionRecord<D>& record, double diameter);

struct ImpactParameterWindow {
  double t_start = 0.0, t_end = 0.0;
  std::int64_t collisions = 0;
  std::vector<double> counts;  // per bin of b/σ
};

template <int D>
class ImpactParameterStatistics final : public EventObserver<D> {
 public:
  // `diameter`: σ of a monodisperse run, or none (polydisperse): each collision's σ_ij.
  // `density` (may be null: no density windows) is refreshed by the caller at each window start.
  ImpactParameterStatistics(std::optional<double> diameter, int bins, std::int64_t window_collisions,
                            std::vector<DensityWindow> density_windows, const LocalDensity* density);
  void on_collision(const CollisionRecord<D>& record) override;

  const UniformBins& bins() const { return bins_; }  // of uniform_impact_variable on [0, 1]
  const std::vector<ImpactParameterWindow>& windows() const { return windows_; }  // closed windows
  const std::vector<double>& total() const { return total_; }
  const std::vector<std::vector<double>>& by_density() const { return by_density_; }
  const std::vector<DensityWindow>& density_windows() const { return density_windows_; }
  std::int64_t window_collisions() const { return window_collisions_; }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  std::optional<double> diameter_;
  UniformBins bins_;
  std::int64_t window_collisions_;
  std::vector<DensityWindow> density_windows_;
  const LocalDensity* density_;
  ImpactParameterWindow open_;
  std::vector<ImpactParameterWindow> windows_;
  std::vector<double> total_;
  std::vector<std::vector<double>> by_density_;
};

}  // namespace granule
