#include "io/export_file.hpp"

#include <filesystem>
#include <stdexcept>

namespace granule {

StagedFile::StagedFile(std::string path) : path_(std::move(path)), out_(path_ + ".partial", std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot write " + path_ + ".partial");
}

StagedFile::~StagedFile() {
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(path_ + ".partial", ignored);
  }
}

void StagedFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write " + path_ + ".partial");
  out_.close();
  std::filesystem::rename(path_ + ".partial", path_);
  committed_ = true;
}

}  // namespace granule
