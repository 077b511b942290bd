// A histogram of equal bins on [low, high), with the values outside counted apart (so that
// normalised distributions and cumulative forms can account for every sample).
#pragma once

#include <vector>

namespace granule {

struct UniformBins {
  double low = 0.0;
  double high = 1.0;
  int bins = 1;

  double width() const { return (high - low) / bins; }
  double edge(int k) const { return low + k * width(); }
  double center(int k) const { return low + (k + 0.5) * width(); }
  // The bin of x, or −1 outside [low, high).
  int bin(double x) const {
    if (!(x >= low && x < high)) return -1;
    const int k = static_cast<int>((x - low) / width());
    return k < bins ? k : bins - 1;
  }
};

}  // namespace granule
