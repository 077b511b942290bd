#include "io/export_file.hpp"

#include <cerrno>
#include <cstdio>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace granule {

StagedFile::StagedFile(std::string path) : path_(std::move(path)), out_(path_ + ".partial", std::ios::binary | std::ios::trunc) {
  if (!out_) throw io_error("cannot create " + path_ + ".partial", errno);
}

StagedFile::~StagedFile() {
  if (!committed_) {
    out_.close();
    std::remove((path_ + ".partial").c_str());
  }
}

void StagedFile::commit() {
  // A stream records only that something failed: errno still holds the reason of the failed call.
  out_.flush();
  if (!out_) throw io_error("cannot write " + path_ + ".partial", errno);
  out_.close();  // writes what the stream still buffers
  if (!out_) throw io_error("cannot write " + path_ + ".partial", errno);
  publish_file(path_ + ".partial", path_);
  committed_ = true;
}

}  // namespace granule
