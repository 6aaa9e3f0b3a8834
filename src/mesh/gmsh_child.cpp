#include "mesh/gmsh_child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <new>
#include <stdexcept>

#include "mesh/mesh_error.hpp"

// Declared by the sanitizer runtimes (sanitizer/common_interface_defs.h); weak, so
// null in a build without them.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace fsi {
namespace {

using Clock = std::chrono::steady_clock;

// The reply on the pipe: [u64 length of what follows][u8 Outcome][payload].
enum class Outcome : std::uint8_t { ok = 0, gmsh_error = 1, out_of_memory = 2, failure = 3 };
constexpr int kReplyFd = 3;       // where the child finds the pipe
constexpr int kExitCalled = 121;  // the child's status if Gmsh called exit()
constexpr int kReplyLost = 122;   // ... if writing the reply failed

// ---- child side: only Gmsh, our job and async-signal-safe calls after fork() ----

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

[[noreturn]] void reply_and_exit(Outcome outcome, const char* payload, std::size_t n) {
  const std::uint64_t length = 1 + n;
  const auto tag = static_cast<char>(outcome);
  const bool sent = write_all(kReplyFd, reinterpret_cast<const char*>(&length), sizeof length) &&
                    write_all(kReplyFd, &tag, 1) && write_all(kReplyFd, payload, n);
  ::_exit(sent ? 0 : kReplyLost);
}

[[noreturn]] void reply_text_and_exit(Outcome outcome, const std::string& text) {
  reply_and_exit(outcome, text.data(), text.size());
}

// Gmsh 4.8 reports errors by throwing a std::string.
[[noreturn]] void reply_current_exception() {
  try {
    throw;
  } catch (const std::string& what) {
    reply_text_and_exit(Outcome::gmsh_error, what);
  } catch (const std::bad_alloc&) {
    reply_and_exit(Outcome::out_of_memory, nullptr, 0);
  } catch (const std::length_error& e) {  // a count beyond any vector (measured, fuzzing)
    reply_text_and_exit(Outcome::gmsh_error, std::string("a count too large (") + e.what() + ")");
  } catch (const std::exception& e) {
    reply_text_and_exit(Outcome::failure, e.what());
  } catch (...) {
    reply_text_and_exit(Outcome::failure, "an exception of unknown type");
  }
}

// An exception leaving one of Gmsh's OpenMP regions ends in std::terminate (measured:
// the structure with H = 1e-12); the exception is still current there, so it can
// be reported like any other.
[[noreturn]] void on_terminate() {
  if (std::current_exception()) reply_current_exception();
  reply_text_and_exit(Outcome::failure, "std::terminate was called");
}

// Static destructors and atexit handlers are the parent's (temporary files, solver
// state): if Gmsh calls exit(), this one, registered last, runs first and stops there.
void on_exit_in_child() {
  ::_exit(kExitCalled);
}

// fds 0-2 to /dev/null and `output`, the pipe to kReplyFd, every other fd closed (so
// no other child keeps our pipe open, and Gmsh cannot touch the parent's files).
void arrange_fds(int reply, int output) {
  const int null_fd = ::open("/dev/null", O_RDWR);
  const int out = output >= 0 ? output : null_fd;
  // Above 10 first, so that the dup2s below cannot overwrite one of them.
  const int r = ::fcntl(reply, F_DUPFD, 10), o = ::fcntl(out, F_DUPFD, 10),
            n = ::fcntl(null_fd, F_DUPFD, 10);
  ::dup2(n, 0);
  ::dup2(o, 1);
  ::dup2(o, 2);
  ::dup2(r, kReplyFd);
  ::fcntl(kReplyFd, F_SETFD, FD_CLOEXEC);
  if (::close_range(kReplyFd + 1, ~0U, 0) != 0)
    for (int fd = kReplyFd + 1; fd < 4096; ++fd) ::close(fd);
}

// Lowers a limit for this process (never above the hard limit it inherited).
void lower_limit(int resource, rlim_t value) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0) return;
  limit.rlim_cur = std::min(value, limit.rlim_max);
  ::setrlimit(resource, &limit);
}

