// Why a path given as an input file (a case, a mesh, a .geo script, a sweep's rows) is
// not one, for its one-line error: missing, or what it is instead (a directory, a FIFO,
// a device), so that `fsicontact run /dev/zero` does not say "no such case file" of a
// path that exists.
#pragma once

#include <string>

namespace fsi {

// Empty if `path` is a regular file (or a link to one). Otherwise "no such <what> file"
// or "<what it is>, not a <what> file; expected <expected>", e.g. for what = "case",
// expected = "a regular TOML file".
std::string input_file_problem(const std::string& path, const std::string& what, const std::string& expected);

}  // namespace fsi
