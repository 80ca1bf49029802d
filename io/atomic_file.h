#pragma once
// Writing a file all or nothing: the one place where bezierpde replaces a file's content.
//
//   write_file_atomically("out/results.csv", text);
//
// The bytes go to a temporary file beside the target (same folder, so the rename stays on one
// file system), named `.<name>.bpde-tmp-<pid>-<k>`. Every write is checked, the file is flushed
// to disk (fsync) and closed (checked), and only then renamed onto the target. On any failure
// (a full disk, a file-size limit, a target that is a directory) the temporary is removed and
// FileError is thrown: the target is exactly as it was.
#include <functional>
#include <string>
#include <string_view>

namespace bpde {

/// Replace (or create) `path` by `bytes`, all or nothing. Throws FileError.
void write_file_atomically(const std::string& path, std::string_view bytes);

/// Replace (or create) `path` by the file that `write_to(tmp)` writes at the path `tmp` (for
/// writers that need a path, not bytes). The temporary is checked (it exists and is a regular
/// file), fsynced and renamed onto `path`; when `write_to` throws or anything fails, the
/// temporary is removed and the target is as it was. Rethrows write_to's exception, else FileError.
void replace_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write_to);

/// Create the new file `path` (it must not exist) with `bytes`, in one pass: every write and the
/// close are checked; on failure the partial file is removed and FileError is thrown. No
/// temporary, no rename, no fsync: for a file inside a private staging folder that is published
/// as a whole by a rename afterwards (io/output_folder.h, the write policy there).
void write_new_file(const std::string& path, std::string_view bytes);

}  // namespace bpde
