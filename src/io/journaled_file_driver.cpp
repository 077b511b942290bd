#include "io/journaled_file_driver.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {
namespace {

constexpr char kMagic[8] = {'G', 'R', 'N', 'L', 'J', 'R', 'N', '1'};
// The largest address: that of a signed 64-bit file offset, as HDF5's own POSIX driver.
constexpr haddr_t kMaxAddress = (haddr_t{1} << 63) - 1;

struct HeldWrite {
  haddr_t address;
  std::vector<unsigned char> bytes;
};

// HDF5 fills `pub` after open; it must come first.
struct JournaledFile {
  H5FD_t pub;
  int fd = -1;
  std::string path;
  dev_t device = 0;
  ino_t inode = 0;
  haddr_t eoa = 0;  // end of the space HDF5 has allocated
  // The largest end of allocated space since the last commit: the superblock a flush writes may
  // state any of them, and the file must be at least that long or HDF5 calls it truncated.
  haddr_t eoa_since_commit = 0;
  haddr_t eof = 0;  // end of the bytes written, held ones included
  std::vector<HeldWrite> held;  // metadata since the last commit, in order
};

JournaledFile* as_file(H5FD_t* file) { return reinterpret_cast<JournaledFile*>(file); }
const JournaledFile* as_file(const H5FD_t* file) { return reinterpret_cast<const JournaledFile*>(file); }

std::string journal_of(const std::string& path) { return path + ".journal"; }

// Puts the system's reason on HDF5's error stack in the words HDF5's own POSIX driver uses
// ("error message = '...'"), where Granule's error messages look for it (io/hdf5_util.cpp).
void report(const char* function, H5E_minor_t minor, const std::string& reason) {
  H5Epush2(H5E_DEFAULT, __FILE__, function, __LINE__, H5E_ERR_CLS, H5E_VFL, minor, "error message = '%s'", reason.c_str());
}

void append_u64(std::string& out, std::uint64_t value) { out.append(reinterpret_cast<const char*>(&value), sizeof value); }

// FNV-1a: the journal is synced before its rename, so this only guards against a damaged disk.
std::uint64_t checksum(const char* data, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t k = 0; k < size; ++k) hash = (hash ^ static_cast<unsigned char>(data[k])) * 1099511628211ull;
  return hash;
}

void write_all_at(int fd, const unsigned char* data, std::size_t size, haddr_t address, const std::string& path) {
  while (size > 0) {
    const ssize_t written = ::pwrite(fd, data, size, static_cast<off_t>(address));
    if (written < 0) {
      if (errno == EINTR) continue;
      throw io_error("cannot write " + path, errno);
    }
    data += written;
    size -= static_cast<std::size_t>(written);
    address += static_cast<haddr_t>(written);
  }
}

// Journal layout: magic, the least length of the file, the count, then per write its address, size
// and bytes, then the checksum of everything before it (all integers 64-bit, this machine's byte
// order: the journal never travels, it is applied or discarded where it was written).
void apply_journal_content(const std::string& content, int fd, const std::string& path) {
  const std::string damaged = journal_of(path) + " is damaged; the file it would repair, " + path + ", may be too";
  auto read_u64 = [&](std::size_t& at) {
    if (at + 8 > content.size()) throw IoError(damaged);
    std::uint64_t value = 0;
    std::memcpy(&value, content.data() + at, 8);
    at += 8;
    return value;
  };
  if (content.size() < sizeof kMagic + 24 || std::memcmp(content.data(), kMagic, sizeof kMagic) != 0) throw IoError(damaged);
  std::size_t end = content.size() - 8;
  std::size_t at = end;
  if (read_u64(at) != checksum(content.data(), end)) throw IoError(damaged);
  at = sizeof kMagic;
  const std::uint64_t length = read_u64(at);
  const std::uint64_t count = read_u64(at);
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t address = read_u64(at);
    const std::uint64_t size = read_u64(at);
    if (size > end - std::min(at, end)) throw IoError(damaged);
    write_all_at(fd, reinterpret_cast<const unsigned char*>(content.data() + at), size, address, path);
    at += size;
  }
  if (at != end) throw IoError(damaged);
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw io_error("cannot read the size of " + path, errno);
  if (static_cast<std::uint64_t>(status.st_size) < length && ::ftruncate(fd, static_cast<off_t>(length)) != 0) {
    throw io_error("cannot extend " + path, errno);
  }
  if (::fsync(fd) != 0) throw io_error("cannot sync " + path + " to disk", errno);
}

