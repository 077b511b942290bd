// Free paths before collision (thesis §3.2.3): at each collision, for each of the two particles,
// the path vector l since that particle's previous collision, l = v (t − t_prev) with v its
// velocity after that collision (a straight flight; across a Lees–Edwards boundary the flight
// continues straight in the image frame it started in), its speed v = |v| and the density ρ of the
// cell where the path ends.  Accumulated as the histogram of (l, angle) that estimates
// P̃(l, α; v, ρ) of (3.22), globally, inside density windows and inside speed windows, plus exact
// sums for the mean free path.  The angle is, for disks, α ∈ [0, 2π) of l from the streamwise (x)
// direction (the thesis's); for spheres, cos θ ∈ [−1, 1] with θ the polar angle of l from the
// streamwise axis: uniform for isotropic flights (the solid angle is 2π d(cos θ)), so that a
// streamwise alignment shows as weight near ±1 as α₀ of (3.24) shows it in 2D.
// The length range starts at `max_length` and, unless fixed (`widen` false), doubles (neighbouring
// bins merged pairwise, which is exact) whenever a longer path arrives, so that no path is lost to overflow: lab-frame paths of a
// sheared run carry the mean flow and reach tens of mean free paths, a range fixed in advance
// dropped 17–35 % of them.  Only a path beyond 2⁶⁰ times the starting range is overflow.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/density_windows.hpp"
#include "analysis/histogram.hpp"
#include "engine/observer.hpp"
#include "archive/state_archive.hpp"

namespace granule {

struct SpeedWindow {
  double low = 0.0, high = 0.0;
  bool contains(double v) const { return v >= low && v < high; }
};

// A joint histogram of path length and angle, row-major (length bin, angle bin), plus the paths
// longer than the last length bin (per angle bin) and exact moments.
struct PathHistogram {
  std::vector<double> counts;    // length_bins × angle_bins
  std::vector<double> overflow;  // angle_bins: paths beyond the range (a fixed one, or the widest)
  double paths = 0.0;
  double sum_length = 0.0;
  double sum_length_squared = 0.0;
  double sum_speed = 0.0;
};

struct FreePathSettings {
  int length_bins = 100;
  int angle_bins = 72;
  double max_length = 1.0;  // starting range of the lengths
  bool widen = true;        // double the range as needed (false: a fixed range, longer paths overflow)
  std::vector<DensityWindow> density_windows;
  std::vector<SpeedWindow> speed_windows;
};

// The angle bins of free paths in d dimensions: α on [0, 2π) (d = 2), cos θ on [−1, 1] (d = 3).
UniformBins free_path_angle_bins(int dimension, int bins);

template <int D>
class FreePathStatistics final : public EventObserver<D> {
 public:
  FreePathStatistics(std::int64_t particles, FreePathSettings settings, const LocalDensity* density);
  void on_collision(const CollisionRecord<D>& record) override;
  // Only paths ending after start() are recorded; paths that began before it are (their start
  // is known from the disks' earlier collisions).
  void start() { recording_ = true; }

  const FreePathSettings& settings() const { return settings_; }
  const UniformBins& length_bins() const { return length_; }  // the current range
  int range_doublings() const { return range_doublings_; }
  double dropped_fraction() const;  // of all recorded paths, those in overflow
  const UniformBins& angle_bins() const { return angle_; }
  const PathHistogram& total() const { return total_; }
  const std::vector<PathHistogram>& by_density() const { return by_density_; }
  const std::vector<PathHistogram>& by_speed() const { return by_speed_; }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  void record_path(std::int32_t particle, double time, const Vec<D>& end, const Vec<D>& velocity_after);
  // The angle bin of a flight's velocity (α in 2D, cos θ in 3D).
  int angle_bin(const Vec<D>& velocity, double speed) const;
  // Doubles the length range until `length` lies inside it (at most kMaxRangeDoublings in all).
  void widen_to(double length);
  static constexpr int kMaxRangeDoublings = 60;

  FreePathSettings settings_;
  UniformBins length_, angle_;
  int range_doublings_ = 0;
  const LocalDensity* density_;
  bool recording_ = false;
  // Each particle's last collision: one record per particle so that a collision touches one
  // cache line per particle.  t is NaN until the particle's first collision is seen.
  struct LastCollision {
    double t;
    Vec<D> v;  // velocity after it
  };
  std::vector<LastCollision> last_;
  PathHistogram total_;
  std::vector<PathHistogram> by_density_, by_speed_;
};

}  // namespace granule
