#include "render/configuration_picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "render/color_scales.hpp"
#include "render/picture_legend.hpp"

namespace granule::render {

namespace {

constexpr int kMinWidth = 16;
constexpr int kMaxWidth = 20000;

// Box coordinates → pixels (y up in the box, down on the picture).
struct PixelMap {
  double scale_x, scale_y, height;
  double px(double x) const { return x * scale_x; }
  double py(double y) const { return height - y * scale_y; }
};

// Value at the fraction `q` of a sample (nth element), used for robust colour ranges.
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

// Each disk's colour, from its velocity (relative to the mean shear flow if asked) or its cell.
std::vector<Rgb> disk_colors(const ConfigurationScene& scene, const PictureOptions& options, const CellFields& fields,
                             double& low, double& high) {
  const ParticleState& p = scene.particles;
  std::vector<Rgb> colors(p.size());
  const auto vx = [&](std::size_t i) {
    return p.vx[i] - (options.subtract_shear_profile ? scene.frame.mean_flow(p.y[i]) : 0.0);
  };
  switch (options.coloring) {
    case DiskColoring::kDirection:
      for (std::size_t i = 0; i < p.size(); ++i) colors[i] = direction_color(std::atan2(p.vy[i], vx(i)));
      break;
    case DiskColoring::kSpeed: {
      std::vector<double> speed(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) speed[i] = std::hypot(vx(i), p.vy[i]);
      // The 99th percentile as the top of the scale: one fast disk does not wash out the picture.
      low = 0.0;
      high = quantile(speed, 0.99);
      for (std::size_t i = 0; i < p.size(); ++i) colors[i] = sequential_color(high > 0.0 ? speed[i] / high : 0.0);
      break;
    }
    case DiskColoring::kSpin: {
      // Centred on 0, ± the 99th percentile of |ω_z|: one fast spinner does not wash out the picture.
      std::vector<double> magnitude(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) magnitude[i] = std::abs(p.wz[i]);
      high = quantile(magnitude, 0.99);
      low = -high;
      for (std::size_t i = 0; i < p.size(); ++i) colors[i] = diverging_color(high > 0.0 ? p.wz[i] / high : 0.0);
      break;
    }
    case DiskColoring::kField: {
      const std::vector<double>& values = *cell_field_by_name(fields, options.field);
      const auto [min, max] = std::minmax_element(values.begin(), values.end());
      low = *min;
      high = *max;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double v = values[fields.grid.index(p.x[i], p.y[i])];
        colors[i] = sequential_color(high > low ? (v - low) / (high - low) : 0.5);
      }
      break;
    }
    case DiskColoring::kNone:
      std::fill(colors.begin(), colors.end(), Rgb{0.15, 0.15, 0.15});
      break;
  }
  return colors;
}

// A disk and those of its periodic / Lees–Edwards images (thesis §1.4.2) that reach into the box:
// the image above sits at x + Δ, the one below at x − Δ.
template <typename Draw>
void for_each_visible_image(double x, double y, double radius, const ConfigurationScene& scene, Draw&& draw) {
  const double lx = scene.frame.length_x, ly = scene.frame.length_y;
  if (x >= radius && x <= lx - radius && y >= radius && y <= ly - radius) {
    draw(x, y);
    return;
  }
  for (int iy = -1; iy <= 1; ++iy) {
    double xi = x + iy * scene.shear_offset;
    xi -= lx * std::floor(xi / lx);
    const double yi = y + iy * ly;
    if (yi + radius <= 0.0 || yi - radius >= ly) continue;
    for (int ix = -1; ix <= 1; ++ix) {
      const double xs = xi + ix * lx;
      if (xs + radius > 0.0 && xs - radius < lx) draw(xs, yi);
    }
  }
}

void draw_arrows(cairo_t* cr, const CellFields& fields, const PixelMap& map, double line_width) {
  const FieldGrid& g = fields.grid;
  double longest = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    if (fields.count[c] > 0.0) longest = std::max(longest, std::hypot(fields.velocity_x[c], fields.velocity_y[c]));
  }
  if (longest <= 0.0) return;
  // The longest arrow spans 90% of a cell; the others in proportion to |V|.
  const double cell_px = std::min(g.cell_width() * map.scale_x, g.cell_height() * map.scale_y);
  const double px_per_velocity = 0.9 * cell_px / longest;
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, line_width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (int iy = 0; iy < g.ny; ++iy) {
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t c = static_cast<std::size_t>(ix) + static_cast<std::size_t>(iy) * static_cast<std::size_t>(g.nx);
      if (fields.count[c] <= 0.0) continue;
      const double x0 = map.px(g.center_x(ix)), y0 = map.py(g.center_y(iy));
      const double dx = fields.velocity_x[c] * px_per_velocity, dy = -fields.velocity_y[c] * px_per_velocity;
      const double length = std::hypot(dx, dy);
      if (length < 0.5) continue;
      cairo_move_to(cr, x0, y0);
      cairo_line_to(cr, x0 + dx, y0 + dy);
      // Head: two strokes at ±25° back from the tip, 30% of the arrow (at least two line widths).
      const double head = std::max(0.3 * length, 2.0 * line_width);
      const double angle = std::atan2(dy, dx);
      for (double side : {-1.0, 1.0}) {
        const double a = angle + std::numbers::pi - side * 25.0 * std::numbers::pi / 180.0;
        cairo_move_to(cr, x0 + dx, y0 + dy);
        cairo_line_to(cr, x0 + dx + head * std::cos(a), y0 + dy + head * std::sin(a));
      }
      cairo_stroke(cr);
    }
  }
}

