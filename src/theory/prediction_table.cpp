#include "theory/prediction_table.hpp"

#include <cmath>

namespace granule::theory {

std::vector<double> linspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (int j = 0; j < points; ++j) {
    out.push_back(points == 1 ? lo : lo + (hi - lo) * j / (points - 1));
  }
  return out;
}

std::vector<double> logspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (double x : linspace(std::log(lo), std::log(hi), points)) out.push_back(std::exp(x));
  return out;
}

}  // namespace granule::theory
