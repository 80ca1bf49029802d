#include "bezierpde/io/output_folder.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <mutex>

#include <algorithm>
#include <atomic>
#include <climits>
#include <filesystem>
#include <system_error>
#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"

namespace bpde {

namespace fs = std::filesystem;

namespace {

// DIR without a trailing separator ("out/demo/" -> "out/demo"), made absolute and with its
// existing part's symbolic links resolved, so that its parent is the folder it really lives in.
fs::path normalised(const std::string& dir) {
  if (dir.empty()) throw FileError("the output folder name is empty");
  fs::path p = fs::path(dir).lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  std::error_code ec;
  fs::path a = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) throw FileError("cannot use output directory '" + dir + "': " + ec.message());
  if (!a.has_filename() && a != a.root_path()) a = a.parent_path();
  return a;
}

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool exists_no_follow(const fs::path& p) {
  std::error_code ec;
  return fs::symlink_status(p, ec).type() != fs::file_type::not_found && !ec;
}

bool writable_dir(const fs::path& p) { return ::access(p.c_str(), W_OK | X_OK) == 0; }

std::string unique_staging_name() {
  static std::atomic<unsigned> counter{0};
  return ".bpde-staging-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

// SIGINT/SIGTERM while a staging folder exists: the handler removes every registered staging
// folder (its files and the one `.previous` level, with async-signal-safe calls only), then
// re-raises the signal with its default action. A folder that is being committed is left alone:
// its `.previous` may hold DIR's old files. Installed on first use, only over the default action.
constexpr int kStagingSlots = 64;
struct StagingSlot {
  std::atomic<int> state{0};  // 0 free, 1 claimed (being set), 2 staging, 3 committing
  char path[PATH_MAX + 1];
};
StagingSlot g_slots[kStagingSlots];

// Remove the entries of the folder `fd` (plain files; folders one level deep when depth > 0).
void unlink_entries(int fd, int depth) {
  alignas(8) char buf[4096];
  for (;;) {
    const long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
    if (n <= 0) return;
    for (long off = 0; off < n;) {
      struct Dirent {
        unsigned long long ino;
        long long off;
        unsigned short reclen;
        unsigned char type;
        char name[1];
      };
      const auto* d = reinterpret_cast<const Dirent*>(buf + off);
      off += d->reclen;
      const char* name = d->name;
      if (!std::strcmp(name, ".") || !std::strcmp(name, "..")) continue;
      if (::unlinkat(fd, name, 0) == 0) continue;
      if (depth > 0) {
        const int sub = ::openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (sub >= 0) {
          unlink_entries(sub, depth - 1);
          ::close(sub);
        }
        ::unlinkat(fd, name, AT_REMOVEDIR);
      }
    }
  }
}

extern "C" void remove_staging_on_signal(int sig) {
  const int saved = errno;
  for (StagingSlot& slot : g_slots) {
    if (slot.state.load() != 2) continue;
    const int fd = ::open(slot.path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
      unlink_entries(fd, 1);
      ::close(fd);
    }
    ::rmdir(slot.path);
  }
  errno = saved;
  std::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_staging_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_staging_on_signal;
      sigemptyset(&sa.sa_mask);
      sigaddset(&sa.sa_mask, SIGINT);
      sigaddset(&sa.sa_mask, SIGTERM);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

// The slot of a new staging folder (-1: none free; the folder is then not cleaned on a signal).
int register_staging(const std::string& path) {
  install_staging_handlers();
  if (path.size() > PATH_MAX) return -1;
  for (int i = 0; i < kStagingSlots; ++i) {
    int expected = 0;
    if (!g_slots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(2);
    return i;
  }
  return -1;
}

void set_staging_state(int slot, int state) {
  if (slot >= 0) g_slots[slot].state.store(state);
}

}  // namespace

void OutputFolder::check(const std::string& dir, const std::vector<std::string>& names) {
  const fs::path t = normalised(dir);
  const std::string fail = "cannot write output directory '" + dir + "': ";
  for (const fs::path& part : t)
    if (part.native().size() > NAME_MAX)
      throw FileError(fail + "a name in it is longer than " + std::to_string(NAME_MAX) + " bytes");
  if (exists_no_follow(t) || is_dir(t)) {
    if (!is_dir(t)) throw FileError(fail + "it exists and is not a directory");
    if (!writable_dir(t)) throw FileError(fail + "it is not writable");
    for (const std::string& n : names)
      if (is_dir(t / n)) throw FileError("cannot write '" + (fs::path(dir) / n).string() + "': it is a directory");
    return;
  }
  // DIR is missing: its nearest existing parent must be a writable directory.
  fs::path p = t.parent_path();
  while (!p.empty() && !exists_no_follow(p) && p != p.root_path()) p = p.parent_path();
  if (!is_dir(p)) throw FileError(fail + "its parent '" + p.string() + "' is not a directory");
  if (!writable_dir(p)) throw FileError(fail + "its parent '" + p.string() + "' is not writable");
}

OutputFolder::OutputFolder(std::string dir, std::vector<std::string> names)
    : dir_(std::move(dir)), names_(std::move(names)), written_(names_.size(), false) {
  check(dir_, names_);
  const fs::path t = normalised(dir_);
  target_ = t.string();
  parent_ = t.parent_path().string();
}

OutputFolder::~OutputFolder() {
  if (!committed_) abandon();
}

void OutputFolder::stage() {
  if (!staging_.empty()) return;
  const fs::path parent(parent_);
  // Remember the topmost missing parent: it is removed again if the run fails.
  fs::path top;
  for (fs::path p = parent; !p.empty() && !exists_no_follow(p) && p != p.root_path(); p = p.parent_path()) top = p;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (!top.empty() && exists_no_follow(top)) created_ = top.string();
  if (ec || !is_dir(parent)) {
    abandon();
    throw FileError("cannot create output directory '" + dir_ + "': " +
                    (ec ? ec.message() : std::string("a parent is not a directory")));
  }
  // Beside DIR when its parent is writable; inside an existing DIR otherwise (a user who may write
  // DIR but not its parent, as with `--out ~`). Both keep every rename on DIR's file system.
  const fs::path t(target_);
  const fs::path home = !writable_dir(parent) && is_dir(t) ? t : parent;
  const fs::path s = home / unique_staging_name();
  slot_ = register_staging(s.string());
  if (!fs::create_directory(s, ec) || ec) {
    abandon();
    throw FileError("cannot create output directory '" + dir_ + "': " + ec.message());
  }
  staging_ = s.string();
}

std::string OutputFolder::file(const std::string& name) {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw InternalError("OutputFolder: '" + name + "' is not one of its files");
  stage();
  written_[static_cast<size_t>(it - names_.begin())] = true;
  return (fs::path(staging_) / name).string();
}

void OutputFolder::write(const std::string& name, std::string_view bytes) { write_new_file(file(name), bytes); }

void OutputFolder::commit() {
  for (size_t i = 0; i < names_.size(); ++i)
    if (!written_[i]) throw InternalError("OutputFolder: '" + names_[i] + "' was not written");
  stage();  // (no names: an empty folder)
  check(dir_, names_);
  const fs::path t(target_), s(staging_);
  std::error_code ec;
  set_staging_state(slot_, 3);
  struct Release {  // back to "staging" if the commit throws (abandon() then removes it)
    OutputFolder& self;
    ~Release() {
      if (!self.committed_) set_staging_state(self.slot_, 2);
    }
  } release{*this};
  if (!exists_no_follow(t)) {
    fs::rename(s, t, ec);
    if (ec) throw FileError("cannot write output directory '" + dir_ + "': " + ec.message());
    committed_ = true;
    set_staging_state(slot_, 0);
    slot_ = -1;
    return;
  }
  // DIR exists: replace its files one by one, keeping the old ones in the staging folder until the
  // last move succeeded. An old file is swapped with the new one (renameat2 RENAME_EXCHANGE: one
  // atomic step that leaves the old file at the new one's staging name); on a file system without
  // the exchange it is first moved into `.previous`, then the new one renamed into place.
  const fs::path backup = s / ".previous";
  enum class How { New, Exchanged, Backed };
  struct Moved {
    std::string name;
    How how;
  };
  std::vector<Moved> moved;
  bool exchange = true;
  const auto undo = [&] {
    std::error_code ignore;
    for (auto m = moved.rbegin(); m != moved.rend(); ++m) {
      const fs::path staged = s / m->name, placed = t / m->name;
      if (m->how == How::Exchanged) {
        ::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, placed.c_str(), RENAME_EXCHANGE);
      } else {
        fs::rename(placed, staged, ignore);
        if (m->how == How::Backed) fs::rename(backup / m->name, placed, ignore);
      }
    }
  };
  const auto failed = [&](const std::string& n, const std::string& why) {
    undo();
    throw FileError("cannot write '" + (fs::path(dir_) / n).string() + "': " + why);
  };
  for (const std::string& n : names_) {
    const fs::path staged = s / n, placed = t / n;
    if (is_dir(placed)) failed(n, "it is a directory");  // (checked above; a directory is never moved away)
    if (exchange) {
      if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, placed.c_str(), RENAME_EXCHANGE) == 0) {
        moved.push_back({n, How::Exchanged});
        continue;
      }
      const int err = errno;
      if (err == EINVAL || err == ENOSYS || err == EOPNOTSUPP) {
        exchange = false;  // not on this file system: the backup folder instead
      } else if (err != ENOENT) {
        failed(n, std::strerror(err));
      }
    }
    const bool had_old = exists_no_follow(placed);
    if (had_old) {
      ec.clear();
      if (!is_dir(backup)) fs::create_directory(backup, ec);
      if (!ec) fs::rename(placed, backup / n, ec);
      if (ec) failed(n, ec.message());
    }
    fs::rename(staged, placed, ec);
    if (ec) {
      std::error_code ignore;
      if (had_old) fs::rename(backup / n, placed, ignore);
      failed(n, ec.message());
    }
    moved.push_back({n, had_old ? How::Backed : How::New});
  }
  committed_ = true;
  fs::remove_all(s, ec);  // the replaced files (a leftover folder is harmless)
  set_staging_state(slot_, 0);
  slot_ = -1;
}

void OutputFolder::abandon() noexcept {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  staging_.clear();
  set_staging_state(slot_, 0);
  slot_ = -1;
  // Only folders this object created, which hold nothing but the staging folder's chain.
  if (!created_.empty()) fs::remove_all(created_, ec);
  created_.clear();
}

}  // namespace bpde
