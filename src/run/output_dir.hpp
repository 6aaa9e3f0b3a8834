#pragma once

#include <string>

namespace fsi {

// Creates `dir` if needed and checks a file can be written there; throws
// InputError naming `source` and output.dir otherwise.
void prepare_output_dir(const std::string& dir, const std::string& source);

}  // namespace fsi
