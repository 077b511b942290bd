// The grains at rest (physics/rest_rule.hpp) as the moving grains of each cell see them: fixed
// spheres, listed as obstacles are (boundary/obstacle_lists.hpp) in every cell whose box comes
// within their radius plus the largest grain radius of their centre, once per periodic image that
// does.  Unlike the obstacles' they change during a run: a grain is added when it comes to rest and
// removed when it is woken.  Within a cell they are kept in the order of their centres, so that the
// search, whose ties go to the first, does not depend on the order in which grains came to rest
// nor on the engine's numbering: a run resumed from a checkpoint rebuilds the same lists.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "boundary/obstacle_lists.hpp"
#include "geometry/vec.hpp"

namespace granule {

template <int D>
class RestingGrains {
 public:
  RestingGrains() = default;
  // Lists for the cells of `grid`; `images[a]`: whether axis a is periodic; `lengths`: the box.
  RestingGrains(const CellLayout& grid, const std::array<bool, 3>& images, const std::array<double, 3>& lengths,
                double largest_grain_radius)
      : grid_(grid),
        images_(images),
        lengths_(lengths),
        largest_grain_radius_(largest_grain_radius),
        tolerance_(round_surface_tolerance(lengths, D)),
        lists_(static_cast<std::size_t>(grid.cells())) {}

  // Grain `particle` of radius `radius`, at rest at `centre` (inside the box).
  void add(std::int32_t particle, const Vec<D>& centre, double radius) {
    for_each_listing(centre, radius, [&](std::vector<RoundSurface<D>>& list, const Vec<D>& image) {
      const RoundSurface<D> entry{particle, image, radius};
      list.insert(std::upper_bound(list.begin(), list.end(), entry, centre_order), entry);
    });
    ++count_;
  }
  // The same grain, listed by add() with the same centre and radius, woken.
  void remove(std::int32_t particle, const Vec<D>& centre, double radius) {
    for_each_listing(centre, radius, [&](std::vector<RoundSurface<D>>& list, const Vec<D>&) {
      std::erase_if(list, [&](const RoundSurface<D>& entry) { return entry.index == particle; });
    });
    --count_;
  }
  void clear() {
    for (auto& list : lists_) list.clear();
    count_ = 0;
  }
  // The engine's numbers changed: grain k is now destination[k].
  void renumber(const std::vector<std::int32_t>& destination) {
    for (auto& list : lists_) {
      for (RoundSurface<D>& entry : list) entry.index = destination[static_cast<std::size_t>(entry.index)];
    }
  }
  std::span<const RoundSurface<D>> in_cell(std::int32_t cell) const {
    if (lists_.empty()) return {};
    return lists_[static_cast<std::size_t>(cell)];
  }
  std::int64_t count() const { return count_; }
  double tolerance() const { return tolerance_; }
  std::size_t bytes() const {
    std::size_t total = lists_.capacity() * sizeof(std::vector<RoundSurface<D>>);
    for (const auto& list : lists_) total += list.capacity() * sizeof(RoundSurface<D>);
    return total;
  }

 private:
  static bool centre_order(const RoundSurface<D>& a, const RoundSurface<D>& b) {
    for (int k = D - 1; k >= 0; --k) {
      if (a.centre[k] != b.centre[k]) return a.centre[k] < b.centre[k];
    }
    return false;
  }
  template <typename Visit>
  void for_each_listing(const Vec<D>& centre, double radius, Visit&& visit) {
    for_each_periodic_image<D>(centre, images_, lengths_, [&](const Vec<D>& image) {
      for_each_cell_within<D>(image, radius + largest_grain_radius_, grid_,
                              [&](std::int32_t cell) { visit(lists_[static_cast<std::size_t>(cell)], image); });
    });
  }

  CellLayout grid_;
  std::array<bool, 3> images_{};
  std::array<double, 3> lengths_{};
  double largest_grain_radius_ = 0.0;
  double tolerance_ = 0.0;
  std::vector<std::vector<RoundSurface<D>>> lists_;  // empty: no grain ever rests
  std::int64_t count_ = 0;
};

}  // namespace granule
