// Density windows (thesis §3.2.2, §3.2.3, §5.2): statistics are collected separately for
// collisions or particles in cells whose density ρ lies in a window [low, high).  Windows may
// overlap; an item counts in every window that contains its density.
#pragma once

#include <vector>

#include "analysis/field_grid.hpp"
#include "archive/state_archive.hpp"
#include "geometry/vec.hpp"
#include "engine/state_blocks.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct DensityWindow {
  double low = 0.0;   // particles per unit area (2D) or volume (3D)
  double high = 0.0;
  bool contains(double density) const { return density >= low && density < high; }
};

// The cell number density field of the latest configuration (on the grid's 2D or 3D cells, per
// unit area or volume), looked up at collision points.  The run refreshes it at the start of every
// statistics window, so a collision is classified by the density of its cell at most one window
// earlier (one collision per particle by default).
class LocalDensity {
 public:
  explicit LocalDensity(const FieldGrid& grid) : grid_(grid), density_(grid.cells(), 0.0) {}
  // A configuration of the grid's dimension.
  void update(const StateBlocks& state) {
    std::fill(density_.begin(), density_.end(), 0.0);
    state.for_each([&](const ParticleState& s, std::size_t) {
      for (std::size_t i = 0; i < s.size(); ++i) {
        density_[grid_.dimension == 3 ? grid_.index(s.x[i], s.y[i], s.z[i]) : grid_.index(s.x[i], s.y[i])] += 1.0;
      }
    });
    for (double& d : density_) d /= grid_.cell_volume();
  }
  double at(double x, double y) const { return density_[grid_.index(x, y)]; }
  double at(double x, double y, double z) const { return density_[grid_.index(x, y, z)]; }
  // At a point of the grid's dimension.
  double at(const Vec2& p) const { return at(p.x, p.y); }
  double at(const Vec3& p) const { return at(p.x, p.y, p.z); }
  const FieldGrid& grid() const { return grid_; }
  void save(StateArchive& archive, const std::string& prefix) const { archive.put(prefix + "density", density_); }
  void restore(const StateArchive& archive, const std::string& prefix) {
    density_ = archive.get_sized<double>(prefix + "density", grid_.cells());
  }

 private:
  FieldGrid grid_;
  std::vector<double> density_;
};

}  // namespace granule
