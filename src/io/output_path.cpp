#include "io/output_path.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "common/errors.hpp"

namespace fsi {

std::string output_path_problem(const std::string& dir) {
  if (dir.empty()) return "is empty";
  if (dir.size() > 4000) return "is " + std::to_string(dir.size()) + " bytes long";
  for (unsigned char ch : dir)
    if (ch < 0x20 || ch == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "U+%04X", ch);
      return std::string("contains the control character ") + code +
             (ch == '\t' ? " (a tab: in a TOML \"...\" string \\t is one; write '...' or \\\\)" : "");
    }
  std::size_t start = 0;
  while (start <= dir.size()) {
    const std::size_t end = std::min(dir.find('/', start), dir.size());
    if (end - start > 255)
      return "has a component of " + std::to_string(end - start) + " bytes (\"" + dir.substr(start, 40) + "...\")";
    start = end + 1;
  }
  return "";
}

void check_output_dir(const std::string& dir, const std::string& origin) {
  namespace fs = std::filesystem;
  auto fail = [&](const std::string& problem) {
    throw InputError(origin + ": output.dir = \"" + dir + "\" " + problem +
                     "; allowed: a directory that exists or can be created, writable");
  };
  const std::string syntax = output_path_problem(dir);
  if (!syntax.empty()) fail(syntax);
  std::error_code ec;
  fs::path existing = fs::path(dir).lexically_normal();
  while (!existing.empty() && !fs::exists(fs::symlink_status(existing, ec))) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (fs::is_symlink(fs::symlink_status(existing, ec)) && !fs::exists(fs::status(existing, ec)))
    fail("passes through the dangling symbolic link " + existing.string());
  if (!fs::is_directory(existing, ec))
    fail(existing == fs::path(dir).lexically_normal() ? "is a file, not a directory"
                                                      : "passes through " + existing.string() + ", which is not a directory");
  // Permission bits do not tell (root passes them; /proc refuses root), so probe with
  // what the run will do there later, and undo it at once: a file in the directory
  // if it exists, a directory in its deepest existing ancestor otherwise.
  const fs::path probe = existing / (".fsicontact-probe-" + std::to_string(::getpid()));
  const bool exists = fs::is_directory(fs::path(dir), ec);
  const int fd = exists ? ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600) : -1;
  const bool ok = exists ? fd >= 0 : ::mkdir(probe.c_str(), 0700) == 0;
  const int err = errno;
  if (fd >= 0) ::close(fd), ::unlink(probe.c_str());
  else if (ok) ::rmdir(probe.c_str());
  if (!ok) fail("cannot be written: " + existing.string() + ": " + std::strerror(err));
}

}  // namespace fsi
