// Impact parameters b = σ |k̂ × v₁₂| / |v₁₂| of thesis eq (3.19) (Fig 1.3): b = 0 is a head-on
// collision, b = σ a grazing one.  Recorded over consecutive windows of W collisions (the thesis
// uses W = N, §2.3, Fig 2.16) and accumulated over the whole measurement, globally and inside
// density windows (Fig 3.30).  Isotropic molecular chaos gives the uniform distribution on [0, σ].
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/density_windows.hpp"
#include "analysis/histogram.hpp"
#include "engine/observer.hpp"
#include "engine/state_archive.hpp"

namespace granule {

double impact_parameter(const CollisionRecord<2>& record, double diameter);

struct ImpactParameterWindow {
  double t_start = 0.0, t_end = 0.0;
  std::int64_t collisions = 0;
  std::vector<double> counts;  // per bin of b/σ
};

class ImpactParameterStatistics final : public EventObserver<2> {
 public:
  // `density` (may be null: no density windows) is refreshed by the caller at each window start.
  ImpactParameterStatistics(double diameter, int bins, std::int64_t window_collisions,
                            std::vector<DensityWindow> density_windows, const LocalDensity* density);
  void on_collision(const CollisionRecord<2>& record) override;

  const UniformBins& bins() const { return bins_; }  // of b/σ on [0, 1]
  const std::vector<ImpactParameterWindow>& windows() const { return windows_; }  // closed windows
  const std::vector<double>& total() const { return total_; }
  const std::vector<std::vector<double>>& by_density() const { return by_density_; }
  const std::vector<DensityWindow>& density_windows() const { return density_windows_; }
  std::int64_t window_collisions() const { return window_collisions_; }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  double diameter_;
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
