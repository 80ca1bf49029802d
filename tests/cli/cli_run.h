#pragma once
// Running the `bpde` binary from the CLI tests (test_cli.cpp, test_hostile_input.cpp): its exit
// status, stdout and stderr, in a temporary folder of this test process.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bpde::testing {

namespace fs = std::filesystem;

struct CmdResult {
  int status;  ///< the exit status, or -signal when the command crashed (SIGSEGV, SIGABRT, ...)
  std::string out, err;
};

/// A folder of this test process under the system's temporary directory.
inline fs::path tmpdir() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("bpde_cli_" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
  }();
  return d;
}

/// The bytes of a file ("" when it cannot be read).
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Run `bpde ARGS` (BPDE_BINARY), capturing stdout and stderr.
inline CmdResult run(const std::string& args) {
  const fs::path o = tmpdir() / "stdout", e = tmpdir() / "stderr";
  const std::string cmd = std::string(BPDE_BINARY) + " " + args + " >" + o.string() + " 2>" + e.string();
  const int rc = std::system(cmd.c_str());
  // A crash is not an exit status: report it as -signal.
  const int status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -(WIFSIGNALED(rc) ? WTERMSIG(rc) : 1000);
  return {status, slurp(o), slurp(e)};
}

/// Run `bpde ARGS` like run(), in a child with the resource limit `resource` (RLIMIT_FSIZE,
/// RLIMIT_AS, ...) set to `value`, and SIGXFSZ ignored, so that a write past a file-size limit
/// fails with EFBIG as on a full disk. The captured stdout and stderr are under the limit too.
inline CmdResult run_with_limit(const std::string& args, int resource, rlim_t value) {
  const fs::path o = tmpdir() / "stdout", e = tmpdir() / "stderr";
  const std::string cmd = std::string(BPDE_BINARY) + " " + args + " >" + o.string() + " 2>" + e.string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const struct rlimit lim = {value, value};
    ::setrlimit(static_cast<__rlimit_resource_t>(resource), &lim);
    std::signal(SIGXFSZ, SIG_IGN);
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int rc = 0;
  if (pid < 0 || ::waitpid(pid, &rc, 0) != pid) return {-1000, "", ""};
  const int status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -(WIFSIGNALED(rc) ? WTERMSIG(rc) : 1000);
  return {status, slurp(o), slurp(e)};
}

/// run() with files limited to `max_file_bytes` (RLIMIT_FSIZE): every write past it fails.
inline CmdResult run_with_file_limit(const std::string& args, rlim_t max_file_bytes) {
  return run_with_limit(args, RLIMIT_FSIZE, max_file_bytes);
}

/// The paths of the `files` line a writing command prints on stdout ("  files  DIR/{a, b}" or
/// "  files  PATH"; jobs/solve_summary.h files_line); none when there is no such line.
inline std::vector<fs::path> printed_files(const std::string& out) {
  const std::string label = "  files ";
  std::vector<fs::path> paths;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(label, 0) != 0) continue;
    std::string text = line.substr(line.find_first_not_of(' ', label.size()));
    const std::size_t brace = text.find("/{");
    if (brace == std::string::npos || text.back() != '}') {
      paths.emplace_back(text);
      continue;
    }
    const fs::path dir = text.substr(0, brace);
    std::istringstream names(text.substr(brace + 2, text.size() - brace - 3));
    for (std::string name; std::getline(names, name, ',');)
      paths.push_back(dir / name.substr(name.find_first_not_of(' ')));
  }
  return paths;
}

/// Write `text` to tmpdir()/name and return its path.
inline fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = tmpdir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

}  // namespace bpde::testing
