// The pre-flight of a file before Granule opens it (io/hdf5_util.hpp, open_file): the HDF5
// library parses a damaged file's metadata with code that, in the versions Debian ships, can
// crash, corrupt the heap or loop on crafted input (its error paths free what they never
// allocated).  So a child process reads the file first — every object, attribute, link and
// dataset header, and every value of a file up to kFullReadBytes — and only a file the child
// read to the end is opened here.  A child that crashes or hangs past kSeconds, or cannot read the
// file's structure, refuses the file; the parent's memory is never touched by the damage.
#include <fcntl.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "io/hdf5_internal.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {

namespace {

constexpr unsigned kSeconds = 120;
// Files up to this size are read whole by the child (every chunk's checksum verified); larger
// ones (a run of 10^8 disks) have their metadata read.
constexpr off_t kFullReadBytes = off_t{256} << 20;

struct Walk {
  hid_t file;
  bool read_values;
  std::string failure;
};

bool read_attributes(hid_t object, Walk& walk) {
  const auto visit = [](hid_t location, const char* name, const H5A_info_t*, void* data) -> herr_t {
    auto& w = *static_cast<Walk*>(data);
    const hid_t attribute = H5Aopen(location, name, H5P_DEFAULT);
    if (attribute < 0) return -1;
    const hid_t type = H5Aget_type(attribute);
    const hid_t space = H5Aget_space(attribute);
    herr_t status = type < 0 || space < 0 ? -1 : 0;
    const hssize_t points = space < 0 ? -1 : H5Sget_simple_extent_npoints(space);
    const std::size_t size = type < 0 ? 0 : H5Tget_size(type);
    const bool variable = type >= 0 && H5Tis_variable_str(type) > 0;
    if (status == 0 && points >= 0 && size > 0 && !variable && static_cast<std::size_t>(points) * size <= (std::size_t{1} << 24)) {
      std::vector<unsigned char> bytes(static_cast<std::size_t>(points) * size + 1);
      status = H5Aread(attribute, type, bytes.data());
    }
    if (space >= 0) H5Sclose(space);
    if (type >= 0) H5Tclose(type);
    H5Aclose(attribute);
    (void)w;
    return status;
  };
  hsize_t index = 0;
  return H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &index, visit, &walk) >= 0;
}

bool read_dataset(hid_t dataset, bool read_values) {
  const hid_t type = H5Dget_type(dataset);
  const hid_t space = H5Dget_space(dataset);
  const hid_t creation = H5Dget_create_plist(dataset);
  bool ok = type >= 0 && space >= 0 && creation >= 0 && H5Pget_nfilters(creation) >= 0;
  const hssize_t points = ok ? H5Sget_simple_extent_npoints(space) : -1;
  ok = ok && points >= 0;
  ok = ok && H5Pget_layout(creation) != H5D_LAYOUT_ERROR;
  const std::size_t size = ok ? H5Tget_size(type) : 0;
  const bool fixed = ok && H5Tdetect_class(type, H5T_VLEN) == 0 && H5Tis_variable_str(type) == 0;
  // The values are read for what reading them may do to the library (a crash, a hang), not for
  // their errors: a killed run's file has a last frame whose chunks were never written, and the
  // readers refuse damaged values themselves where they read them.
  if (ok && read_values && fixed && points > 0 && size > 0 &&
      static_cast<std::size_t>(points) <= static_cast<std::size_t>(kFullReadBytes) / size) {
    std::vector<unsigned char> bytes(static_cast<std::size_t>(points) * size);
    H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
    H5Eclear2(H5E_DEFAULT);
  }
  if (creation >= 0) H5Pclose(creation);
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  return ok;
}

