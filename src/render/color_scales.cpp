#include "render/color_scales.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace granule::render {

namespace {

// HSV → RGB at full value; saturation 0.85 keeps neighbouring hues distinguishable on white.
Rgb hue_color(double hue_turns) {
  constexpr double kSaturation = 0.85;
  const double h = 6.0 * (hue_turns - std::floor(hue_turns));
  const double f = h - std::floor(h);
  const double p = 1.0 - kSaturation, q = 1.0 - kSaturation * f, t = 1.0 - kSaturation * (1.0 - f);
  switch (static_cast<int>(h) % 6) {
    case 0: return {1.0, t, p};
    case 1: return {q, 1.0, p};
    case 2: return {p, 1.0, t};
    case 3: return {p, q, 1.0};
    case 4: return {t, p, 1.0};
    default: return {1.0, p, q};
  }
}

// Nine equally spaced samples of matplotlib's viridis, interpolated linearly.
constexpr std::array<Rgb, 9> kViridis{{{0.267, 0.005, 0.329},
                                       {0.278, 0.175, 0.483},
                                       {0.229, 0.322, 0.546},
                                       {0.173, 0.449, 0.558},
                                       {0.128, 0.567, 0.551},
                                       {0.155, 0.683, 0.499},
                                       {0.360, 0.785, 0.388},
                                       {0.668, 0.862, 0.196},
                                       {0.993, 0.906, 0.144}}};

}  // namespace

Rgb direction_color(double angle) { return hue_color(angle / (2.0 * std::numbers::pi)); }

Rgb sequential_color(double value) {
  const double u = std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0) * (kViridis.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(u), kViridis.size() - 2);
  const double w = u - static_cast<double>(k);
  const Rgb& a = kViridis[k];
  const Rgb& b = kViridis[k + 1];
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)};
}

Rgb grey_color(double value) {
  const double v = std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0);
  return {v, v, v};
}

}  // namespace granule::render