// The held writes: journal, apply, sync, forget.  Throws IoError.
void commit(JournaledFile& file) {
  if (file.held.empty()) return;
  std::string content(kMagic, sizeof kMagic);
  append_u64(content, std::max(file.eoa, file.eoa_since_commit));
  append_u64(content, file.held.size());
  for (const HeldWrite& w : file.held) {
    append_u64(content, w.address);
    append_u64(content, w.bytes.size());
    content.append(reinterpret_cast<const char*>(w.bytes.data()), w.bytes.size());
  }
  append_u64(content, checksum(content.data(), content.size()));
  const std::string journal = journal_of(file.path);
  write_file_atomically(journal, content);
  apply_journal_content(content, file.fd, file.path);
  if (std::remove(journal.c_str()) != 0) throw io_error("cannot remove " + journal, errno);
  file.held.clear();
  file.eof = std::max(file.eof, std::max(file.eoa, file.eoa_since_commit));
  file.eoa_since_commit = file.eoa;
}

H5FD_t* open_file(const char* name, unsigned flags, hid_t, haddr_t maxaddr) {
  if (name == nullptr || *name == '\0' || maxaddr == 0 || maxaddr > kMaxAddress) return nullptr;
  int mode = (flags & H5F_ACC_RDWR) ? O_RDWR : O_RDONLY;
  if (flags & H5F_ACC_TRUNC) mode |= O_TRUNC;
  if (flags & H5F_ACC_CREAT) mode |= O_CREAT;
  if (flags & H5F_ACC_EXCL) mode |= O_EXCL;
  try {
    if (flags & H5F_ACC_TRUNC) {
      std::filesystem::remove(journal_of(name));
    } else if (flags & H5F_ACC_RDWR) {
      replay_journal(name);
    }
  } catch (const std::exception& error) {
    report("open", H5E_CANTOPENFILE, error.what());
    return nullptr;
  }
  const int fd = ::open(name, mode | O_CLOEXEC, 0644);
  if (fd < 0) {
    report("open", H5E_CANTOPENFILE, std::strerror(errno));
    return nullptr;
  }
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    ::close(fd);
    return nullptr;
  }
  auto* file = new (std::nothrow) JournaledFile{};
  if (file == nullptr) {
    ::close(fd);
    return nullptr;
  }
  file->fd = fd;
  file->path = name;
  file->device = status.st_dev;
  file->inode = status.st_ino;
  file->eof = static_cast<haddr_t>(status.st_size);
  return &file->pub;
}

herr_t close_file(H5FD_t* handle) {
  JournaledFile* file = as_file(handle);
  herr_t result = 0;
  try {
    commit(*file);
  } catch (const std::exception& error) {
    report("close", H5E_CANTCLOSEFILE, error.what());
    result = -1;
  }
  if (::close(file->fd) != 0) {
    report("close", H5E_CANTCLOSEFILE, std::strerror(errno));
    result = -1;
  }
  delete file;
  return result;
}

int compare_files(const H5FD_t* a, const H5FD_t* b) {
  const JournaledFile* x = as_file(a);
  const JournaledFile* y = as_file(b);
  if (x->device != y->device) return x->device < y->device ? -1 : 1;
  if (x->inode != y->inode) return x->inode < y->inode ? -1 : 1;
  return 0;
}

herr_t query(const H5FD_t*, unsigned long* flags) {
  // As HDF5's POSIX driver, less file images.  SWMR_IO (POSIX reads and writes, as that driver's)
  // is what H5Fincrement_filesize asks for; Granule never opens a file in SWMR mode.
  *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
           H5FD_FEAT_AGGREGATE_SMALLDATA | H5FD_FEAT_POSIX_COMPAT_HANDLE | H5FD_FEAT_DEFAULT_VFD_COMPATIBLE |
           H5FD_FEAT_SUPPORTS_SWMR_IO;
  return 0;
}

haddr_t get_eoa(const H5FD_t* file, H5FD_mem_t) { return as_file(file)->eoa; }

herr_t set_eoa(H5FD_t* file, H5FD_mem_t, haddr_t address) {
  JournaledFile* f = as_file(file);
  f->eoa = address;
  f->eoa_since_commit = std::max(f->eoa_since_commit, address);
  return 0;
}

haddr_t get_eof(const H5FD_t* file, H5FD_mem_t) { return as_file(file)->eof; }

