// Colour scales of the configuration pictures: the hue wheel of velocity directions (the inset of
// thesis Fig 1.1), a sequential scale for magnitudes (speed, cell fields) and its grey variant
// (the thesis's shaded maps: lighter for higher values), and a diverging scale for signed values.  Components are in [0, 1].
#pragma once

namespace granule::render {

struct Rgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
};

// Hue wheel: the direction angle (radians, 0 along +x, counter-clockwise) is the hue, so that
// opposite directions get complementary colours (+x red, +y yellow-green, −x cyan, −y violet).
Rgb direction_color(double angle);

// Sequential scale (viridis) of a value in [0, 1] (clamped): dark blue for low, yellow for high.
Rgb sequential_color(double value);

// Diverging scale (matplotlib's RdBu reversed) of a value in [−1, 1] (clamped): blue for negative,
// near-white at 0, red for positive — for signed quantities such as the spin ω_z (thesis Fig C.4).
Rgb diverging_color(double value);

// Grey shade of a value in [0, 1] (clamped), as the thesis's maps: darker for lower values.
Rgb grey_color(double value);

}  // namespace granule::render
