// Mutants of a real Granule HDF5 file, for the file fuzzer: what a damaged disk, a hand edit with
// h5py or a hostile file can make of it.  Semantic mutations go through the HDF5 library (an
// attribute or a dataset deleted, given another shape, count or type, or values NaN, ±∞,
// negative or huge); byte mutations damage the file itself (bits flipped, bytes zeroed, the file
// cut short).  Every mutant is determined by (seed, index), so a failure is reproduced by its
// two numbers.
#pragma once

#include <cstdint>
#include <string>

namespace granule::fuzz {

struct MutationOptions {
  // Recompute the digest of a checkpoint dataset whose values were edited (xxh3_64 attribute):
  // the edit of a hostile user, which only the engine's own checks can then refuse.
  bool reseal_digests = false;
};

// Recomputes the digest of every checkpoint dataset of `path` (xxh3_64) from its values, as a
// hostile user who edited them would.
void reseal_digests(const std::string& path);

// Writes mutant `index` of `original` to `mutant` and returns what was done to it, one line.
std::string write_mutant(const std::string& original, const std::string& mutant, std::uint64_t seed, std::uint64_t index,
                         const MutationOptions& options);

}  // namespace granule::fuzz
