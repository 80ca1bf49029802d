// OutputFolder (io/output_folder.h): an output folder is written all or nothing.
#include "bezierpde/io/output_folder.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "bezierpde/core/errors.h"

using namespace bpde;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("bpde_outfolder_" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    s[fs::relative(e.path(), dir).string()] = e.is_directory() ? "<dir>" : slurp(e.path());
  return s;
}

void put(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

bool has_staging(const fs::path& parent) {
  for (const auto& e : fs::directory_iterator(parent))
    if (e.path().filename().string().rfind(".bpde-staging", 0) == 0) return true;
  return false;
}

int entries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.exists() ? 1 : 0;
  return n;
}

}  // namespace

TEST(OutputFolder, MissingFolderAppearsWithEveryFileOrNotAtAll) {
  const fs::path top = scratch("missing");
  const fs::path dir = top / "a" / "b";
  {
    OutputFolder out(dir.string(), {"x.txt", "y.txt"});
    EXPECT_FALSE(fs::exists(top)) << "the constructor creates nothing";
    put(out.file("x.txt"), "X");
    EXPECT_FALSE(fs::exists(dir)) << "nothing in DIR before commit";
    put(out.file("y.txt"), "Y");
    out.commit();
  }
  EXPECT_EQ(slurp(dir / "x.txt"), "X");
  EXPECT_EQ(slurp(dir / "y.txt"), "Y");
  EXPECT_EQ(entries(dir), 2);
  EXPECT_EQ(entries(dir.parent_path()), 1);
  EXPECT_FALSE(has_staging(dir.parent_path()));

  // Abandoned (an exception before commit): the parents it created are gone again.
  const fs::path top2 = scratch("abandoned");
  {
    OutputFolder out((top2 / "a" / "b").string(), {"x.txt"});
    put(out.file("x.txt"), "X");
    EXPECT_TRUE(fs::exists(top2));
  }
  EXPECT_FALSE(fs::exists(top2));
}

TEST(OutputFolder, ExistingFolderKeepsItsOtherFilesAndIsReplacedOnlyOnCommit) {
  const fs::path dir = scratch("existing");
  fs::create_directories(dir / "sub");
  put((dir / "x.txt").string(), "old X");
  put((dir / "other.txt").string(), "other");
  put((dir / "sub" / "z").string(), "z");
  const auto before = snapshot(dir);
  {
    OutputFolder out(dir.string(), {"x.txt", "y.txt"});
    put(out.file("x.txt"), "new X");
    put(out.file("y.txt"), "Y");
  }  // not committed
  EXPECT_EQ(snapshot(dir), before);
  EXPECT_FALSE(has_staging(dir.parent_path())) << "staging folder removed";
  {
    OutputFolder out(dir.string(), {"x.txt", "y.txt"});
    put(out.file("x.txt"), "new X");
    put(out.file("y.txt"), "Y");
    out.commit();
  }
  auto after = before;
  after["x.txt"] = "new X";
  after["y.txt"] = "Y";
  EXPECT_EQ(snapshot(dir), after);
}

TEST(OutputFolder, TargetsThatCannotBeReplacedAreRefusedBeforeAnythingMoves) {
  const fs::path dir = scratch("blocked");
  fs::create_directories(dir / "y.txt");
  put((dir / "x.txt").string(), "old X");
  const auto before = snapshot(dir);
  EXPECT_THROW(OutputFolder(dir.string(), {"x.txt", "y.txt"}), FileError);
  // Blocked only after the files were staged: commit refuses, DIR as it was, staging removed.
  fs::remove(dir / "y.txt");
  const auto before2 = snapshot(dir);
  {
    OutputFolder out(dir.string(), {"x.txt", "y.txt"});
    put(out.file("x.txt"), "new X");
    put(out.file("y.txt"), "Y");
    fs::create_directories(dir / "y.txt");
    EXPECT_THROW(out.commit(), FileError);
  }
  auto expected = before2;
  expected["y.txt"] = "<dir>";
  EXPECT_EQ(snapshot(dir), expected);
  (void)before;
  // A file as DIR, a file as a parent, a name longer than NAME_MAX.
  const fs::path plain = scratch("plain");
  put(plain.string(), "plain");
  EXPECT_THROW(OutputFolder(plain.string(), {"x.txt"}), FileError);
  EXPECT_THROW(OutputFolder((plain / "sub").string(), {"x.txt"}), FileError);
  EXPECT_THROW(OutputFolder((plain / "a" / "b").string(), {"x.txt"}), FileError);
  EXPECT_EQ(slurp(plain), "plain");
  EXPECT_THROW(OutputFolder((dir / std::string(300, 'n')).string(), {"x.txt"}), FileError);
  EXPECT_THROW(OutputFolder("", {"x.txt"}), FileError);
}

