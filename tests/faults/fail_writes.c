/* Fault injection for Granule's I/O tests (tests/cli/test_io_faults.py), loaded with LD_PRELOAD:
 * a disk that fills up.  Once GRANULE_FAULT_BUDGET bytes have been written to regular files, every
 * further write fails with ENOSPC (GRANULE_FAULT_ERRNO=EIO: with EIO); the write that crosses the
 * budget is short, as on a nearly full disk; fsync, fdatasync and rename fail once the budget is
 * spent (a full disk may report a lost write only there).  Intercepted: write, pwrite, pwrite64,
 * writev (HDF5's sec2 driver and libstdc++'s file streams) and fwrite (cairo's PNG writer).
 *   GRANULE_FAULT_PATH    only files whose name contains this text count and fail
 *   GRANULE_FAULT_REPORT  at exit, write the bytes counted to this file (to measure a clean run)
 * Pipes, terminals and devices (stdout, stderr) are never touched. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

static long long budget = -1; /* bytes; negative: unlimited */
static long long used = 0;
static int fault_errno = ENOSPC;
static const char* path_pattern = NULL;

__attribute__((constructor)) static void read_settings(void) {
  const char* text = getenv("GRANULE_FAULT_BUDGET");
  if (text && *text) budget = atoll(text);
  text = getenv("GRANULE_FAULT_ERRNO");
  if (text && strcmp(text, "EIO") == 0) fault_errno = EIO;
  text = getenv("GRANULE_FAULT_PATH");
  if (text && *text) path_pattern = text;
}

static void* next_symbol(const char* name) {
  void* symbol = dlsym(RTLD_NEXT, name);
  if (!symbol) abort();
  return symbol;
}
/* The libc function this library stands in front of (a union: ISO C has no cast from the object
 * pointer dlsym returns to a function pointer). */
#define REAL(name) ((union { void* object; __typeof__(&name) function; }){next_symbol(#name)}.function)

/* Whether the file name (the last component of `path`) contains the pattern. */
static int path_matches(const char* path) {
  const char* name = strrchr(path, '/');
  return path_pattern == NULL || strstr(name ? name + 1 : path, path_pattern) != NULL;
}

/* Whether the file behind `fd` is one the fault applies to: a regular file or a directory
 * (fsync of a directory), on a path matching the pattern. */
static int watched(int fd) {
  struct stat status;
  if (fstat(fd, &status) != 0 || !(S_ISREG(status.st_mode) || S_ISDIR(status.st_mode))) return 0;
  if (path_pattern == NULL) return 1;
  char link[64], path[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t length = readlink(link, path, sizeof path - 1);
  if (length < 0) return 0;
  path[length] = '\0';
  return path_matches(path);
}

static int spent(void) { return budget >= 0 && __atomic_load_n(&used, __ATOMIC_SEQ_CST) >= budget; }

/* Bytes of a `count`-byte write that may go to `fd`: all of them for unwatched files, else what
 * is left of the budget (0: the write fails). */
static size_t allowance(int fd, size_t count) {
  if (budget < 0 || !watched(fd)) return count;
  const long long left = budget - __atomic_load_n(&used, __ATOMIC_SEQ_CST);
  if (left <= 0) return 0;
  return (unsigned long long)left < count ? (size_t)left : count;
}

static ssize_t counted(int fd, ssize_t written) {
  if (written > 0 && watched(fd)) __atomic_add_fetch(&used, (long long)written, __ATOMIC_SEQ_CST);
  return written;
}

static ssize_t refuse(void) {
  errno = fault_errno;
  return -1;
}

ssize_t write(int fd, const void* data, size_t count) {
  const size_t allowed = allowance(fd, count);
  if (allowed == 0 && count > 0) return refuse();
  return counted(fd, REAL(write)(fd, data, allowed));
}

ssize_t pwrite(int fd, const void* data, size_t count, off_t offset) {
  const size_t allowed = allowance(fd, count);
  if (allowed == 0 && count > 0) return refuse();
  return counted(fd, REAL(pwrite)(fd, data, allowed, offset));
}

ssize_t pwrite64(int fd, const void* data, size_t count, off64_t offset) {
  const size_t allowed = allowance(fd, count);
  if (allowed == 0 && count > 0) return refuse();
  return counted(fd, REAL(pwrite64)(fd, data, allowed, offset));
}

ssize_t writev(int fd, const struct iovec* vectors, int count) {
  size_t total = 0;
  for (int i = 0; i < count; ++i) total += vectors[i].iov_len;
  const size_t allowed = allowance(fd, total);
  if (allowed == 0 && total > 0) return refuse();
  if (allowed == total) return counted(fd, REAL(writev)(fd, vectors, count));
  /* A short write: the first `allowed` bytes, as one plain write. */
  char* joined = malloc(allowed);
  if (!joined) return refuse();
  size_t at = 0;
  for (int i = 0; i < count && at < allowed; ++i) {
    const size_t part = vectors[i].iov_len < allowed - at ? vectors[i].iov_len : allowed - at;
    memcpy(joined + at, vectors[i].iov_base, part);
    at += part;
  }
  const ssize_t written = REAL(write)(fd, joined, allowed);
  free(joined);
  return counted(fd, written);
}

size_t fwrite(const void* data, size_t size, size_t items, FILE* stream) {
  if (size == 0 || items == 0) return REAL(fwrite)(data, size, items, stream);
  const int fd = fileno(stream);
  const size_t allowed = allowance(fd, size * items) / size;
  const size_t written = allowed == 0 ? 0 : REAL(fwrite)(data, size, allowed, stream);
  counted(fd, (ssize_t)(written * size));
  if (written < items) {
    errno = fault_errno;
    stream->_flags |= _IO_ERR_SEEN; /* what glibc's failed write sets: ferror(stream) is true */
  }
  return written;
}

int fsync(int fd) {
  if (spent() && watched(fd)) return (int)refuse();
  return REAL(fsync)(fd);
}

int fdatasync(int fd) {
  if (spent() && watched(fd)) return (int)refuse();
  return REAL(fdatasync)(fd);
}

int rename(const char* from, const char* to) {
  if (spent() && (path_matches(from) || path_matches(to))) return (int)refuse();
  return REAL(rename)(from, to);
}

__attribute__((destructor)) static void report(void) {
  const char* path = getenv("GRANULE_FAULT_REPORT");
  if (!path || !*path) return;
  char text[32];
  const int length = snprintf(text, sizeof text, "%lld\n", used);
  const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return;
  if (REAL(write)(fd, text, (size_t)length) != length) perror("fail_writes: report");
  close(fd);
}