void draw_legend(cairo_t* cr, const PictureOptions& options, int width, double low, double high) {
  const double size = std::max(18.0, width / 14.0);  // legend scale in pixels
  switch (options.coloring) {
    case DiskColoring::kDirection:
      draw_direction_wheel(cr, width - 1.35 * size, 1.35 * size, size);
      break;
    case DiskColoring::kSpeed:
    case DiskColoring::kField: {
      const std::string label = options.coloring == DiskColoring::kSpeed
                                    ? (options.subtract_shear_profile ? "speed relative to u(y)" : "speed")
                                    : options.field;
      const double bar_width = 3.0 * size, bar_height = 0.3 * size;
      draw_color_bar(cr, width - bar_width - 0.6 * size, 1.0 * size, bar_width, bar_height, low, high, label.c_str(),
                     sequential_color);
      break;
    }
    case DiskColoring::kSpin: {
      const double bar_width = 3.0 * size, bar_height = 0.3 * size;
      draw_color_bar(cr, width - bar_width - 0.6 * size, 1.0 * size, bar_width, bar_height, low, high, "spin ω_z",
                     [](double u) { return diverging_color(2.0 * u - 1.0); });
      break;
    }
    case DiskColoring::kNone:
      break;
  }
}

// The walls as black lines where they stand (2 px at least, so that they show beside touching
// disks); a wall that has moved into the box leaves the space behind it grey.
void draw_walls(cairo_t* cr, const ConfigurationScene& scene, const PixelMap& map, double line_width) {
  const double lx = scene.frame.length_x, ly = scene.frame.length_y;
  const auto shift = [&](int face) { return scene.wall_shift[static_cast<std::size_t>(face)]; };
  cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
  for (int axis = 0; axis < 2; ++axis) {
    if (!scene.walls[static_cast<std::size_t>(axis)]) continue;
    const double length = axis == 0 ? lx : ly;
    for (const auto& [from, to] : {std::pair{0.0, shift(2 * axis)}, std::pair{length - shift(2 * axis + 1), length}}) {
      if (!(to > from)) continue;
      const double x0 = axis == 0 ? from : 0.0, x1 = axis == 0 ? to : lx;
      const double y0 = axis == 1 ? from : 0.0, y1 = axis == 1 ? to : ly;
      cairo_rectangle(cr, map.px(x0), map.py(y1), map.px(x1) - map.px(x0), map.py(y0) - map.py(y1));
      cairo_fill(cr);
    }
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, line_width);
  for (int side = 0; side < 2; ++side) {
    if (scene.walls[0]) {
      const double x = side == 0 ? shift(0) : lx - shift(1);
      cairo_move_to(cr, map.px(x), map.py(0.0));
      cairo_line_to(cr, map.px(x), map.py(ly));
    }
    if (scene.walls[1]) {
      const double y = side == 0 ? shift(2) : ly - shift(3);
      cairo_move_to(cr, map.px(0.0), map.py(y));
      cairo_line_to(cr, map.px(lx), map.py(y));
    }
  }
  cairo_stroke(cr);
}

}  // namespace

