#include "analysis/flow_classification.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace granule {

namespace {

// Union–find whose root is always the smallest id of its set.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::int32_t find(std::int32_t i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      auto& p = parent_[static_cast<std::size_t>(i)];
      p = parent_[static_cast<std::size_t>(p)];  // path halving
      i = p;
    }
    return i;
  }
  void join(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<std::int32_t> parent_;
};

// Disks binned in cells at least `side` wide and high: count → prefix sum → permute.
struct BinnedDisks {
  int nx = 1, ny = 1;
  double length_x = 1.0, length_y = 1.0;
  std::vector<std::int32_t> start, disks;  // disks of cell c: disks[start[c] .. start[c + 1])

  int column(double x) const {
    const double wrapped = x - length_x * std::floor(x / length_x);
    return std::clamp(static_cast<int>(wrapped / length_x * nx), 0, nx - 1);
  }
  int row(double y) const { return std::clamp(static_cast<int>(y / length_y * ny), 0, ny - 1); }
  std::size_t cell(int cx, int cy) const { return static_cast<std::size_t>(cx) + static_cast<std::size_t>(cy) * static_cast<std::size_t>(nx); }
};

BinnedDisks bin_disks(const ParticleState& s, double length_x, double length_y, double side) {
  // No more cells than disks: σ-sized cells of a dilute gas are mostly empty, and two arrays of
  // them cost 114 bytes per disk at ν = 0.05 (the peak of a whole run, measured with heaptrack).
  side = std::max(side, std::sqrt(length_x * length_y / static_cast<double>(std::max<std::size_t>(1, s.size()))));
  BinnedDisks b;
  b.length_x = length_x;
  b.length_y = length_y;
  b.nx = std::max(1, static_cast<int>(std::floor(length_x / side)));
  b.ny = std::max(1, static_cast<int>(std::floor(length_y / side)));
  std::vector<std::uint32_t> cell_of(s.size());  // fewer cells than disks: 32 bits suffice
  b.start.assign(static_cast<std::size_t>(b.nx) * static_cast<std::size_t>(b.ny) + 1, 0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    cell_of[i] = static_cast<std::uint32_t>(b.cell(b.column(s.x[i]), b.row(s.y[i])));
    ++b.start[cell_of[i] + 1];
  }
  std::partial_sum(b.start.begin(), b.start.end(), b.start.begin());
  b.disks.resize(s.size());
  std::vector<std::int32_t> next(b.start.begin(), b.start.end() - 1);
  for (std::size_t i = 0; i < s.size(); ++i) b.disks[static_cast<std::size_t>(next[cell_of[i]]++)] = static_cast<std::int32_t>(i);
  return b;
}

}  // namespace

double densest_band_mass_fraction(const std::vector<double>& y, double length_y, double band_width) {
  const std::size_t n = y.size();
  if (n == 0) return 0.0;
  if (band_width >= length_y) return 1.0;
  // The best band can start at a disk: slide a window [y_i, y_i + w) over the sorted y's, the
  // second copy (y + L_y) closing bands that wrap through the top.
  std::vector<double> sorted(y);
  std::sort(sorted.begin(), sorted.end());
  std::size_t best = 0, end = 0;
  const auto at = [&](std::size_t k) { return k < n ? sorted[k] : sorted[k - n] + length_y; };
  for (std::size_t i = 0; i < n; ++i) {
    end = std::max(end, i);
    while (end < i + n && at(end) < sorted[i] + band_width) ++end;
    best = std::max(best, end - i);
  }
  return static_cast<double>(best) / static_cast<double>(n);
}