herr_t get_handle(H5FD_t* file, hid_t, void** handle) {
  *handle = &as_file(file)->fd;
  return 0;
}

herr_t read_bytes(H5FD_t* handle, H5FD_mem_t, hid_t, haddr_t address, size_t size, void* buffer) {
  JournaledFile* file = as_file(handle);
  if (address + size > file->eoa) return -1;
  auto* out = static_cast<unsigned char*>(buffer);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t got = ::pread(file->fd, out + done, size - done, static_cast<off_t>(address + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      report("read", H5E_READERROR, std::strerror(errno));
      return -1;
    }
    if (got == 0) {  // past the end of the bytes on disk: zeros, as HDF5's POSIX driver reads
      std::fill(out + done, out + size, 0);
      break;
    }
    done += static_cast<std::size_t>(got);
  }
  for (const HeldWrite& w : file->held) {  // in order, so that a later write wins
    const haddr_t first = std::max(address, w.address);
    const haddr_t last = std::min<haddr_t>(address + size, w.address + w.bytes.size());
    if (first < last) std::memcpy(out + (first - address), w.bytes.data() + (first - w.address), last - first);
  }
  return 0;
}

herr_t write_bytes(H5FD_t* handle, H5FD_mem_t type, hid_t, haddr_t address, size_t size, const void* buffer) {
  JournaledFile* file = as_file(handle);
  if (address + size > file->eoa) return -1;
  const auto* bytes = static_cast<const unsigned char*>(buffer);
  try {
    if (type == H5FD_MEM_DRAW) {
      write_all_at(file->fd, bytes, size, address, file->path);
    } else {
      file->held.push_back({address, std::vector<unsigned char>(bytes, bytes + size)});
    }
  } catch (const std::exception& error) {
    report("write", H5E_WRITEERROR, error.what());
    return -1;
  }
  file->eof = std::max<haddr_t>(file->eof, address + size);
  return 0;
}

// HDF5 calls these at the end of a flush and at close: the flush's metadata is complete.
herr_t flush_file(H5FD_t* handle, hid_t, hbool_t) {
  try {
    commit(*as_file(handle));
  } catch (const std::exception& error) {
    report("flush", H5E_WRITEERROR, error.what());
    return -1;
  }
  return 0;
}

// The file is cut to the end of allocated space only when closed: before, a superblock on disk may
// state a larger end (eoa_since_commit).
herr_t truncate_file(H5FD_t* handle, hid_t dxpl, hbool_t closing) {
  JournaledFile* file = as_file(handle);
  if (flush_file(handle, dxpl, closing) < 0) return -1;
  if (!closing || file->eoa == file->eof) return 0;
  if (::ftruncate(file->fd, static_cast<off_t>(file->eoa)) != 0) {
    report("truncate", H5E_SEEKERROR, std::strerror(errno));
    return -1;
  }
  file->eof = file->eoa;
  return 0;
}

H5FD_class_t make_class() {
  H5FD_class_t c{};
  c.name = "granule_journaled";
  c.maxaddr = kMaxAddress;
  c.fc_degree = H5F_CLOSE_WEAK;
  c.open = open_file;
  c.close = close_file;
  c.cmp = compare_files;
  c.query = query;
  c.get_eoa = get_eoa;
  c.set_eoa = set_eoa;
  c.get_eof = get_eof;
  c.get_handle = get_handle;
  c.read = read_bytes;
  c.write = write_bytes;
  c.flush = flush_file;
  c.truncate = truncate_file;
  const H5FD_mem_t map[H5FD_MEM_NTYPES] = H5FD_FLMAP_DICHOTOMY;
  std::copy(std::begin(map), std::end(map), c.fl_map);
  return c;
}

}  // namespace

hid_t journaled_file_driver() {
  static const H5FD_class_t driver_class = make_class();
  static const hid_t id = H5FDregister(&driver_class);
  return id;
}

void replay_journal(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(journal_of(path) + ".tmp", ignored);  // never renamed: never applied
  const std::string journal = journal_of(path);
  if (!std::filesystem::exists(journal)) return;
  std::ifstream in(journal, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw IoError("cannot read " + journal);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw io_error("cannot open " + path + " to apply " + journal, errno);
  try {
    apply_journal_content(content, fd, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw io_error("cannot close " + path, errno);
  if (std::remove(journal.c_str()) != 0) throw io_error("cannot remove " + journal, errno);
}

}  // namespace granule::h5
