#include "run/output_dir.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"

namespace fsi {

void prepare_output_dir(const std::string& dir, const std::string& source) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(source + ": output.dir = \"" + dir + "\" cannot be created" +
                     (ec ? " (" + ec.message() + ")" : std::string()) + "; allowed: a writable directory");
  const std::string probe = (fs::path(dir) / (".write-test-" + std::to_string(::getpid()))).string();
  {
    std::ofstream out(probe);
    if (!out)
      throw InputError(source + ": output.dir = \"" + dir +
                       "\" is not writable; allowed: a writable directory");
  }
  std::remove(probe.c_str());
}

}  // namespace fsi