TEST(OutputFolder, EveryNamedFileMustBeWritten) {
  const fs::path dir = scratch("names");
  OutputFolder out(dir.string(), {"x.txt", "y.txt"});
  EXPECT_THROW(out.file("z.txt"), InternalError);
  put(out.file("x.txt"), "X");
  EXPECT_THROW(out.commit(), InternalError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(OutputFolder, TrailingSeparatorNamesTheSameFolder) {
  const fs::path dir = scratch("trailing");
  {
    OutputFolder out(dir.string() + "/", {"x.txt"});
    put(out.file("x.txt"), "X");
    out.commit();
  }
  EXPECT_EQ(slurp(dir / "x.txt"), "X");
}

// A user who may write DIR but not its parent (`--out ~` of an ordinary user): the files are
// staged inside DIR, and DIR gets them, or keeps its old ones when the run fails. Run in a child
// process as that user: as root, the child drops to nobody (uid 65534), which owns DIR only; as
// an ordinary user, the parent is made read-only.
TEST(OutputFolder, WritableFolderInAReadOnlyParentIsWrittenInPlace) {
  const fs::path parent = scratch("readonly_parent");
  const fs::path dir = parent / "u";
  fs::create_directories(dir);
  put((dir / "x.txt").string(), "old X");
  put((dir / "keep.txt").string(), "keep");
  const bool root = ::geteuid() == 0;
  constexpr uid_t kNobody = 65534;
  if (root) {
    ASSERT_EQ(::chown(dir.c_str(), kNobody, kNobody), 0);
    ASSERT_EQ(::chown((dir / "x.txt").c_str(), kNobody, kNobody), 0);
  } else {
    fs::permissions(parent, fs::perms::owner_read | fs::perms::owner_exec);
  }
  // 0: committed; 1: abandoned as asked; 10 + k: step k failed.
  const auto as_user = [&](bool commit) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      if (root && (::setgid(kNobody) != 0 || ::setuid(kNobody) != 0)) ::_exit(10);
      if (::access(parent.c_str(), W_OK) == 0) ::_exit(11);  // the parent must be read-only to us
      try {
        OutputFolder out(dir.string(), {"x.txt", "y.txt"});
        put(out.file("x.txt"), "new X");
        put(out.file("y.txt"), "Y");
        if (!commit) ::_exit(has_staging(dir) && !has_staging(parent) ? 1 : 12);
        out.commit();
      } catch (const std::exception&) {
        ::_exit(13);
      }
      ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  // (the abandoned child _exits without its destructor: its staging folder stays, as after SIGKILL)
  EXPECT_EQ(as_user(false), 1);
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".bpde-staging", 0) == 0) fs::remove_all(e.path());
  EXPECT_EQ(as_user(true), 0);
  if (!root) fs::permissions(parent, fs::perms::owner_all);
  EXPECT_EQ(slurp(dir / "x.txt"), "new X");
  EXPECT_EQ(slurp(dir / "y.txt"), "Y");
  EXPECT_EQ(slurp(dir / "keep.txt"), "keep");
  EXPECT_FALSE(has_staging(dir));
  EXPECT_FALSE(has_staging(parent));
}
