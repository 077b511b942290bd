// A large export file streamed to `<path>.partial` and renamed to `<path>` only when complete, so
// that a failed or interrupted export leaves no partial output under the final name.
#pragma once

#include <fstream>
#include <string>

namespace granule {

class StagedFile {
 public:
  explicit StagedFile(std::string path);  // throws IoError naming the path
  ~StagedFile();                          // removes the partial file unless committed
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  std::ofstream& stream() { return out_; }
  void commit();  // flush, close, sync and rename; throws IoError on failure

 private:
  std::string path_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace granule
