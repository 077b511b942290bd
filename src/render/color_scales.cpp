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

// Nine equally spaced samples of matplotlib's RdBu_r over [−1, 1].
constexpr std::array<Rgb, 9> kRedBlue{{{0.020, 0.188, 0.380},
                                       {0.129, 0.400, 0.675},
                                       {0.263, 0.576, 0.765},
                                       {0.573, 0.773, 0.871},
                                       {0.969, 0.969, 0.969},
                                       {0.957, 0.647, 0.510},
                                       {0.839, 0.376, 0.302},
                                       {0.698, 0.094, 0.169},
                                       {0.404, 0.000, 0.122}}};

// Linear interpolation of equally spaced samples at u ∈ [0, 1] (clamped; NaN → 0).
template <std::size_t N>
Rgb interpolate(const std::array<Rgb, N>& samples, double u) {
  const double at = std::clamp(std::isfinite(u) ? u : 0.0, 0.0, 1.0) * (N - 1);
  const auto k = std::min(static_cast<std::size_t>(at), N - 2);
  const double w = at - static_cast<double>(k);
  const Rgb& a = samples[k];
  const Rgb& b = samples[k + 1];
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)};
}

}  // namespace

Rgb direction_color(double angle) { return hue_color(angle / (2.0 * std::numbers::pi)); }

Rgb sequential_color(double value) { return interpolate(kViridis, value); }

Rgb diverging_color(double value) { return interpolate(kRedBlue, 0.5 * (value + 1.0)); }

Rgb grey_color(double value) {
  const double v = std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0);
  return {v, v, v};
}

}  // namespace granule::render
