// Small wrappers over the HDF5 C API shared by Granule's files (snapshots, fields, collision
// statistics, spectra, f1): every call checked (a failure throws IoError naming the file, the
// object and the system's reason), identifiers owned by Handle, attributes, extendible per-frame
// datasets, and the `<name>.partial` life cycle of a file (create, publish, reopen and truncate).
// Objects are created without modification times, so equal content gives byte-identical files.
// Defined in io/hdf5_util.cpp, and the per-frame datasets and PartialFile in io/hdf5_frames.cpp.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace granule::h5 {

// One HDF5 identifier, closed once.  close() reports a failed close (closing a dataset or a file
// writes what HDF5 still caches, which fails on a full disk); the destructor closes quietly, for
// the paths on which an exception is already on its way.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(Handle&& other) noexcept : id_(other.release()), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept;
  ~Handle() { discard(); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  void close();     // throws IoError
  hid_t release();  // the caller closes the identifier

 private:
  void discard() noexcept;
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

// An identifier returned by an HDF5 call, checked as check_id does, owned with its closer.
Handle owned(hid_t id, Handle::Closer closer, hid_t location, const char* action, const char* name);
// Creation properties (dataset, group or file class) without object modification times.
Handle untimed_creation_properties(hid_t property_class, hid_t location, const char* name);

// Throws IoError "cannot <action> <name> in <file of location>: <reason>" when status < 0.
void check(herr_t status, hid_t location, const char* action, const char* name);
// The same for a call returning an identifier; returns a valid identifier.
hid_t check_id(hid_t id, hid_t location, const char* action, const char* name);

void write_attribute(hid_t object, const char* name, hid_t type, const void* data, hsize_t count = 1);
void write_string_attribute(hid_t object, const char* name, const std::string& value);
inline void write_double(hid_t object, const char* name, double value) { write_attribute(object, name, H5T_NATIVE_DOUBLE, &value); }

// Files a user keeps are written as `<path>.partial` and renamed when complete.  Creates the
// partial file stamped with the format name, its version and Granule's version (root attributes
// `format`, `format_version`, `granule_version`); the caller owns (closes) the identifier.
hid_t create_partial_file(const std::string& path, const char* format, int format_version, const std::string& granule_version);
// Closes a file made by create_partial_file (taking the identifier) and gives it its final name
// `path` only when the close succeeded: otherwise throws IoError and `<path>.partial` remains.
void publish_partial_file(hid_t file, const std::string& path);

// An extendible dataset of frames: shape (frames, row...) with one chunk per frame.  These are
// the file's per-frame datasets: those whose first dimension is unlimited.  The caller owns the
// identifier; add_frames closes it at once.
hid_t create_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row);
void add_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row);
// Writes frame `frame` of a dataset, extending it to frame + 1 frames.
void append_frame(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame);
// Rows first_row .. first_row + rows - 1 of a frame, written block by block (a frame of 10^8
// disks without a copy of it).
void append_frame_rows(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame, hsize_t first_row,
                       hsize_t rows);

// Makes the `.partial` file a killed run left readable as it stood at its last flush: applies a
// journal left behind (io/journaled_file_driver.hpp) and rewrites the superblock's end of
// allocated space, which HDF5's flushes do not always keep up to date.  Throws IoError.
void recover_partial_file(const std::string& partial);

// A file of frames written as `<path>.partial` (snapshots, fields): each frame is flushed when
// complete, and publish() gives the file its final name.  Destroyed unpublished, it leaves
// `<path>.partial`, closed.
class PartialFile {
 public:
  // A new file, as create_partial_file.
  PartialFile(const std::string& path, const char* format, int format_version, const std::string& granule_version);
  // Resume: reopens `<path>.partial` if it exists, else the published `path` renamed back to
  // `<path>.partial` (not copied), and cuts every per-frame dataset to its first `keep_frames`
  // frames (keep_frames < 0: the complete frames).  Throws InputError, before renaming
  // anything, when the file is not of `format` or holds fewer complete frames than asked for.
  PartialFile(const std::string& path, const char* format, std::int64_t keep_frames);

  hid_t get() const { return file_.get(); }
  std::int64_t frames() const { return frames_; }
  void flush();      // the file as it stands (after its layout)
  void end_frame();  // flush and count a frame whose datasets are all written
  void publish();    // close and rename (once; later calls do nothing)

