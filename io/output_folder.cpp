#include "bezierpde/io/output_folder.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <filesystem>
#include <system_error>
#include <utility>

#include "bezierpde/core/errors.h"

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
  const fs::path s = parent / unique_staging_name();
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

void OutputFolder::commit() {
  for (size_t i = 0; i < names_.size(); ++i)
    if (!written_[i]) throw InternalError("OutputFolder: '" + names_[i] + "' was not written");
  stage();  // (no names: an empty folder)
  check(dir_, names_);
  const fs::path t(target_), s(staging_);
  std::error_code ec;
  if (!exists_no_follow(t)) {
    fs::rename(s, t, ec);
    if (ec) throw FileError("cannot write output directory '" + dir_ + "': " + ec.message());
    committed_ = true;
    return;
  }
  // DIR exists: replace its files one by one, keeping the old ones until the last move succeeded.
  const fs::path backup = s / ".previous";
  fs::create_directory(backup, ec);
  if (ec) throw FileError("cannot write output directory '" + dir_ + "': " + ec.message());
  struct Moved {
    std::string name;
    bool had_old;
  };
  std::vector<Moved> moved;
  const auto undo = [&] {
    std::error_code ignore;
    for (auto m = moved.rbegin(); m != moved.rend(); ++m) {
      fs::rename(t / m->name, s / m->name, ignore);
      if (m->had_old) fs::rename(backup / m->name, t / m->name, ignore);
    }
  };
  for (const std::string& n : names_) {
    const bool had_old = exists_no_follow(t / n);
    if (had_old) {
      if (is_dir(t / n)) {  // (checked above; a directory must never be moved away)
        undo();
        throw FileError("cannot write '" + (fs::path(dir_) / n).string() + "': it is a directory");
      }
      fs::rename(t / n, backup / n, ec);
      if (ec) {
        undo();
        throw FileError("cannot write '" + (fs::path(dir_) / n).string() + "': " + ec.message());
      }
    }
    fs::rename(s / n, t / n, ec);
    if (ec) {
      std::error_code ignore;
      if (had_old) fs::rename(backup / n, t / n, ignore);
      undo();
      throw FileError("cannot write '" + (fs::path(dir_) / n).string() + "': " + ec.message());
    }
    moved.push_back({n, had_old});
  }
  committed_ = true;
  fs::remove_all(s, ec);  // the replaced files (a leftover folder is harmless)
}

void OutputFolder::abandon() noexcept {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  staging_.clear();
  // Only folders this object created, which hold nothing but the staging folder's chain.
  if (!created_.empty()) fs::remove_all(created_, ec);
  created_.clear();
}

}  // namespace bpde
