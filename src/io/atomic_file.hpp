// Files appear whole or not at all: written under a temporary name in the same
// directory, then renamed (rename is atomic on POSIX file systems).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace fsi {

// Calls `write` on a stream to `path`.tmp, then renames it to `path`.
// Throws std::runtime_error naming the path if anything fails.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// For writers that need a file name (Cairo): `write` fills the temporary path.
void write_atomically_to(const std::string& path,
                         const std::function<void(const std::string& tmp_path)>& write);

}  // namespace fsi
