// Small wrappers over the HDF5 C API shared by Granule's files (snapshots, fields, collision
// statistics): error checks that throw, attributes, and extendible per-frame datasets.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace granule::h5 {

void check(herr_t status, const std::string& what);
hid_t check_id(hid_t id, const std::string& what);

void write_attribute(hid_t object, const char* name, hid_t type, const void* data, hsize_t count = 1);
void write_string_attribute(hid_t object, const char* name, const std::string& value);
inline void write_double(hid_t object, const char* name, double value) { write_attribute(object, name, H5T_NATIVE_DOUBLE, &value); }
template <typename T>
T read_attribute(hid_t object, const char* name, hid_t type) {
  T value{};
  const hid_t attribute = check_id(H5Aopen(object, name, H5P_DEFAULT), std::string("reading attribute ") + name);
  check(H5Aread(attribute, type, &value), name);
  H5Aclose(attribute);
  return value;
}
std::string read_string_attribute(hid_t object, const char* name);

// Files a user keeps are written as `<path>.partial` and renamed when complete.  Creates the
// partial file stamped with the format name, its version and Granule's version (root attributes
// `format`, `format_version`, `granule_version`).
hid_t create_partial_file(const std::string& path, const char* format, int format_version, const std::string& granule_version);
// Close a file made by create_partial_file and give it its final name `path`.
void publish_partial_file(hid_t file, const std::string& path);
// Reopen a file of frames to continue it: `<path>.partial` if a run left one, else the published
// `<path>`, renamed back to `<path>.partial` until it is complete again.  Every extendible
// dataset is cut to its first `keep_frames` frames (what a checkpoint knew of).
hid_t reopen_frames_file(const std::string& path, std::int64_t keep_frames);

// An extendible dataset of frames: shape (frames, row...) with one chunk per frame.
hid_t create_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row);
// Write (grow = true, extending the dataset by one frame) or read one frame of a dataset.
void transfer_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, bool grow);
void append_frame(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame);
void read_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame);

// A whole fixed-shape double dataset written at once (shape `dims`, row-major `data`).
void write_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, const std::vector<double>& data);
void write_vector(hid_t location, const char* name, const std::vector<double>& data);
hid_t create_group(hid_t location, const char* name);

}  // namespace granule::h5
