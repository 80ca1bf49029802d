#include "bezierpde/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

namespace fs = std::filesystem;

std::string temp_path_for(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  const fs::path p(path);
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "." + std::string.
  std::string name(1, '.');
  name += p.filename().string();
  name += ".bpde-tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter.fetch_add(1));
  return (p.parent_path() / name).string();
}

[[noreturn]] void fail(const std::string& path, const char* what, int err) {
  throw FileError("cannot write file '" + path + "' (" + what + ": " + std::strerror(err) + ")");
}

// fsync and close `fd` (open on `tmp`), then rename `tmp` onto `path`; removes `tmp` and throws
// FileError on failure.
void sync_close_rename(int fd, const std::string& tmp, const std::string& path) {
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, "fsync", err);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "close", err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename", err);
  }
}

// fsync and rename `tmp` onto `path`; removes `tmp` and throws FileError on failure.
void commit(const std::string& tmp, const std::string& path) {
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "open", err);
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const int err = errno ? errno : EINVAL;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, "not a regular file", err);
  }
  sync_close_rename(fd, tmp, path);
}

// Create `tmp` (exclusively) and write `bytes` to it; returns the open descriptor. On failure
// removes `tmp` and throws FileError naming `path`.
int create_and_write(const std::string& tmp, const std::string& path, std::string_view bytes) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, "create", errno);
  const char* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      ::unlink(tmp.c_str());
      fail(path, "write", err);
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  return fd;
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  const std::string tmp = temp_path_for(path);
  sync_close_rename(create_and_write(tmp, path, bytes), tmp, path);
}

void write_new_file(const std::string& path, std::string_view bytes) {
  const int fd = create_and_write(path, path, bytes);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(path.c_str());
    fail(path, "close", err);
  }
}

void replace_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write_to) {
  const std::string tmp = temp_path_for(path);
  try {
    write_to(tmp);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  commit(tmp, path);
}

}  // namespace bpde
