// Files a user keeps are written atomically: to a temporary name beside the target, then renamed,
// so that a reader never sees a half-written file.
#pragma once

#include <string>

namespace granule {

// Throws std::runtime_error (naming the path) when the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace granule
