#include "analysis/spin_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace granule {

namespace {

constexpr std::size_t kAll = static_cast<std::size_t>(PairDirection::kAll);
constexpr std::size_t kFlow = static_cast<std::size_t>(PairDirection::kFlow);
constexpr std::size_t kGradient = static_cast<std::size_t>(PairDirection::kGradient);

// Grains binned in cells at least `side` wide along each axis: count → prefix sum → permute.
struct GrainCells {
  int dimension = 2;
  std::array<int, 3> n{1, 1, 1};
  std::array<double, 3> length{1.0, 1.0, 1.0};
  std::vector<std::uint32_t> start, grains;  // grains of cell c: grains[start[c] .. start[c + 1])

  int index(int axis, double coordinate) const {
    const double wrapped = coordinate - length[axis] * std::floor(coordinate / length[axis]);
    return std::clamp(static_cast<int>(wrapped / length[axis] * n[axis]), 0, n[axis] - 1);
  }
  std::size_t cell(const std::array<int, 3>& c) const {
    return static_cast<std::size_t>(c[0]) +
           static_cast<std::size_t>(n[0]) * (static_cast<std::size_t>(c[1]) + static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(c[2]));
  }
};

double coordinate(const ParticleState& s, int axis, std::size_t i) { return axis == 0 ? s.x[i] : (axis == 1 ? s.y[i] : s.z[i]); }

GrainCells bin_grains(const ParticleState& s, const PairImages& images, double side) {
  GrainCells b;
  b.dimension = s.dimension;
  b.length = images.length;
  // No more cells than grains: a dilute gas's cells of a few σ would be mostly empty.
  double volume = 1.0;
  for (int a = 0; a < s.dimension; ++a) volume *= images.length[a];
  side = std::max(side, std::pow(volume / static_cast<double>(std::max<std::size_t>(1, s.size())), 1.0 / s.dimension));
  for (int a = 0; a < s.dimension; ++a) b.n[a] = std::max(1, static_cast<int>(std::floor(images.length[a] / side)));
  std::vector<std::uint32_t> cell_of(s.size());
  b.start.assign(static_cast<std::size_t>(b.n[0]) * static_cast<std::size_t>(b.n[1]) * static_cast<std::size_t>(b.n[2]) + 1, 0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::array<int, 3> c{0, 0, 0};
    for (int a = 0; a < s.dimension; ++a) c[a] = b.index(a, coordinate(s, a, i));
    cell_of[i] = static_cast<std::uint32_t>(b.cell(c));
    ++b.start[cell_of[i] + 1];
  }
  std::partial_sum(b.start.begin(), b.start.end(), b.start.begin());
  b.grains.resize(s.size());
  std::vector<std::uint32_t> next(b.start.begin(), b.start.end() - 1);
  for (std::size_t i = 0; i < s.size(); ++i) b.grains[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  return b;
}

// The distinct cells that can hold a partner of grain i within one cell side: the 3^D block around
// its cell, whose rows beyond the top or bottom are the image rows (columns shifted by ∓Δ, thesis
// §1.4.2), without the cells beyond a wall; each once, also when an axis has fewer than 3 cells.
std::vector<std::size_t> cells_around(const GrainCells& b, const ParticleState& s, const PairImages& images, std::size_t i) {
  std::vector<std::size_t> cells;
  const int reach_z = b.dimension == 3 ? 1 : 0;
  for (int dz = -reach_z; dz <= reach_z; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      std::array<int, 3> c{0, b.index(1, s.y[i]) + dy, b.dimension == 3 ? b.index(2, s.z[i]) + dz : 0};
      int image = 0;
      if (c[1] < 0 || c[1] >= b.n[1]) {
        if (images.walls[1]) continue;
        image = c[1] < 0 ? -1 : 1;
        c[1] -= image * b.n[1];
      }
      if (c[2] < 0 || c[2] >= b.n[2]) {
        if (images.walls[2]) continue;
        c[2] = (c[2] + b.n[2]) % b.n[2];
      }
      const int column = b.index(0, s.x[i] - image * images.shear_offset);
      for (int dx = -1; dx <= 1; ++dx) {
        c[0] = column + dx;
        if (c[0] < 0 || c[0] >= b.n[0]) {
          if (images.walls[0]) continue;
          c[0] = (c[0] + b.n[0]) % b.n[0];
        }
        cells.push_back(b.cell(c));
      }
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

// r_j − r_i to the nearest image of j: across the top and bottom the image is shifted by ±Δ along x
// (thesis §1.4.2); no image across a wall.
std::array<double, 3> separation(const ParticleState& s, const PairImages& images, std::size_t i, std::size_t j) {
  std::array<double, 3> d{s.x[j] - s.x[i], s.y[j] - s.y[i], s.dimension == 3 ? s.z[j] - s.z[i] : 0.0};
  if (!images.walls[1]) {
    const double up = std::round(d[1] / images.length[1]);
    d[1] -= up * images.length[1];
    d[0] -= up * images.shear_offset;
  }
  for (int a : {0, 2}) {
    if (!images.walls[a]) d[a] -= images.length[a] * std::round(d[a] / images.length[a]);
  }
  return d;
}

void require_valid(const ParticleState& s, const PairImages& images, const SpinCorrelationSettings& settings, double reach) {
  if (!s.rough()) throw std::invalid_argument("the grains are smooth: they carry no spins to correlate");
  if (!(reach > 0.0) || !std::isfinite(reach)) throw std::invalid_argument("the diameter must be positive and finite");
  if (!(settings.contact_shell > 0.0) || !(settings.max_distance > 1.0 + settings.contact_shell) ||
      !std::isfinite(settings.max_distance)) {
    throw std::invalid_argument("the largest distance must exceed the contact shell 1 + shell > 1 (in contact distances)");
  }
  if (settings.bins < 1 || settings.bins > 100000) throw std::invalid_argument("the bins must number 1 … 100000");
  for (int a = 0; a < s.dimension; ++a) {
    if (!images.walls[a] && images.length[a] < 2.0 * reach) {
      throw std::invalid_argument("the box (" + std::to_string(images.length[a]) + " along axis " + std::to_string(a) +
                                  ") is shorter than twice the largest distance (" + std::to_string(reach) +
                                  "): a pair would meet two images");
    }
  }
}

}  // namespace

double SpinPairSums::correlation(PairDirection direction, std::size_t bin) const {
  const auto d = static_cast<std::size_t>(direction);
  return pairs[d][bin] > 0.0 ? products[d][bin] / pairs[d][bin] : std::numeric_limits<double>::quiet_NaN();
}

double SpinPairSums::contact_correlation() const {
  return contact_pairs > 0.0 ? contact_products / contact_pairs : std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> spin_correlation_edges(const SpinCorrelationSettings& settings) {
  std::vector<double> edges(static_cast<std::size_t>(settings.bins) + 1);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    edges[k] = 1.0 + (settings.max_distance - 1.0) * static_cast<double>(k) / settings.bins;
  }
  return edges;
}

SpinPairSums spin_pair_sums(const ParticleState& s, const PairImages& images, double diameter,
                            const SpinCorrelationSettings& settings) {
  const double largest = s.polydisperse() ? *std::max_element(s.diameter.begin(), s.diameter.end()) : diameter;
  const double reach = settings.max_distance * largest;
  require_valid(s, images, settings, reach);
  const int components = s.spin_components();
  const auto spin_axis = [&](int k) { return components == 1 ? 2 : k; };
  const std::size_t n = s.size();

  SpinPairSums out;
  for (std::size_t d = 0; d < kPairDirections; ++d) {
    out.pairs[d].assign(static_cast<std::size_t>(settings.bins), 0.0);
    out.products[d].assign(static_cast<std::size_t>(settings.bins), 0.0);
  }
  if (n == 0) return out;
  for (int k = 0; k < components; ++k) {
    const std::vector<double>& w = s.spin(k);
    out.mean_spin[spin_axis(k)] = std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(n);
  }
  for (int k = 0; k < components; ++k) {
    const std::vector<double>& w = s.spin(k);
    const double mean = out.mean_spin[spin_axis(k)];
    for (double value : w) out.spin_variance += (value - mean) * (value - mean);
  }
  out.spin_variance /= static_cast<double>(n);
  // Spins all alike have no fluctuation to correlate: their pairs are counted with product 0.
  const double scale = out.spin_variance > 0.0 ? 1.0 / out.spin_variance : 0.0;

  const GrainCells b = bin_grains(s, images, reach);
  const double bin_width = (settings.max_distance - 1.0) / settings.bins;
  for (std::size_t i = 0; i < n; ++i) {
    for (const std::size_t c : cells_around(b, s, images, i)) {
      for (std::uint32_t k = b.start[c]; k < b.start[c + 1]; ++k) {
        const std::size_t j = b.grains[k];
        if (j <= i) continue;  // each pair once
        const std::array<double, 3> d = separation(s, images, i, j);
        const double contact = s.polydisperse() ? 0.5 * (s.diameter[i] + s.diameter[j]) : diameter;
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / contact;
        if (r >= settings.max_distance) continue;
        double product = 0.0;
        for (int a = 0; a < components; ++a) {
          const double mean = out.mean_spin[spin_axis(a)];
          product += (s.spin(a)[i] - mean) * (s.spin(a)[j] - mean);
        }
        product *= scale;
        // A pair a hair closer than contact (round-off of a saved configuration) counts in the first bin.
        const auto bin = static_cast<std::size_t>(std::clamp(static_cast<int>((r - 1.0) / bin_width), 0, settings.bins - 1));
        const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
        out.pairs[kAll][bin] += 1.0;
        out.products[kAll][bin] += product;
        if (ax >= ay && ax >= az) {
          out.pairs[kFlow][bin] += 1.0;
          out.products[kFlow][bin] += product;
        } else if (ay >= az) {
          out.pairs[kGradient][bin] += 1.0;
          out.products[kGradient][bin] += product;
        }
        if (r < 1.0 + settings.contact_shell) {
          out.contact_pairs += 1.0;
          out.contact_products += product;
        }
      }
    }
  }
  return out;
}

void SpinCorrelationAverage::add(const SpinPairSums& frame) {
  if (total.pairs[kAll].empty()) {
    total = frame;
  } else {
    for (std::size_t d = 0; d < kPairDirections; ++d) {
      for (std::size_t k = 0; k < total.pairs[d].size(); ++k) {
        total.pairs[d][k] += frame.pairs[d][k];
        total.products[d][k] += frame.products[d][k];
      }
    }
    total.contact_pairs += frame.contact_pairs;
    total.contact_products += frame.contact_products;
  }
  contact_by_frame.push_back(frame.contact_correlation());
}

double SpinCorrelationAverage::contact_mean() const {
  double sum = 0.0;
  int count = 0;
  for (double c : contact_by_frame) {
    if (std::isfinite(c)) {
      sum += c;
      ++count;
    }
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

double SpinCorrelationAverage::contact_error() const {
  const double mean = contact_mean();
  double squares = 0.0;
  int count = 0;
  for (double c : contact_by_frame) {
    if (std::isfinite(c)) {
      squares += (c - mean) * (c - mean);
      ++count;
    }
  }
  if (count < 2) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(squares / (count - 1) / count);
}

}  // namespace granule
