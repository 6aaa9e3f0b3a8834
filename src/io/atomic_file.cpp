#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <sstream>

#include "common/errors.hpp"
#include "common/interrupt.hpp"

namespace fsi {
namespace {

// Writes all of `bytes` to `fd`, retrying on EINTR and partial writes; false with
// errno set on failure.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  set_temporary_file(tmp.c_str());
  auto fail = [&](int err) {
    ::unlink(tmp.c_str());
    clear_temporary_file();
    throw OutputError(path, err);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    clear_temporary_file();
    throw OutputError(path, err);
  }
  if (!write_all(fd, bytes)) {
    const int err = errno;
    ::close(fd);
    fail(err);
  }
  if (::close(fd) != 0) fail(errno);  // delayed errors (quota, NFS) are reported here
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(errno);
  clear_temporary_file();
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::ostringstream out;
  write(out);
  write_file_atomically(path, out.view());
}

bool is_temporary_of(const std::string& file_name, const std::string& name) {
  const std::string prefix = name + ".tmp";
  if (file_name.size() <= prefix.size() || file_name.compare(0, prefix.size(), prefix) != 0) return false;
  return file_name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
}

}  // namespace fsi
