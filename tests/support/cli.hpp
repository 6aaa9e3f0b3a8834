// Runs the fsicontact binary in a scratch directory and captures what it says.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::testing {

struct CliRun {
  int status = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The scratch directories this test process made, removed when it ends if its tests
// passed; a failed test's are kept, to be looked at. Left behind, they filled the temp
// dir: 182 of them, 65 MB, after a day of runs. Only the process that made them removes
// them (a child forked by a test that exits through exit() does not).
class ScratchDirs {
 public:
  void add(const std::filesystem::path& dir) { dirs_.push_back(dir); }
  ~ScratchDirs() {
    if (::getpid() != owner_ || !::testing::UnitTest::GetInstance()->Passed()) return;
    std::error_code ec;
    for (const auto& d : dirs_) std::filesystem::remove_all(d, ec);
  }

 private:
  pid_t owner_ = ::getpid();
  std::vector<std::filesystem::path> dirs_;
};

// A fresh empty directory under the system temp dir, unique per test, removed when the
// test process ends if its tests passed.
inline std::filesystem::path scratch_dir(const std::string& name) {
  static ScratchDirs made;  // after gtest's UnitTest, so destroyed before it
  const auto dir = std::filesystem::temp_directory_path() /
                   ("fsicontact-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  made.add(dir);
  return dir;
}

// Runs a whole shell command line in `cwd` (for commands that set an environment).
inline CliRun run_shell(const std::string& command, const std::filesystem::path& cwd) {
  const auto out = cwd / ".stdout", err = cwd / ".stderr";
  const std::string cmd = "cd '" + cwd.string() + "' && " + command + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// `args` is appended to the binary's path as shell words; runs with `cwd` as the
// working directory.
inline CliRun run_cli(const std::string& args, const std::filesystem::path& cwd) {
  std::string command = "'";  // built step by step: "'" + std::string trips GCC 12's -Wrestrict
  command += FSICONTACT_BINARY;
  command += "' ";
  command += args;
  return run_shell(command, cwd);
}

// Starts the binary with `args` (already split) in `cwd`, stdout and stderr to the
// given files; returns its pid (for a signal and waitpid).
inline pid_t spawn_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                       const std::filesystem::path& out, const std::filesystem::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    std::FILE* o = std::freopen(out.c_str(), "w", stdout);
    std::FILE* e = std::freopen(err.c_str(), "w", stderr);
    if (!o || !e) ::_exit(126);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(FSICONTACT_BINARY));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(FSICONTACT_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// The exit status of a spawned run (128 + signal if it died by one).
inline int wait_cli(pid_t pid) {
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

}  // namespace fsi::testing