std::vector<std::int32_t> cluster_labels(const ParticleState& s, double length_x, double length_y, double shear_offset,
                                         double contact_distance) {
  const BinnedDisks b = bin_disks(s, length_x, length_y, contact_distance);
  DisjointSets sets(s.size());
  const double r2 = contact_distance * contact_distance;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const int cy = b.row(s.y[i]);
    for (int dy = -1; dy <= 1; ++dy) {
      // A row beyond the top (bottom) is the bottom (top) row's image, at y ± L_y and shifted by ±Δ.
      const int image = cy + dy >= b.ny ? 1 : (cy + dy < 0 ? -1 : 0);
      const int row = cy + dy - image * b.ny;
      const double offset_x = image * shear_offset, offset_y = image * length_y;
      const int cx = b.column(s.x[i] - offset_x);
      for (int dx = -1; dx <= 1; ++dx) {
        const std::size_t c = b.cell((cx + dx + b.nx) % b.nx, row);
        for (std::int32_t k = b.start[c]; k < b.start[c + 1]; ++k) {
          const auto j = static_cast<std::size_t>(b.disks[static_cast<std::size_t>(k)]);
          double sx = s.x[j] + offset_x - s.x[i];
          sx -= length_x * std::round(sx / length_x);
          const double sy = s.y[j] + offset_y - s.y[i];
          if (j != i && sx * sx + sy * sy < r2) sets.join(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
        }
      }
    }
  }
  std::vector<std::int32_t> labels(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) labels[i] = sets.find(static_cast<std::int32_t>(i));
  return labels;
}

double largest_cluster_mass_fraction(const std::vector<std::int32_t>& labels) {
  if (labels.empty()) return 0.0;
  std::vector<std::int32_t> size(labels.size(), 0);
  for (std::int32_t l : labels) ++size[static_cast<std::size_t>(l)];
  return static_cast<double>(*std::max_element(size.begin(), size.end())) / static_cast<double>(labels.size());
}

FlowClassification classify_flow(const StateBlocks& state, const ShearFrame& frame, double shear_offset, double diameter,
                                 const FlowClassificationSettings& settings) {
  FlowClassification out;
  const std::size_t n = state.size();
  if (n == 0) return out;
  // Streamwise profiles over `rows` rows: ρ(y) = count / row area, V_x(y) = Σ v_x / count.
  const auto rows = static_cast<std::size_t>(settings.rows);
  std::vector<double> count(rows, 0.0), momentum_x(rows, 0.0);
  ParticleState positions;
  positions.x.reserve(n);
  positions.y.reserve(n);
  state.for_each([&](const ParticleState& s, std::size_t) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto r = static_cast<std::size_t>(std::clamp(static_cast<int>(s.y[i] / frame.length_y * settings.rows), 0, settings.rows - 1));
      count[r] += 1.0;
      momentum_x[r] += s.vx[i];
    }
    positions.x.insert(positions.x.end(), s.x.begin(), s.x.end());
    positions.y.insert(positions.y.end(), s.y.begin(), s.y.end());
  });
  const double mean = static_cast<double>(n) / static_cast<double>(rows);  // ρ(y)/ρ̄ = count / mean
  const auto [lowest, highest] = std::minmax_element(count.begin(), count.end());
  out.density_contrast = (*highest - *lowest) / mean;
  double deviation2 = 0.0, velocity2 = 0.0;
  int occupied = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    deviation2 += (count[r] / mean - 1.0) * (count[r] / mean - 1.0);
    if (count[r] == 0.0) continue;
    const double linear = frame.mean_flow((static_cast<double>(r) + 0.5) * frame.length_y / settings.rows);
    velocity2 += (momentum_x[r] / count[r] - linear) * (momentum_x[r] / count[r] - linear);
    ++occupied;
  }
  out.density_rms_deviation = std::sqrt(deviation2 / static_cast<double>(rows));
  const double velocity_unit = frame.sheared() ? std::abs(frame.shear_velocity) : 1.0;
  out.velocity_profile_deviation = std::sqrt(velocity2 / occupied) / velocity_unit;
  out.densest_band_mass_fraction = densest_band_mass_fraction(positions.y, frame.length_y, settings.band_fraction * frame.length_y);
  out.largest_cluster_mass_fraction = largest_cluster_mass_fraction(
      cluster_labels(positions, frame.length_x, frame.length_y, shear_offset, (1.0 + settings.cluster_gap) * diameter));
  return out;
}

}  // namespace granule
