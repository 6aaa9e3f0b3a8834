#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fsi {

void write_atomically_to(const std::string& path,
                         const std::function<void(const std::string& tmp_path)>& write) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  try {
    write(tmp);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  write_atomically_to(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + path);
    write(out);
    out.flush();
    if (!out) throw std::runtime_error("error while writing " + path);
  });
}

}  // namespace fsi
