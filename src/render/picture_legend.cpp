#include "render/picture_legend.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <numbers>

namespace granule::render {

namespace {

void white_panel(cairo_t* cr, double x, double y, double width, double height) {
  cairo_rectangle(cr, x, y, width, height);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

}  // namespace

void draw_direction_wheel(cairo_t* cr, double cx, double cy, double radius) {
  const double margin = 0.25 * radius;
  white_panel(cr, cx - radius - margin, cy - radius - margin, 2.0 * (radius + margin), 2.0 * (radius + margin));
  constexpr int kWedges = 90;
  const double step = 2.0 * std::numbers::pi / kWedges;
  for (int k = 0; k < kWedges; ++k) {
    const double angle = (k + 0.5) * step;
    const Rgb c = direction_color(angle);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_move_to(cr, cx, cy);
    // Picture y points down: the direction angle θ is drawn at −θ.
    cairo_arc_negative(cr, cx, cy, radius, -(k * step), -((k + 1) * step) - 0.01);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
}

void draw_color_bar(cairo_t* cr, double x, double y, double width, double height, double low, double high,
                    const char* label, const std::function<Rgb(double)>& scale) {
  const double font = std::max(9.0, height);
  const double margin = 0.4 * font;
  white_panel(cr, x - margin, y - margin - 1.2 * font, width + 2.0 * margin, height + 2.0 * margin + 2.4 * font);
  const int steps = std::max(2, static_cast<int>(width));
  for (int k = 0; k < steps; ++k) {
    const Rgb c = scale((k + 0.5) / steps);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, x + width * k / steps, y, width / steps + 0.5, height);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font);
  cairo_move_to(cr, x, y - 0.3 * font);
  cairo_show_text(cr, label);
  char low_text[32], high_text[32];
  std::snprintf(low_text, sizeof low_text, "%.4g", low);
  std::snprintf(high_text, sizeof high_text, "%.4g", high);
  cairo_move_to(cr, x, y + height + font);
  cairo_show_text(cr, low_text);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, high_text, &extents);
  cairo_move_to(cr, x + width - extents.x_advance, y + height + font);
  cairo_show_text(cr, high_text);
}

void draw_caption(cairo_t* cr, double x, double y, double font, const std::string& text) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  const double margin = 0.4 * font;
  white_panel(cr, x, y, extents.x_advance + 2.0 * margin, 1.2 * font + 2.0 * margin);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_move_to(cr, x + margin, y + margin + font);
  cairo_show_text(cr, text.c_str());
}

}  // namespace granule::render
