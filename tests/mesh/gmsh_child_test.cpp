// The child process that runs Gmsh: whatever the job does (throw, crash, hang, exit,
// print, allocate without end), the parent gets its bytes or a MeshError saying
// what happened, keeps its own terminal quiet, and leaves no zombie.
#include "mesh/gmsh_child.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <thread>

#include "mesh/mesh_error.hpp"
#include "support/sanitizers.hpp"

namespace fsi::gmsh_child_test {
namespace {

const ChildTask kTask{"testing the child", "it had a small cap"};

std::vector<char> bytes(const std::string& s) {
  return {s.begin(), s.end()};
}

// The MeshError's message, or "" if the call returned.
std::string failure_of(const std::function<std::vector<char>()>& job, ChildLimits limits = {}) {
  try {
    run_in_child(job, kTask, limits);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

bool no_child_left() {
  int status;
  return ::waitpid(-1, &status, WNOHANG) == -1 && errno == ECHILD;
}

TEST(GmshChild, ReturnsTheJobsBytes) {
  std::string big(3 << 20, 'x');  // more than a pipe holds: the parent reads while the child writes
  big[12345] = 'y';
  EXPECT_EQ(run_in_child([&] { return bytes(big); }, kTask, {}), bytes(big));
  EXPECT_TRUE(run_in_child([] { return std::vector<char>{}; }, kTask, {}).empty());
  EXPECT_TRUE(no_child_left());
}

TEST(GmshChild, AGmshErrorIsAMeshErrorWithItsText) {
  const std::string m =
      failure_of([]() -> std::vector<char> { throw std::string("Unable to\nrecover"); });
  EXPECT_EQ(m, "Gmsh failed while testing the child: Unable to recover");  // one line
}

TEST(GmshChild, AnExceptionEscapingAThreadIsReportedNotAnAbort) {
  // What Gmsh's OpenMP regions do with an exception: std::terminate in that thread.
  const std::string m = failure_of([]() -> std::vector<char> {
    std::thread([] { throw std::string("Identical points in triangulation"); }).join();
    return {};
  });
  EXPECT_EQ(m, "Gmsh failed while testing the child: Identical points in triangulation");
}

TEST(GmshChild, BadAllocIsOutOfMemory) {
  const std::string m = failure_of([]() -> std::vector<char> { throw std::bad_alloc(); });
  EXPECT_EQ(m, "Gmsh ran out of memory while testing the child: it had a small cap");
}

TEST(GmshChild, TheMemoryCapStopsARunawayAllocation) {
#if defined(FSICONTACT_ASAN)
  GTEST_SKIP() << "AddressSanitizer's allocator dies instead of throwing std::bad_alloc";
#endif
  const std::string m = failure_of(
      [] {
        std::vector<char> v(std::size_t{8} << 30);  // 8 GB under a cap of 256 MB
        return std::vector<char>(v.begin(), v.begin() + 1);
      },
      {60, std::size_t{256} << 20});
  EXPECT_EQ(m, "Gmsh ran out of memory while testing the child: it had a small cap");
}

TEST(GmshChild, ACrashNamesTheSignal) {
  EXPECT_EQ(failure_of([]() -> std::vector<char> { std::abort(); }),
            "Gmsh crashed (SIGABRT) while testing the child");
  EXPECT_EQ(failure_of([]() -> std::vector<char> {
              std::raise(SIGSEGV);
              return {};
            }),
            "Gmsh crashed (SIGSEGV) while testing the child");
  EXPECT_TRUE(no_child_left());
}

TEST(GmshChild, WhatTheChildPrintedBeforeDyingIsInTheMessage) {
  const std::string m = failure_of([]() -> std::vector<char> {
    std::fprintf(stderr, "first line\nlast words\n");
    std::fflush(stderr);
    std::abort();
  });
  EXPECT_EQ(m, "Gmsh crashed (SIGABRT) while testing the child (it said: last words)");
}

TEST(GmshChild, AHangIsStoppedAtTheTimeLimit) {
  const auto start = std::chrono::steady_clock::now();
  const std::string m = failure_of(
      []() -> std::vector<char> {
        for (;;) ::pause();
      },
      {0.3, 0});
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(m, "Gmsh did not finish testing the child within 0.3 s; it was stopped");
  EXPECT_LT(took, 5.0);
  EXPECT_TRUE(no_child_left());
}

TEST(GmshChild, ExitInTheChildRunsNoneOfTheParentsExitHandlers) {
  static const pid_t parent = ::getpid();
  static const std::string marker = "/tmp/fsicontact-child-exit-" + std::to_string(parent);
  std::remove(marker.c_str());
  // The parent's handler, registered before the fork; it marks a run in a child only.
  std::atexit([] {
    if (::getpid() != parent) std::fclose(std::fopen(marker.c_str(), "w"));
  });
  EXPECT_EQ(failure_of([]() -> std::vector<char> { std::exit(3); }),
            "Gmsh called exit() while testing the child");
  EXPECT_FALSE(std::ifstream(marker).good());
}

TEST(GmshChild, PrintsNothingToOurTerminal) {
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const auto out = run_in_child(
      [] {
        std::cout << "Info: to stdout" << std::endl;
        std::cerr << "Error: to stderr" << std::endl;
        ::write(1, "raw\n", 4);
        ::write(2, "raw\n", 4);
        return bytes("ok");
      },
      kTask, {});
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(out, bytes("ok"));
}

TEST(GmshChild, CannotTouchTheParentsFiles) {
  const int low = ::open("/dev/null", O_RDONLY);
  const int fd = ::fcntl(low, F_DUPFD, 20);  // above the few fds the child sets up
  ::close(low);
  ASSERT_GE(fd, 20);
  const auto out = run_in_child(
      [fd] { return bytes(::fcntl(fd, F_GETFD) == -1 ? "closed" : "open"); }, kTask, {});
  ::close(fd);
  EXPECT_EQ(out, bytes("closed"));
}

// A signal handler installed without SA_RESTART makes poll/read/waitpid fail with EINTR.
TEST(GmshChild, SignalsToTheParentDoNotBreakTheCall) {
  struct sigaction action {
  }, old{};
  action.sa_handler = [](int) {};
  ::sigaction(SIGALRM, &action, &old);
  const itimerval every_ms{{0, 1000}, {0, 1000}}, off{};
  ::setitimer(ITIMER_REAL, &every_ms, nullptr);
  const auto out = run_in_child(
      [] {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        return bytes(std::string(1 << 20, 'z'));
      },
      kTask, {});
  ::setitimer(ITIMER_REAL, &off, nullptr);
  ::sigaction(SIGALRM, &old, nullptr);
  EXPECT_EQ(out.size(), std::size_t{1} << 20);
  EXPECT_TRUE(no_child_left());
}

}  // namespace
}  // namespace fsi::gmsh_child_test
