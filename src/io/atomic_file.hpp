// Files a user keeps are published atomically and durably: written under a temporary name beside
// the target, synced to disk, renamed, and the directory synced, so that neither a reader nor a
// crash ever sees a half-written file under the final name.
#pragma once

#include <filesystem>
#include <string>

namespace granule {

// Writes `content` to `<path>.tmp` and publishes it as `path`.  Throws IoError naming the file
// (and the system's reason) when anything fails; the temporary is then removed.
void write_file_atomically(const std::string& path, const std::string& content);

// Gives the complete file `temporary` its final name `path`: fsync it, rename it, fsync the
// directory.  Throws IoError; the temporary keeps its name when the rename did not happen.
void publish_file(const std::string& temporary, const std::string& path);

// A temporary file or folder (a `.partial` output, scratch frames), removed whatever happens once
// its owner ends, with the journal of a flush HDF5 did not finish (io/journaled_file_driver.hpp);
// a published output no longer exists under this name, so nothing is lost.
struct RemovedAtExit {
  std::filesystem::path path;
  ~RemovedAtExit() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
    for (const char* journal : {".journal", ".journal.tmp"}) std::filesystem::remove(path.string() + journal, ignored);
  }
};

}  // namespace granule
