// Mutants of a real Granule text file (a sweep point's JSON record or a run's summary.json, a
// timeseries.csv), for the file fuzzer: what a damaged disk, a hand edit or a hostile file can make
// of it.  Byte mutations (a bit flipped, a byte changed, bytes inserted, the file cut short), line
// mutations (a line deleted, duplicated or swapped with another), number mutations (a number
// replaced by NaN, ±inf, −1, 1e308, an integer beyond 64 bits, a string), and for JSON, value
// mutations (a value given another type, a key deleted, renamed or added).  One to three of them
// per mutant.  Every mutant is determined by (seed, index), so a failure is reproduced by its two
// numbers.
#pragma once

#include <cstdint>
#include <string>

namespace granule::fuzz {

// Mutant `index` of `text`; `what` is set to what was done, one line.
std::string mutate_text(const std::string& text, std::uint64_t seed, std::uint64_t index, std::string& what);

// Writes mutant `index` of the file `original` to `mutant` and returns what was done to it.
std::string write_text_mutant(const std::string& original, const std::string& mutant, std::uint64_t seed,
                              std::uint64_t index);

}  // namespace granule::fuzz