std::optional<DiskColoring> parse_disk_coloring(std::string_view name) {
  if (name == "direction") return DiskColoring::kDirection;
  if (name == "speed") return DiskColoring::kSpeed;
  if (name == "field") return DiskColoring::kField;
  if (name == "spin") return DiskColoring::kSpin;
  if (name == "none") return DiskColoring::kNone;
  return std::nullopt;
}

RasterImage render_configuration(const ConfigurationScene& scene, const PictureOptions& options) {
  if (options.width_px < kMinWidth || options.width_px > kMaxWidth) {
    throw std::invalid_argument("width " + std::to_string(options.width_px) + " px is outside [16, 20000]");
  }
  if (options.coloring == DiskColoring::kField && cell_field_names().end() ==
      std::find(cell_field_names().begin(), cell_field_names().end(), options.field)) {
    throw std::invalid_argument("unknown cell field '" + options.field + "'");
  }
  if (options.coloring == DiskColoring::kSpin && !scene.particles.rough()) {
    throw std::invalid_argument("spin colours need rough grains (this configuration has no spins)");
  }
  const ShearFrame& frame = scene.frame;
  const int width = options.width_px;
  const int height = std::max(1, static_cast<int>(std::lround(width * frame.length_y / frame.length_x)));
  const PixelMap map{width / frame.length_x, height / frame.length_y, static_cast<double>(height)};

  FieldGrid grid = automatic_picture_grid(static_cast<std::int64_t>(scene.particles.size()), frame.length_x, frame.length_y);
  if (options.cells_x > 0 && options.cells_y > 0) grid = {options.cells_x, options.cells_y, frame.length_x, frame.length_y};
  CellMoments moments(grid);
  moments.add(scene.particles, frame, options.subtract_shear_profile);
  const CellFields fields = fields_from_moments(moments, frame, scene.shear_offset, options.subtract_shear_profile);
  double low = 0.0, high = 0.0;
  const std::vector<Rgb> colors = disk_colors(scene, options, fields, low, high);

  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  const double radius_px = std::max(0.5 * scene.diameter * map.scale_x, options.min_disk_radius_px);
  const double radius_box = radius_px / map.scale_x;
  const ParticleState& p = scene.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    cairo_set_source_rgb(cr, colors[i].r, colors[i].g, colors[i].b);
    for_each_visible_image(p.x[i], p.y[i], radius_box, scene, [&](double x, double y) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, map.px(x), map.py(y), radius_px, 0.0, 2.0 * std::numbers::pi);
    });
    cairo_fill(cr);
  }
  if (scene.walls[0] || scene.walls[1]) draw_walls(cr, scene, map, std::max(2.0, width / 400.0));
  cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
  for (const Obstacle& obstacle : scene.obstacles) {
    const double radius = 0.5 * obstacle.diameter;
    for_each_visible_image(obstacle.centre[0], obstacle.centre[1], radius, scene, [&](double x, double y) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, map.px(x), map.py(y), radius * map.scale_x, 0.0, 2.0 * std::numbers::pi);
    });
    cairo_fill(cr);
  }
  if (options.arrows) draw_arrows(cr, fields, map, std::max(1.0, width / 800.0));
  if (options.legend) draw_legend(cr, options, width, low, high);
  if (!options.caption.empty()) {
    const double font = std::max(10.0, width / 45.0);
    draw_caption(cr, 0.3 * font, 0.3 * font, font, options.caption);
  }
  cairo_destroy(cr);

  cairo_surface_flush(surface);
  RasterImage image{width, height, std::vector<Pixel>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))};
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int row = 0; row < height; ++row) {
    const auto* line = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(row) * stride);
    for (int column = 0; column < width; ++column) {
      const std::uint32_t v = line[column];
      image.pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)] = {
          static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
    }
  }
  cairo_surface_destroy(surface);
  return image;
}

}  // namespace granule::render
