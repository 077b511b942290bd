// Files a user keeps are published atomically and durably: written under a temporary name beside
// the target, synced to disk, renamed, and the directory synced, so that neither a reader nor a
// crash ever sees a half-written file under the final name.
#pragma once

#include <string>

namespace granule {

// Writes `content` to `<path>.tmp` and publishes it as `path`.  Throws IoError naming the file
// (and the system's reason) when anything fails; the temporary is then removed.
void write_file_atomically(const std::string& path, const std::string& content);

// Gives the complete file `temporary` its final name `path`: fsync it, rename it, fsync the
// directory.  Throws IoError; the temporary keeps its name when the rename did not happen.
void publish_file(const std::string& temporary, const std::string& path);

}  // namespace granule
