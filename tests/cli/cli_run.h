#pragma once
// Running the `bpde` binary from the CLI tests (test_cli.cpp, test_hostile_input.cpp): its exit
// status, stdout and stderr, in a temporary folder of this test process.
#include <sys/wait.h>
#include <unistd.h>

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