bool walk_file(Walk& walk) {
  if (!read_attributes(walk.file, walk)) return false;
  const auto visit = [](hid_t file, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    auto& w = *static_cast<Walk*>(data);
    const hid_t object = H5Oopen(file, name, H5P_DEFAULT);
    if (object < 0) return -1;
    bool ok = read_attributes(object, w);
    if (!ok) w.failure = std::string("the attributes of ") + name;
    if (ok && info->type == H5O_TYPE_DATASET) {
      ok = read_dataset(object, w.read_values);
      if (!ok) w.failure = std::string("dataset ") + name;
    }
    if (ok && info->type == H5O_TYPE_GROUP) {
      const auto link = [](hid_t, const char*, const H5L_info_t*, void*) -> herr_t { return 0; };
      hsize_t index = 0;
      ok = H5Literate(object, H5_INDEX_NAME, H5_ITER_INC, &index, link, nullptr) >= 0;
      if (!ok) w.failure = std::string("the links of group ") + name;
    }
    H5Oclose(object);
    return ok ? 0 : -1;
  };
  return H5Ovisit2(walk.file, H5_INDEX_NAME, H5_ITER_INC, visit, &walk, H5O_INFO_BASIC) >= 0;
}

// The child: reads the file, writes the reason of a failure to `report`, exits 0 when it read it all.
[[noreturn]] void preflight_child(const std::string& path, int report) {
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) {  // HDF5's or a sanitizer's report of the damage is the parent's refusal
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  std::signal(SIGALRM, SIG_DFL);
  alarm(kSeconds);
  struct stat status {};
  const bool small = stat(path.c_str(), &status) == 0 && status.st_size <= kFullReadBytes;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::string reason;
  if (file < 0) {
    reason = failure_reason();
  } else {
    Walk walk{file, small, {}};
    if (!walk_file(walk)) {
      reason = failure_reason();
      if (!walk.failure.empty()) reason = walk.failure + ": " + reason;
    }
    if (H5Fclose(file) < 0 && reason.empty()) reason = failure_reason();
  }
  if (!reason.empty()) {
    const ssize_t written = write(report, reason.data(), reason.size());
    (void)written;
  }
  _exit(reason.empty() ? 0 : 1);
}

}  // namespace

void preflight(const std::string& path) {
  // A file is read by the child once per process while it stays the same (its identity, size and
  // modification time): an analysis reads a file's frames one by one.
  struct stat before {};
  if (stat(path.c_str(), &before) != 0) return;  // H5Fopen reports the missing file
  const std::string identity = std::to_string(before.st_dev) + ":" + std::to_string(before.st_ino) + ":" +
                               std::to_string(before.st_size) + ":" + std::to_string(before.st_mtim.tv_sec) + "." +
                               std::to_string(before.st_mtim.tv_nsec);
  static std::mutex mutex;
  static std::set<std::string> verified;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (verified.count(identity) > 0) return;
  }
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return;  // no sandbox to be had: the file is read as it is
  const pid_t child = fork();
  if (child < 0) {
    close(pipe_ends[0]);
    close(pipe_ends[1]);
    return;
  }
  if (child == 0) {
    close(pipe_ends[0]);
    preflight_child(path, pipe_ends[1]);
  }
  close(pipe_ends[1]);
  std::string reason;
  char buffer[512];
  for (ssize_t got; (got = read(pipe_ends[0], buffer, sizeof buffer)) != 0;) {
    if (got > 0) reason.append(buffer, static_cast<std::size_t>(got));
    if (got < 0 && errno != EINTR) break;
  }
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    const std::lock_guard<std::mutex> lock(mutex);
    verified.insert(identity);
    return;
  }
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM) {
    throw InputError("cannot read " + path + ": the HDF5 library did not finish reading its structure in " +
                     std::to_string(kSeconds) + " s (a damaged or crafted file)");
  }
  if (WIFSIGNALED(status) || (WIFEXITED(status) && reason.empty())) {
    throw InputError("cannot read " + path + ": the file is damaged (the HDF5 library failed on its structure)");
  }
  throw InputError("cannot read " + path + ": " + reason);
}

}  // namespace granule::h5
