// Which schema a measurement file is checked against: the kind the caller expects, and for spectra
// the file's "dimension" attribute (absent in 2D files).
#include <string>

#include "io/collision_statistics_file.hpp"
#include "io/f1_file.hpp"
#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "io/spectra_file.hpp"
#include "io/spins_file.hpp"

namespace granule::h5 {

namespace {

// A spectra file's variant: 3D files say so; 2D files carry no dimension.
int spectra_dimension(const std::string& path) {
  Handle file = open_file(path);
  const int dimension = has_attribute(file.get(), "dimension") ? read_attribute<int>(file.get(), "dimension", H5T_NATIVE_INT) : 2;
  file.close();
  if (dimension != 2 && dimension != 3) {
    throw InputError(path + ": attribute dimension is " + std::to_string(dimension) + "; expected 2 or 3");
  }
  return dimension;
}

}  // namespace

void check_measurement_file(const std::string& path, Measurement kind) {
  const FileSchema& schema = kind == Measurement::kCollisionStatistics ? collision_statistics_schema()
                             : kind == Measurement::kF1                ? f1_schema()
                             : kind == Measurement::kSpins             ? spins_file::spins_schema()
                                                                       : spectra_file::spectra_schema(spectra_dimension(path));
  check_file_schema(path, schema);
}

}  // namespace granule::h5
