// The file fuzzer's readers of text files, beside its HDF5 ones (file_fuzz.cpp):
//   sweep-record: ORIGINAL is a point's record in a sweep directory (DIR/points/NAME.json).  Even
//     mutants are of the record; odd ones of the point's summary.json with the record removed, as
//     when a sweep stopped between the two.  Read as a restart and --collect read them.
//   timeseries: ORIGINAL is a timeseries.csv, read as `granule run --resume` and
//     `granule plot timeseries` read it.
#pragma once

#include <cstdint>
#include <string>

namespace granule::fuzz {

bool is_text_reader(const std::string& reader);

// Writes mutant `index` of ORIGINAL where `reader` reads it under WORK; returns what was done.
std::string prepare_text_mutant(const std::string& reader, const std::string& original, const std::string& work,
                                std::uint64_t seed, std::uint64_t index);

// Reads the mutant prepared last, as `granule` does.
void read_text_mutant(const std::string& reader, const std::string& original, const std::string& work);

}  // namespace granule::fuzz
