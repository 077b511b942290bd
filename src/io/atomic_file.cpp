#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>

#include "io/io_error.hpp"

namespace granule {

namespace {

// A POSIX file descriptor closed once; close() reports the error a deferred write may surface.
class Descriptor {
 public:
  Descriptor(const std::string& path, int flags, mode_t mode = 0) : path_(path), fd_(::open(path.c_str(), flags | O_CLOEXEC, mode)) {
    if (fd_ < 0) throw io_error(((flags & O_CREAT) ? "cannot create " : "cannot open ") + path_, errno);
  }
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;

  void write_all(const std::string& content) {
    std::size_t done = 0;
    while (done < content.size()) {  // a write may be short (signal, nearly full disk)
      const ssize_t n = ::write(fd_, content.data() + done, content.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw io_error("cannot write " + path_, errno);
      done += static_cast<std::size_t>(n);
    }
  }
  void sync() {
    if (::fsync(fd_) != 0) throw io_error("cannot sync " + path_ + " to disk", errno);
  }
  void close() {
    const int status = ::close(fd_);
    fd_ = -1;
    if (status != 0) throw io_error("cannot close " + path_, errno);
  }

 private:
  std::string path_;
  int fd_;
};

std::string directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

}  // namespace

void publish_file(const std::string& temporary, const std::string& path) {
  {
    Descriptor file(temporary, O_RDONLY);
    file.sync();
    file.close();
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw io_error("cannot rename " + temporary + " to " + path, errno);
  // The rename itself is durable only once the directory is.
  Descriptor directory(directory_of(path), O_RDONLY | O_DIRECTORY);
  directory.sync();
  directory.close();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".tmp";
  try {
    Descriptor file(temporary, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    file.write_all(content);
    file.close();
    publish_file(temporary, path);
  } catch (const IoError&) {
    std::remove(temporary.c_str());  // nothing to keep: the caller still has the content
    throw;
  }
}

}  // namespace granule
