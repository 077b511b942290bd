// What the flat walls of a run took and gave over a sampling interval, per wall face
// 2·axis + side (side 0 at coordinate 0, side 1 at L_axis), from the wall collision records:
//  • pressure: the normal momentum the wall took per unit wall area per unit time (> 0: pushed out);
//  • shear stress: the tangential momentum it took along the flow axis x per unit area per unit
//    time (along y for the x walls);
//  • heat input: the energy it gave the gas (translational plus rotational) per unit area per unit
//    time (> 0 when a moving or rough wall heats the gas, < 0 when an inelastic wall cools it);
//  • collisions: the number of wall collisions in the interval.
// The wall area is L_other in 2D (a line), L_other1 · L_other2 in 3D.
// Grains at rest (physics/rest_rule.hpp) bear on the floor — the wall gravity pushes towards —
// through the bed they stand on: their weight, and the momentum the hits on them take, are the
// floor's, so that its pressure stays the weight of the grains above it as with every grain moving.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "engine/observer.hpp"
#include "archive/state_archive.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct WallFaceSample {
  double pressure = 0.0;
  double shear_stress = 0.0;
  double heat_input = 0.0;
  double collisions = 0.0;
};

// The columns of one face, named wall_<axis><side>_<quantity> (e.g. wall_y0_pressure).
template <typename Face, typename Visit>
void for_each_wall_column(int face, Face& f, Visit&& visit) {
  static constexpr const char* kNames[6][4] = {
      {"wall_x0_pressure", "wall_x0_shear_stress", "wall_x0_heat_input", "wall_x0_collisions"},
      {"wall_x1_pressure", "wall_x1_shear_stress", "wall_x1_heat_input", "wall_x1_collisions"},
      {"wall_y0_pressure", "wall_y0_shear_stress", "wall_y0_heat_input", "wall_y0_collisions"},
      {"wall_y1_pressure", "wall_y1_shear_stress", "wall_y1_heat_input", "wall_y1_collisions"},
      {"wall_z0_pressure", "wall_z0_shear_stress", "wall_z0_heat_input", "wall_z0_collisions"},
      {"wall_z1_pressure", "wall_z1_shear_stress", "wall_z1_heat_input", "wall_z1_collisions"}};
  visit(kNames[face][0], f.pressure);
  visit(kNames[face][1], f.shear_stress);
  visit(kNames[face][2], f.heat_input);
  visit(kNames[face][3], f.collisions);
}

// The tangential axis whose momentum is the wall shear stress: x, or y for the x walls.
inline int wall_shear_axis(int wall_axis) { return wall_axis == 0 ? 1 : 0; }

template <int D>
class WallStress {
 public:
  explicit WallStress(const SystemParams& params);
  // A hit of a wall, or of a grain at rest (the floor's; other surfaces' hits are not its business).
  void add(const SurfaceHitRecord<D>& record);
  // A grain that came to rest or was woken: its weight bears on the floor while it rests.
  void add(const RestRecord<D>& record);
  // The faces with a wall (the others stay empty) over the interval of length dt > 0 ending at t.
  std::array<std::optional<WallFaceSample>, 6> sample(double t, double dt) const;
  // Start a new interval at t.
  void clear(double t) {
    sums_ = {};
    weight_impulse_ = 0.0;
    weight_since_ = t;
  }
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix);

 private:
  struct FaceSums {
    double normal = 0.0, tangential = 0.0, energy = 0.0, collisions = 0.0;
  };
  std::array<bool, 6> present_{};
  std::array<double, 6> area_{};
  std::array<FaceSums, 6> sums_{};
  // The floor (−1: none, or no grain may rest) and g along its outward normal; the mass at rest,
  // and ∫ m_rest g_n dt over the interval up to weight_since_.
  int floor_ = -1;
  double floor_gravity_ = 0.0;
  double resting_mass_ = 0.0;
  double weight_impulse_ = 0.0;
  double weight_since_ = 0.0;
};

}  // namespace granule
