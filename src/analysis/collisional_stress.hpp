// The collisional stress field of thesis eq (1.6): in each cell, τ^(c) = σ/(V t) Σ J k̂ k̂ over the
// collisions whose contact point lies in the cell during an interval of length t (V the cell
// area).  Each collision moves momentum J k̂ across the contact over the distance σ (§1.4.3,
// after Allen & Tildesley §16.4).  Summed over all cells this is exactly the global collisional
// stress of the run's time series.
#pragma once

#include <vector>

#include "analysis/field_grid.hpp"
#include "engine/observer.hpp"
#include "engine/state_archive.hpp"

namespace granule {

struct CollisionalStress {
  std::vector<double> xx, xy, yy;  // per cell
  std::vector<double> collisions;  // collisions per cell in the interval
  double interval = 0.0;           // t: length of the averaging interval
};

class CollisionalStressField final : public EventObserver {
 public:
  CollisionalStressField(const FieldGrid& grid, double diameter);
  void on_collision(const CollisionRecord& record) override;
  // Start a new averaging interval at time t.
  void restart(double t);
  // The stress (1.6) over the interval [start, t].
  CollisionalStress stress(double t) const;
  double interval_start() const { return start_; }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  FieldGrid grid_;
  double diameter_;
  double start_ = 0.0;
  std::vector<double> sum_xx_, sum_xy_, sum_yy_, count_;
};

}  // namespace granule
