// Numbers in messages and the handling of stop signals (issue 11).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>

#include "common/format.hpp"
#include "common/interrupt.hpp"

namespace fsi::format_and_signals_test {
namespace {

// A range error must show the value the user gave, not a rounding of it:
// `omega = 1 is out of range (0, 1]` for 1.0000001 read as a contradiction.
TEST(Format, ShortestReadsBackAsTheSameDouble) {
  EXPECT_EQ(shortest(1.0000001), "1.0000001");
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(1e-300), "1e-300");
  EXPECT_EQ(shortest(0.49999999999999), "0.49999999999999");
  for (double v : {0.1 + 0.2, 1.0 / 3.0, 6.02e23, -2.5e-17})
    EXPECT_EQ(std::stod(shortest(v)), v) << shortest(v);
  EXPECT_EQ(shortest(INFINITY), "inf");
  EXPECT_EQ(approx(6.020797289396147e+22), "6.02e+22");
}

// The first SIGTERM only asks to stop; the second removes the temporary file being
// written before the process dies of it, so that no `*.tmp<pid>` stays behind.
TEST(Signals, ASecondSignalRemovesTheTemporaryFileAndKills) {
  const std::filesystem::path tmp = std::filesystem::temp_directory_path() /
                                    ("fsicontact-signal-" + std::to_string(::getpid()) + ".tmp1");
  const pid_t pid = ::fork();
  if (pid == 0) {
    install_interrupt_handler();
    std::ofstream(tmp) << "half";
    set_temporary_file(tmp.c_str());
    std::raise(SIGTERM);
    if (!interrupt_requested() || interrupt_signal() != SIGTERM || interrupted_exit_status() != 143) ::_exit(3);
    std::raise(SIGTERM);  // dies here
    ::_exit(4);
  }
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  ASSERT_TRUE(WIFSIGNALED(raw)) << "exit status " << WEXITSTATUS(raw);
  EXPECT_EQ(WTERMSIG(raw), SIGTERM);
  EXPECT_FALSE(std::filesystem::exists(tmp));
  std::filesystem::remove(tmp);
}

}  // namespace
}  // namespace fsi::format_and_signals_test