// Default dispositions, so that a crash is reported as the signal (and not through
// a handler the parent installed, such as a sanitizer's), and no core file.
void arrange_signals_and_limits(std::size_t address_space_cap) {
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGPIPE, SIGXFSZ, SIGTERM, SIGALRM})
    ::signal(sig, SIG_DFL);
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  lower_limit(RLIMIT_CORE, 0);
  lower_limit(RLIMIT_FSIZE, 16u << 20);  // Gmsh writes no file; caps its chatter
  if (address_space_cap > 0) lower_limit(RLIMIT_AS, address_space_cap);
}

[[noreturn]] void child_main(const std::function<std::vector<char>()>& job, int reply, int output,
                             std::size_t address_space_cap) {
  arrange_fds(reply, output);
  arrange_signals_and_limits(address_space_cap);
  // A sanitizer that stops the child (Gmsh's allocation beyond the cap) would run the
  // parent's death callback: libFuzzer's saves the input as a "crash" the parent
  // never had (measured: lying-header.msh). The parent reports the exit instead.
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  std::set_terminate(on_terminate);
  std::atexit(on_exit_in_child);
  try {
    const std::vector<char> bytes = job();
    reply_and_exit(Outcome::ok, bytes.data(), bytes.size());
  } catch (...) {
    reply_current_exception();
  }
}

}  // namespace

void forbid_side_effects() {
  lower_limit(RLIMIT_FSIZE, 0);
  lower_limit(RLIMIT_NPROC, 0);
}

namespace {

// ---- parent side ----

class UniqueFd {
 public:
  explicit UniqueFd(int fd = -1) : fd_(fd) {}
  ~UniqueFd() { reset(); }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  int get() const { return fd_; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

// Owns the child's pid: whatever happens in the parent, the child is killed and
// reaped (no zombie).
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  ~Child() {
    if (!reaped_) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  void kill() { ::kill(pid_, SIGKILL); }
  // The wait status, or -1 if it cannot be had (SIGCHLD set to SIG_IGN reaps for us).
  int wait() {
    int status = 0;
    pid_t r;
    do r = ::waitpid(pid_, &status, 0);
    while (r < 0 && errno == EINTR);
    reaped_ = true;
    return r == pid_ ? status : -1;
  }

 private:
  pid_t pid_;
  bool reaped_ = false;
};

struct Reply {
  std::vector<char> bytes;  // as received, length prefix included
  bool timed_out = false;
  bool complete() const {
    std::uint64_t length = 0;
    if (bytes.size() < sizeof length) return false;
    std::memcpy(&length, bytes.data(), sizeof length);
    return length >= 1 && bytes.size() - sizeof length >= length;
  }
  Outcome outcome() const { return static_cast<Outcome>(bytes[sizeof(std::uint64_t)]); }
  std::vector<char> payload() const {
    return {bytes.begin() + sizeof(std::uint64_t) + 1, bytes.end()};
  }
};

// Reads until the reply is complete (not until EOF: a child forked meanwhile by
// another thread may hold a copy of the pipe), EOF, or the deadline.
Reply read_reply(int fd, Clock::time_point deadline) {
  Reply reply;
  std::vector<char> chunk(1 << 20);
  while (!reply.complete()) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      reply.timed_out = true;
      break;
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), INT_MAX)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t k = ::read(fd, chunk.data(), chunk.size());
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;  // EOF: the child has gone
    reply.bytes.insert(reply.bytes.end(), chunk.data(), chunk.data() + k);
  }
  return reply;
}

