// 3D fields files and particle exports read back: the fields.h5 layout (K, nz, ny, nx) with its
// grid and Lees–Edwards state per frame, the .vti extent, and extended XYZ / .vtp rows with z and
// each particle's own radius.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "analysis/cell_fields.hpp"
#include "io/export_field_source.hpp"
#include "io/export_vtk.hpp"
#include "io/export_xyz.hpp"
#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"

namespace granule {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("granule_test_exports_3d_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const FieldGrid kGrid{4, 3, 2.0, 1.5, 2, 1.0, 3};

// Every cell value is a distinct function of the cell, the field's position in the list and the frame.
FieldsFrame frame_with_labels(int label) {
  FieldsFrame f;
  f.t = label;
  f.c = 10.0 * label;
  f.configurations = 1;
  f.shear_offset = 0.25 * label;
  f.shear_velocity = 3.0;
  for (CellFields* fields : {&f.instant, &f.average}) {
    fields->grid = kGrid;
    int field = 0;
    for_each_field(*fields, [&](const char*, std::vector<double>& v) {
      v.resize(kGrid.cells());
      for (std::size_t c = 0; c < v.size(); ++c) v[c] = 1000.0 * label + 100.0 * field + static_cast<double>(c);
      ++field;
    });
  }
  return f;
}

TEST(Fields3d, FileHoldsEveryFieldAsVolumesWithTheGridAndImageState) {
  const std::string path = (scratch("fields") / "fields.h5").string();
  SystemParams system;
  system.dimension = 3;
  {
    FieldsWriter writer(path, kGrid, FieldsMetadata{system, "lees-edwards", false, "run", "test"}, false);
    for (int k = 0; k < 3; ++k) writer.append(frame_with_labels(k));
    writer.finish();
  }
  h5::Handle file = h5::open_file(path);
  const FieldGrid grid = read_fields_grid(file.get());
  EXPECT_EQ(grid.dimension, 3);
  EXPECT_EQ(grid.nz, 2);
  EXPECT_EQ(grid.length_z, 1.0);
  EXPECT_EQ(h5::dataset_shape(file.get(), "/average/kinetic_yz"), (std::vector<hsize_t>{3, 2, 3, 4}));
  double offset = 0.0;
  h5::read_frame(file.get(), "/frames/shear_offset", H5T_NATIVE_DOUBLE, &offset, 2, {});
  EXPECT_EQ(offset, 0.5);
  file.close();

  const FieldFileFrame last = read_field_file_frame(path, -1);
  EXPECT_EQ(last.arrays.size(), 2u * 17u) << "12 fields of 2D and 5 z components, instant and average";
  const auto found = std::find_if(last.arrays.begin(), last.arrays.end(), [](const NamedCellArray& a) { return a.name == "average_velocity_z"; });
  ASSERT_NE(found, last.arrays.end());
  // velocity_z is the 13th field (index 12): cell (ix, iy, iz) = (1, 2, 1) is c = 1 + 4·(2 + 3·1) = 21.
  EXPECT_EQ(found->values[21], 2000.0 + 1200.0 + 21.0);
}

TEST(Fields3d, TwoDimensionalFilesHaveNoThirdAxisAttributes) {
  const std::string path = (scratch("fields2d") / "fields.h5").string();
  const FieldGrid grid{3, 2, 1.0, 2.0};
  FieldsWriter writer(path, grid, FieldsMetadata{SystemParams{}, "periodic", false, "run", "test"}, false);
  writer.finish();
  h5::Handle file = h5::open_file(path);
  for (const char* name : {"dimension", "nz", "length_z"}) EXPECT_EQ(H5Aexists(file.get(), name), 0) << name;
  EXPECT_EQ(H5Lexists(file.get(), "/frames/shear_offset", H5P_DEFAULT), 0);
  EXPECT_EQ(H5Lexists(file.get(), "/instant/velocity_z", H5P_DEFAULT), 0);
  file.close();
}

TEST(Fields3d, ImageDataSpansTheBoxInThreeDimensions) {
  const std::string path = (scratch("vti") / "fields.vti").string();
  write_vti_fields(path, kGrid, {{"density", std::vector<double>(kGrid.cells(), 1.0)}}, 0.5);
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("WholeExtent=\"0 4 0 3 0 2\""), std::string::npos);
  EXPECT_NE(text.find("Spacing=\"0.5 0.5 0.5\""), std::string::npos);
  EXPECT_THROW(write_vti_fields(path, kGrid, {{"short", std::vector<double>(12, 1.0)}}, 0.5), std::invalid_argument);
}

ParticleState two_spheres(bool polydisperse) {
  ParticleState p;
  p.dimension = 3;
  if (polydisperse) p.diameter = {0.0, 0.0};
  p.resize(2);
  p.x = {0.1, 0.2};
  p.y = {0.3, 0.4};
  p.z = {0.5, 0.6};
  p.vx = {1.0, -1.0};
  p.vy = {2.0, -2.0};
  p.vz = {3.0, -3.0};
  if (polydisperse) {
    p.diameter = {0.02, 0.04};
    p.mass = {1.0, 8.0};
  }
  return p;
}

TEST(Exports3d, ExtendedXyzRowsCarryZAndEachRadius) {
  std::ostringstream out;
  XyzFrameInfo info;
  info.diameter = 0.03;
  info.length_z = 0.75;
  write_xyz_frame(out, two_spheres(true), info);
  std::istringstream lines(out.str());
  std::string count, header, first, second;
  std::getline(lines, count);
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(count, "2");
  EXPECT_NE(header.find("Lattice=\"1 0 0 0 1 0 0 0 0.75\""), std::string::npos) << header;
  EXPECT_NE(header.find("pbc=\"T T T\""), std::string::npos) << header;
  EXPECT_EQ(first, "D 0.1 0.3 0.5 1 2 3 0.01");
  EXPECT_EQ(second, "D 0.2 0.4 0.6 -1 -2 -3 0.02");
  std::ostringstream mono;
  write_xyz_frame(mono, two_spheres(false), info);
  EXPECT_NE(mono.str().find("D 0.2 0.4 0.6 -1 -2 -3 0.015\n"), std::string::npos) << "σ/2 of the monodisperse diameter";
}

}  // namespace
}  // namespace granule
