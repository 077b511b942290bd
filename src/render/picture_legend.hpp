// Legends drawn into a configuration picture (cairo, device units = pixels): the hue wheel of
// velocity directions (as the inset of thesis Fig 1.1), a colour bar with its range, and a caption.
#pragma once

#include <cairo.h>

#include <functional>
#include <string>

#include "render/color_scales.hpp"

namespace granule::render {

// A wheel of radius `radius` centred at (cx, cy): the colour at angle θ (counter-clockwise from +x,
// picture y up) is the colour of a disk moving in direction θ.
void draw_direction_wheel(cairo_t* cr, double cx, double cy, double radius);

// A horizontal bar whose left end is `low` and right end `high`, labelled with both values.
void draw_color_bar(cairo_t* cr, double x, double y, double width, double height, double low, double high,
                    const char* label, const std::function<Rgb(double)>& scale);

// One line of text on a white panel whose top-left corner is (x, y); `font` is the font size in pixels.
void draw_caption(cairo_t* cr, double x, double y, double font, const std::string& text);

}  // namespace granule::render
