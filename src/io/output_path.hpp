// Output directories are data, never code: a path is used byte for byte as given
// (never pasted into TOML or a shell line) and checked before anything is created.
#pragma once

#include <string>

namespace fsi {

// What is wrong with `dir` as a path, or "" if nothing: empty; a NUL or control
// character (a TOML "\t" in "C:\temp" is a tab); a component longer than NAME_MAX
// (255 bytes) or a path longer than 4000 bytes.
std::string output_path_problem(const std::string& dir);

// The file system agrees: the part of `dir` that exists is directories (no file, no
// dangling link on the way) and the deepest existing one is writable. Creates
// nothing. Throws InputError "<origin>: output.dir = "<dir>" ...; allowed: ...".
void check_output_dir(const std::string& dir, const std::string& origin);

}  // namespace fsi