// The last line the child printed (Gmsh prints nothing with General.Terminal = 0;
// this is what the C++ runtime or a sanitizer said before the child died).
std::string last_output_line(int fd) {
  if (fd < 0) return "";
  const off_t size = ::lseek(fd, 0, SEEK_END);
  const off_t from = std::max<off_t>(0, size - 400);
  std::string tail(static_cast<std::size_t>(size - from), '\0');
  const ssize_t k = ::pread(fd, tail.data(), tail.size(), from);
  tail.resize(k > 0 ? static_cast<std::size_t>(k) : 0);
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r' || tail.back() == ' '))
    tail.pop_back();
  const auto nl = tail.find_last_of('\n');
  return nl == std::string::npos ? tail : tail.substr(nl + 1);
}

std::string signal_name(int sig) {
  const char* abbrev = ::sigabbrev_np(sig);
  return abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

// A message on one line: callers print it as one line of the error report.
std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s;
}

[[noreturn]] void throw_failure(const Reply& reply, int status, const ChildTask& task,
                                const std::string& output) {
  const std::string after = output.empty() ? "" : " (it said: " + one_line(output) + ")";
  if (reply.complete()) {
    const std::vector<char> p = reply.payload();
    const std::string text = one_line({p.begin(), p.end()});
    switch (reply.outcome()) {
      case Outcome::gmsh_error:
        throw MeshError("Gmsh failed while " + task.doing + ": " + text);
      case Outcome::out_of_memory:
        throw MeshError(
            "Gmsh ran out of memory while " + task.doing +
            (task.out_of_memory_detail.empty() ? "" : ": " + task.out_of_memory_detail));
      default:
        throw MeshError("the Gmsh child process failed while " + task.doing + ": " + text);
    }
  }
  if (status != -1 && WIFSIGNALED(status))
    throw MeshError("Gmsh crashed (" + signal_name(WTERMSIG(status)) + ") while " + task.doing +
                    after);
  if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == kExitCalled)
    throw MeshError("Gmsh called exit() while " + task.doing);
  if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw MeshError("Gmsh exited with status " + std::to_string(WEXITSTATUS(status)) + " while " +
                    task.doing + after);
  throw MeshError("the Gmsh child process sent no complete reply while " + task.doing + after);
}

// The parent's address space now, so that the child's cap is "what it has plus
// `extra`" (under AddressSanitizer the process already maps terabytes of shadow).
std::size_t address_space_now() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

std::size_t physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(size)
                               : 0;
}

std::vector<char> run_in_child(const std::function<std::vector<char>()>& job, const ChildTask& task,
                               const ChildLimits& limits) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0)
    throw MeshError("cannot start Gmsh (pipe: " + std::string(std::strerror(errno)) + ")");
  UniqueFd from_child(ends[0]), to_parent(ends[1]);
  UniqueFd output(::memfd_create("gmsh-output", MFD_CLOEXEC));  // -1: the child uses /dev/null
  const std::size_t now = address_space_now();
  const std::size_t cap = limits.extra_memory > 0 && now > 0 ? now + limits.extra_memory : 0;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(limits.seconds));
  std::fflush(nullptr);  // else the child's copy of unwritten stdio buffers could be written twice
  const pid_t pid = ::fork();
  if (pid < 0)
    throw MeshError("cannot start Gmsh (fork: " + std::string(std::strerror(errno)) + ")");
  if (pid == 0) child_main(job, to_parent.get(), output.get(), cap);
  Child child(pid);
  to_parent.reset();  // so that EOF arrives when the child exits
  const Reply reply = read_reply(from_child.get(), deadline);
  if (reply.timed_out) {
    child.kill();
    child.wait();
    throw MeshError("Gmsh did not finish " + task.doing + " within " +
                    seconds_text(limits.seconds) + " s; it was stopped");
  }
  const int status = child.wait();
  if (reply.complete() && reply.outcome() == Outcome::ok) return reply.payload();
  throw_failure(reply, status, task, last_output_line(output.get()));
}

}  // namespace fsi
