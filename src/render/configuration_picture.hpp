// Pictures of a particle configuration (thesis Figs 2.2, 2.3, 3.4, 3.10): every disk drawn to scale
// in the box (y up), coloured by the direction of its velocity (the hue wheel of Fig 1.1's inset),
// by its speed, by its spin ω_z (rough grains, thesis Fig C.4) or by a coarse-grained cell field
// (analysis/named_cell_fields.hpp), with the coarse-grained velocity field V(r) of §1.4.3 drawn as
// arrows from the cell centres.  Disks crossing the box edges are drawn with their periodic /
// Lees–Edwards images (thesis §1.4.2), so a picture tiles like the system; flat walls (Fig C.5) are
// drawn as lines along the faces they stand on, fixed obstacles as grey disks with their images.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"
#include "analysis/named_cell_fields.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/system_params.hpp"
#include "render/raster_image.hpp"

namespace granule::render {

enum class DiskColoring { kDirection, kSpeed, kField, kSpin, kNone };

// "direction", "speed", "field", "spin", "none".
std::optional<DiskColoring> parse_disk_coloring(std::string_view name);

struct ConfigurationScene {
  const ParticleState& particles;  // lab frame, inside the box
  double diameter = 0.0;           // σ
  ShearFrame frame;                // box and Lees–Edwards shear velocity U
  double shear_offset = 0.0;       // Lees–Edwards image offset Δ ∈ [0, L_x)
  std::array<bool, 2> walls{};     // flat walls at both ends of x, of y (SystemParams::walls)
  // How far each wall (faces x0, x1, y0, y1) has moved into the box (a vibrated floor, a piston).
  std::array<double, 4> wall_shift{};
  std::vector<Obstacle> obstacles{};  // fixed obstacles, drawn grey (SystemParams::obstacles)
};

struct PictureOptions {
  int width_px = 1000;  // the height follows the box's aspect ratio
  DiskColoring coloring = DiskColoring::kDirection;
  std::string field = "density";  // the cell field of DiskColoring::kField
  // Lees–Edwards: colours and arrows from the velocity relative to the mean flow u(y) = γ (y − L_y/2).
  bool subtract_shear_profile = false;
  bool arrows = true;
  int cells_x = 0;  // coarse-graining grid of the arrows and field colours; 0: automatic
  int cells_y = 0;
  bool legend = true;
  // One line drawn in the top-left corner (a movie frame's time and c); empty: none.
  std::string caption;
  // Disks smaller than this radius on screen are drawn at it, so that dilute systems of 10^6
  // disks (σ well below a pixel) stay visible.
  double min_disk_radius_px = 0.6;
};

// Throws std::invalid_argument for an unknown field name, a width outside [16, 20000], or spin
// colours for smooth grains.
RasterImage render_configuration(const ConfigurationScene& scene, const PictureOptions& options);

}  // namespace granule::render
