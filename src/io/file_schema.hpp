// The schema of a Granule measurement file that other programs read (the figure scripts, with
// h5py): which datasets and attributes it holds, their types and shapes, and which values must be
// finite.  check_file_schema checks a file against it before anything else reads it, so that a
// damaged or edited file is refused with a message naming the dataset or attribute and what was
// expected, not met by a script half way through a figure.
//
// Shapes are written as comma-separated dimensions: a number ("7"), a name ("F"), or a name plus a
// number ("B+1", an array of bin edges).  A name is bound by the first dataset that has it, and
// every later one must agree.  One name of a path may hold a "*" for the members of its group whose
// names fit ("windows/*/h", "free_paths/speed_window_*/counts"); dimension names in lower case are
// then bound anew in each member, names in upper case are shared by all.  A required dataset or
// attribute, and a listed group, is required when the group it is in exists.
#pragma once

#include <string>
#include <vector>

namespace granule::h5 {

enum class Values {
  kFinite,    // numbers, each finite
  kNumbers,   // numbers: NaN marks what could not be measured (a window without samples), ∞ a length
              // without bound (the cluster length L0 of an elastic system)
  kIntegers,  // stored as integers
  kText,      // one string (attributes only)
};

struct DatasetRule {
  std::string path;
  const char* shape;  // "" for a scalar
  Values values = Values::kFinite;
  bool required = true;
};

struct AttributeRule {
  std::string object;  // "." for the file itself; may hold one "*"
  std::string name;
  Values values = Values::kFinite;
  int count = 1;  // the number of values (strings: 1)
  bool required = true;
};

struct FileSchema {
  const char* format;  // the file's "format" attribute
  int oldest_version;  // the "format_version" values it describes
  int newest_version;
  std::vector<std::string> groups;  // may hold one "*"
  std::vector<DatasetRule> datasets;
  std::vector<AttributeRule> attributes;
};

// Throws InputError naming the file, the object and what the schema expects.  Every dataset of the
// file, described or not, must store the bytes its shape claims.
void check_file_schema(const std::string& path, const FileSchema& schema);

// The measurement files that figure scripts read, each checked against its schema (its writer
// declares it) by check_measurement_file, defined in io/measurement_schemas.cpp.
enum class Measurement { kCollisionStatistics, kSpectra, kF1, kSpins };
void check_measurement_file(const std::string& path, Measurement kind);

}  // namespace granule::h5
