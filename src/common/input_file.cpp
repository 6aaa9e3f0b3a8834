#include "common/input_file.hpp"

#include <filesystem>
#include <system_error>

namespace fsi {

std::string input_file_problem(const std::string& path, const std::string& what, const std::string& expected) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows links
  std::string is;
  switch (st.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return "no such " + what + " file";
    case fs::file_type::directory: is = "a directory"; break;
    case fs::file_type::fifo: is = "a FIFO (named pipe)"; break;
    case fs::file_type::character: is = "a character device"; break;
    case fs::file_type::block: is = "a block device"; break;
    case fs::file_type::socket: is = "a socket"; break;
    default: is = ec ? "not accessible (" + ec.message() + ")" : "not a regular file"; break;
  }
  return is + ", not a " + what + " file; expected " + expected;
}

}  // namespace fsi
