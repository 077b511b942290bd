// The schema check of the measurement files figure scripts read (io/file_schema.hpp): a file that
// holds what the schema says passes; each way of not holding it is refused with a message naming
// the dataset or attribute and what was expected (the dimension and the dataset that fixed it).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {
namespace {

namespace fs = std::filesystem;

// Two windows of curves over their own speeds, frames shared by the whole file.
const FileSchema& schema() {
  static const FileSchema s{"granule-test",
                            1,
                            2,
                            {"windows/*/fits"},
                            {{"time", "F"},
                             {"frame_index", "F", Values::kIntegers},
                             {"maps", "F,3,3", Values::kNumbers},
                             {"windows/*/edges", "v+1"},
                             {"windows/*/density", "F,v", Values::kNumbers},
                             {"windows/*/replicates", "r,2", Values::kNumbers, false}},
                            {{".", "boundary", Values::kText},
                             {".", "box", Values::kFinite, 2},
                             {".", "particles", Values::kIntegers},
                             {"windows/*", "speed_scale", Values::kFinite},
                             {"windows/*", "ratio", Values::kNumbers}}};
  return s;
}

struct Contents {
  int version = 1;
  hsize_t frames = 4;
  std::vector<hsize_t> speeds{5, 7};  // one window each
  bool frame_index_as_integers = true;
  double box_x = 1.0;
  double ratio = std::numeric_limits<double>::quiet_NaN();  // not measured: allowed
  bool replicates = false;
  std::function<void(hid_t)> edit;  // a last change, on the open file
};

fs::path write(const std::string& name, const Contents& c) {
  const fs::path dir = fs::temp_directory_path() / "granule_test_file_schema";
  fs::create_directories(dir);
  const fs::path path = dir / (name + ".h5");
  const hid_t file = create_partial_file(path.string(), "granule-test", c.version, "test");
  write_string_attribute(file, "boundary", "periodic");
  const double box[2] = {c.box_x, 1.0};
  write_attribute(file, "box", H5T_NATIVE_DOUBLE, box, 2);
  const long long particles = 10;
  write_attribute(file, "particles", H5T_NATIVE_LLONG, &particles);
  write_vector(file, "time", std::vector<double>(c.frames, 0.5));
  if (c.frame_index_as_integers) {
    std::vector<long long> index(c.frames);
    for (hsize_t k = 0; k < c.frames; ++k) index[k] = static_cast<long long>(k);
    Handle space(H5Screate_simple(1, &c.frames, nullptr), H5Sclose);
    Handle dataset(H5Dcreate2(file, "frame_index", H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    check(H5Dwrite(dataset.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, index.data()), file, "write", "frame_index");
  } else {
    write_vector(file, "frame_index", std::vector<double>(c.frames, 1.0));
  }
  write_dataset(file, "maps", {c.frames, 3, 3}, std::vector<double>(c.frames * 9, 1.0));
  Handle(create_group(file, "windows"), H5Gclose).close();
  for (std::size_t w = 0; w < c.speeds.size(); ++w) {
    const std::string g = "windows/00" + std::to_string(w);
    Handle group(create_group(file, g.c_str()), H5Gclose);
    Handle(create_group(group.get(), "fits"), H5Gclose).close();
    write_double(group.get(), "speed_scale", 2.0);
    write_double(group.get(), "ratio", c.ratio);
    write_vector(group.get(), "edges", std::vector<double>(c.speeds[w] + 1, 0.25));
    write_dataset(group.get(), "density", {c.frames, c.speeds[w]}, std::vector<double>(c.frames * c.speeds[w], 0.0));
    if (c.replicates) write_dataset(group.get(), "replicates", {3, 2}, std::vector<double>(6, 1.0));
    group.close();
  }
  if (c.edit) c.edit(file);
  publish_partial_file(file, path.string());
  return path;
}

std::string refusal(const fs::path& path) {
  try {
    check_file_schema(path.string(), schema());
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

Contents valid() { return {}; }

TEST(FileSchema, AcceptsWhatItDescribesWithEachWindowItsOwnSpeedsAndOptionalsEitherWay) {
  EXPECT_EQ(refusal(write("valid", valid())), "");
  Contents bootstrapped = valid();
  bootstrapped.replicates = true;
  bootstrapped.version = 2;
  EXPECT_EQ(refusal(write("bootstrapped", bootstrapped)), "");
}

TEST(FileSchema, RefusesAShapeThatDisagreesNamingTheDimensionAndWhereItWasFixed) {
  Contents c = valid();
  c.edit = [](hid_t file) {
    check(H5Ldelete(file, "maps", H5P_DEFAULT), file, "delete", "maps");
    write_dataset(file, "maps", {3, 3, 3}, std::vector<double>(27, 1.0));
  };
  const std::string message = refusal(write("frames", c));
  EXPECT_NE(message.find("dataset maps has shape (3, 3, 3); expected (F = 4, 3, 3); F as time has it"), std::string::npos)
      << message;
}

TEST(FileSchema, BindsLowerCaseDimensionsPerGroupMember) {
  Contents c = valid();
  c.edit = [](hid_t file) {
    check(H5Ldelete(file, "windows/001/density", H5P_DEFAULT), file, "delete", "density");
    write_dataset(file, "windows/001/density", {4, 5}, std::vector<double>(20, 0.0));  // window 0's 5 speeds, not its own 7
  };
  const std::string message = refusal(write("per_window", c));
  EXPECT_NE(message.find("dataset windows/001/density has shape (4, 5); expected (F = 4, v = 7)"), std::string::npos) << message;
}

TEST(FileSchema, RefusesMissingObjectsTypesAndValuesNamingThem) {
  struct Case {
    const char* name;
    std::function<void(Contents&)> change;
    const char* expected;
  };
  const std::vector<Case> cases{
      {"version", [](Contents& c) { c.version = 3; }, "format_version 3 is not one this Granule reads (1 … 2)"},
      {"integers", [](Contents& c) { c.frame_index_as_integers = false; },
       "dataset frame_index is not stored as integers"},
      {"infinite_box", [](Contents& c) { c.box_x = std::numeric_limits<double>::infinity(); },
       "attribute box holds inf at index 0; expected finite numbers"},
      {"missing_dataset", [](Contents& c) {
         c.edit = [](hid_t file) { check(H5Ldelete(file, "windows/000/edges", H5P_DEFAULT), file, "delete", ""); };
       }, "has no dataset windows/000/edges"},
      {"missing_group", [](Contents& c) {
         c.edit = [](hid_t file) { check(H5Ldelete(file, "windows/001/fits", H5P_DEFAULT), file, "delete", ""); };
       }, "has no group windows/001/fits"},
      {"missing_attribute", [](Contents& c) {
         c.edit = [](hid_t file) { check(H5Adelete_by_name(file, "windows/001", "speed_scale", H5P_DEFAULT), file, "delete", ""); };
       }, "has no attribute speed_scale of windows/001"},
      {"claims_unstored", [](Contents& c) {
         c.edit = [](hid_t file) {
           const hsize_t claimed = hsize_t{1} << 40, max = H5S_UNLIMITED, chunk = 1024;
           Handle space(H5Screate_simple(1, &claimed, &max), H5Sclose);
           Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
           H5Pset_chunk(properties.get(), 1, &chunk);
           Handle(H5Dcreate2(file, "undescribed", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Dclose).close();
         };
       }, "dataset undescribed needs 8796093022208 bytes"},
  };
  for (const Case& k : cases) {
    Contents c = valid();
    k.change(c);
    const std::string message = refusal(write(k.name, c));
    EXPECT_NE(message.find(k.expected), std::string::npos) << k.name << ": " << message;
    EXPECT_EQ(message.rfind(fs::temp_directory_path().string(), 0), 0u) << k.name << ": the refusal names the file: " << message;
  }
}

}  // namespace
}  // namespace granule::h5
