// Files appear whole or not at all: written under a temporary name in the same
// directory (`name.tmp<pid>`), then renamed (rename is atomic on POSIX file systems).
// A failed write removes the temporary and throws OutputError naming the path and
// the system's reason (ENOSPC: "No space left on device"); a second Ctrl-C or
// SIGTERM during a write removes the temporary before the process dies
// (common/interrupt.hpp).
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace fsi {

// Writes `bytes` to `path` atomically.
void write_file_atomically(const std::string& path, std::string_view bytes);

// Calls `write` on an in-memory stream, then writes its text to `path` atomically.
// The stream is in memory so that every byte reaches the file through one checked
// write(2) loop: an ofstream's failure does not keep the errno that says why.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// True for the temporary names write_file_atomically uses for `name` ("summary.json"
// → "summary.json.tmp<digits>"), so a later run can remove what a SIGKILL left.
bool is_temporary_of(const std::string& file_name, const std::string& name);

}  // namespace fsi