 private:
  std::string path_;
  Handle file_;
  std::int64_t frames_ = 0;
};

// A whole fixed-shape double dataset written at once (shape `dims`, row-major `data`).
void write_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, const std::vector<double>& data);
void write_vector(hid_t location, const char* name, const std::vector<double>& data);
bool has_attribute(hid_t object, const char* name);
bool has_link(hid_t location, const char* name);
// A group; the caller owns the identifier.
hid_t create_group(hid_t location, const char* name);

// Reading a file: every file Granule reads is untrusted.  Each read checks what the file holds
// against what the caller expects (an attribute's number of values, a dataset's rank and shape, a
// numeric or string type) before it copies anything, and bounds every size it takes from the file
// by the bytes the file stores, so that no allocation is sized by a damaged or hostile file.
// Every refusal and every failed read is an InputError naming the file, the object and what was
// expected (granule exits with code 2).  Defined in io/hdf5_read.cpp.

// Opens a file read-only.
Handle open_file(const std::string& path);
// The name of the file an object belongs to (empty when none), for the messages of a refusal.
std::string file_name(hid_t object);
// Reads the `count` values of a numeric attribute (a scalar when count = 1), converted to the
// numeric memory type `type`, into `data`; an integer type reads only attributes stored as integers.
void read_attribute_values(hid_t object, const char* name, hid_t type, void* data, hsize_t count = 1);
template <typename T>
T read_attribute(hid_t object, const char* name, hid_t type) {
  T value{};
  read_attribute_values(object, name, type, &value);
  return value;
}
// A string attribute, fixed-length or variable-length (as h5py writes them).
std::string read_string_attribute(hid_t object, const char* name);

// A shape as a refusal names it: "(3, 4)", "(5,)", "a scalar".
std::string shape_text(const std::vector<hsize_t>& dims);
// Refuses a dataset (`object` names it) whose `count` elements need more bytes than it stores:
// sizes taken from the file are then bounded by the file's own size.
void require_stored(hid_t dataset, hsize_t count, hid_t location, const std::string& object);
// The shape of a dataset.
std::vector<hsize_t> dataset_shape(hid_t location, const char* name);
// The shape of each frame of a per-frame dataset (its shape without the frames axis), refused when
// one frame needs more bytes than the dataset stores.
std::vector<hsize_t> frame_row(hid_t file, const char* name);
// Frame `frame` of the per-frame dataset `name`, whose frames must have the shape `row` (empty for
// a scalar per frame), converted to the numeric memory type `type`, into `data`.
void read_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, const std::vector<hsize_t>& row);
// The same as doubles, allocated after the checks.
std::vector<double> read_frame_values(hid_t file, const char* name, hsize_t frame, const std::vector<hsize_t>& row);
// A whole one-dimensional numeric dataset as doubles; `length`, when given, is the length it must have.
constexpr hsize_t kAnyLength = ~hsize_t{0};
std::vector<double> read_vector(hid_t location, const char* name, hsize_t length = kAnyLength);
// A whole numeric dataset of any shape as doubles, row-major.
std::vector<double> read_values(hid_t location, const char* name);
// Refuses a dataset that stores fewer bytes than its whole shape claims.
void require_whole(hid_t location, const char* name);
// Whether a dataset stores integers (else floats, strings or another class).
bool stored_as_integers(hid_t location, const char* name);

// The frames every per-frame dataset holds: the shortest length, since a run stopped in the
// middle of a frame leaves some datasets one frame longer than others (0 without any).  A dataset
// that claims more frames than it stores (beyond the one a killed run may leave unwritten) is refused.
std::int64_t complete_frames(hid_t file);
// The same for a killed run's file that a resume cuts back to its first `kept` frames (those its
// checkpoint counts, flushed before the checkpoint was published): only they must be stored.  The
// frames after them may be in any state a kill leaves — their extent written while their chunk was
// still in HDF5's cache.
std::int64_t complete_frames(hid_t file, std::int64_t kept);
// The same for the file at `path` (a `.partial` or a published file).
std::int64_t complete_frames(const std::string& path);
// The one-dimensional per-frame dataset `name` of a file of frames (e.g. `shear_velocity` of
// snapshots.h5) over its complete frames; empty when the file has no such dataset.
std::vector<double> read_frame_series(const std::string& path, const char* name);

}  // namespace granule::h5
