#pragma once
// An output folder written all or nothing (docs/FORMATS.md "Output folders"): the one place where
// `bpde solve`, `blend`, `sample` and `demo` put their files into DIR.
//
//   OutputFolder out(dir, {"result.json", "surface.obj"});  // checks DIR; writes nothing yet
//   write_json_file(out.file("result.json"), result);       // into the staging folder
//   write_obj(out.file("surface.obj"), mesh);
//   out.commit();                                            // DIR gets both files, or neither
//
// The files are written into a staging folder beside DIR (in DIR's parent, so that every rename
// stays on one file system) named `.bpde-staging-<pid>-<k>`; when DIR exists and its parent is not
// writable (`--out ~` of an ordinary user), inside DIR instead. commit() then
// - renames the staging folder to DIR when DIR does not exist (one atomic rename);
// - when DIR exists, moves each staged file onto DIR/<name> by rename (each replacement atomic),
//   after checking that DIR is a writable directory and no DIR/<name> is a directory. The files
//   it replaces are kept in the staging folder until the last move succeeded: a failed move puts
//   every file back. DIR's other files are never touched.
// Write policy inside the staging folder: the folder is private to this object (a fresh name, no
// other writer), so every file in it is created new and written in one pass (write(), or a
// writer given file(), such as write_obj), each write and the close checked; no temporary file,
// no rename per file and no fsync. Writers that take a path and write it atomically themselves
// (the STEP plugin's write_step, write_view_html) still use their own temporary and fsync for
// the files they write (surface.step, view.html). A file that fails leaves the run to throw and the staging
// folder to be removed: DIR only ever sees complete files, published by the renames of commit().
// Durability: the outputs are complete or absent for every failure of the process (an error, a
// signal, SIGKILL); after a crash of the operating system or a power loss within the kernel's
// write-back interval (about 30 s on Linux) a published file may be empty or short, as with any
// program that does not fsync. Syncing each file would add a disk flush per file to every run,
// several times the report's CPU cost in wall time on a busy disk (docs/performance.md).
// Destroyed without a successful commit() (an exception on the way: a file that cannot be
// written, bad input found late), it removes the staging folder and every parent of DIR it
// created, so DIR and its parents are exactly as they were.
#include <string>
#include <string_view>
#include <vector>

namespace bpde {

class OutputFolder {
 public:
  /// `dir`: the output folder DIR (created with its parents if missing); `names`: the plain file
  /// names that commit() will put into it, all of which must be written through file(). Throws
  /// FileError when DIR cannot be an output folder (it is a file, a name is too long, a target
  /// DIR/<name> is a directory, DIR or its nearest existing parent is not writable). Creates
  /// nothing: the staging folder is made by the first file().
  OutputFolder(std::string dir, std::vector<std::string> names);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// The path to write the file `name` (one of the names) to, inside the staging folder (created,
  /// with DIR's missing parents, on first use; FileError if that fails).
  std::string file(const std::string& name);
  /// Write the file `name` (one of the names) with `bytes` into the staging folder
  /// (write_new_file: one pass, checked, no temporary: see the write policy above).
  void write(const std::string& name, std::string_view bytes);
  /// Put every file into DIR (see above). Throws FileError (DIR as it was) when it cannot.
  void commit();

  /// The checks of the constructor, alone: throws FileError when DIR cannot receive `names`.
  static void check(const std::string& dir, const std::vector<std::string>& names);

 private:
  void stage();
  void abandon() noexcept;

  std::string dir_;       ///< DIR as given (for messages)
  std::string target_;    ///< DIR, normalised (no trailing separator)
  std::string parent_;    ///< the folder that holds DIR and the staging folder
  std::string staging_;   ///< the staging folder ("" until the first file())
  std::string created_;   ///< the topmost parent of DIR this object created ("" if none)
  std::vector<std::string> names_;
  std::vector<bool> written_;
  bool committed_ = false;
  int slot_ = -1;  ///< its entry in the table the SIGINT/SIGTERM handler cleans (-1: none)
};

}  // namespace bpde
