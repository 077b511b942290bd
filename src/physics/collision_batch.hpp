// The earliest collision of one particle with a batch of candidate partners, computed for the whole
// batch at once: the arithmetic of collision_time() operation by operation (the same doubles, so
// the same trajectories bit for bit), with its three tests turned into selections, so that the
// compiler runs the batch in vector registers and no unpredictable branch is taken per pair (about
// half of all pairs approach, and which half is random: ARCHITECTURE.md, "Speed").
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "physics/collision_time.hpp"

namespace granule {

template <int D>
struct CollisionBatch {
  // A block of cells holds about 16 spheres or 5 disks at the default occupancy (0.6 per cell); a
  // scan that finds more (crowded cells, small grains of a mixture) runs in several batches.
  static constexpr int kCapacity = 64;

  // Candidate k: its id, its position and velocity relative to the particle (image applied), and
  // its contact distance.
  std::array<std::int32_t, kCapacity> partner;
  alignas(64) std::array<std::array<double, kCapacity>, D> r;
  alignas(64) std::array<std::array<double, kCapacity>, D> v;
  alignas(64) std::array<double, kCapacity> contact;
  int size = 0;

  bool full() const { return size == kCapacity; }

  // The earliest collision in the batch if it is earlier than `best` (then `best` and `best_partner`
  // change), the first in batch order among equal times: what collision_time() gives pair by pair
  // with a strict `t < best`, in the same order.  Empties the batch.
  void take_earliest(double& best, std::int32_t& best_partner) {
    alignas(64) std::array<double, kCapacity> delay;
    const int n = size;
    for (int k = 0; k < n; ++k) {
      double b = r[0][k] * v[0][k];
      double rr = r[0][k] * r[0][k];
      double vv = v[0][k] * v[0][k];
      for (int a = 1; a < D; ++a) {
        b += r[a][k] * v[a][k];
        rr += r[a][k] * r[a][k];
        vv += v[a][k] * v[a][k];
      }
      const bool approach = (b < 0.0) & (b * b > kGrazingCosineSquared * rr * vv);
      const double c = rr - contact[k] * contact[k];
      const double disc = b * b - vv * c;
      const double root = c / (-b + std::sqrt(disc));  // NaN or ±inf where not selected below
      const double touching = c <= 0.0 ? 0.0 : root;
      delay[k] = approach & ((c <= 0.0) | (disc >= 0.0)) ? touching : kNever;
    }
    int earliest = -1;
    for (int k = 0; k < n; ++k) {
      const bool earlier = delay[k] < best;
      best = earlier ? delay[k] : best;
      earliest = earlier ? k : earliest;
    }
    if (earliest >= 0) best_partner = partner[static_cast<std::size_t>(earliest)];
    size = 0;
  }
};

}  // namespace granule
