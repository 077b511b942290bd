#include "analysis/collisional_stress.hpp"

#include <algorithm>

namespace granule {

CollisionalStressField::CollisionalStressField(const FieldGrid& grid, double diameter)
    : grid_(grid), diameter_(diameter), sum_xx_(grid.cells()), sum_xy_(grid.cells()), sum_yy_(grid.cells()),
      count_(grid.cells()) {}

void CollisionalStressField::on_collision(const CollisionRecord& r) {
  const std::size_t c = grid_.index(r.contact_point.x, r.contact_point.y);
  const double j = r.impulse;
  const Vec2 k = r.contact_normal;
  sum_xx_[c] += j * k.x * k.x;
  sum_xy_[c] += j * k.x * k.y;
  sum_yy_[c] += j * k.y * k.y;
  count_[c] += 1.0;
}

void CollisionalStressField::restart(double t) {
  start_ = t;
  for (auto* v : {&sum_xx_, &sum_xy_, &sum_yy_, &count_}) std::fill(v->begin(), v->end(), 0.0);
}

CollisionalStress CollisionalStressField::stress(double t) const {
  CollisionalStress out{sum_xx_, sum_xy_, sum_yy_, count_, t - start_};
  const double scale = out.interval > 0.0 ? diameter_ / (grid_.cell_area() * out.interval) : 0.0;
  for (auto* v : {&out.xx, &out.xy, &out.yy}) {
    for (double& x : *v) x *= scale;
  }
  return out;
}

void CollisionalStressField::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "start", start_);
  archive.put(prefix + "sum_xx", sum_xx_);
  archive.put(prefix + "sum_xy", sum_xy_);
  archive.put(prefix + "sum_yy", sum_yy_);
  archive.put(prefix + "count", count_);
}

void CollisionalStressField::restore(const StateArchive& archive, const std::string& prefix) {
  start_ = archive.scalar(prefix + "start");
  sum_xx_ = archive.get_sized<double>(prefix + "sum_xx", grid_.cells());
  sum_xy_ = archive.get_sized<double>(prefix + "sum_xy", grid_.cells());
  sum_yy_ = archive.get_sized<double>(prefix + "sum_yy", grid_.cells());
  count_ = archive.get_sized<double>(prefix + "count", grid_.cells());
}

}  // namespace granule
