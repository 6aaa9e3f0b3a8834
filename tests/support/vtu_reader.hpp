// A reader of VTK XML .vtu files for the tests, written from the format's description
// (not from io/vtu.cpp): ASCII arrays, and appended raw data after '_' with UInt64
// headers, each array [byte count][bytes], or zlib-compressed ([blocks, block size,
// last block's size, compressed sizes][blocks]).
#pragma once

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::testing {

namespace vtu_detail {

inline std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline std::uint64_t u64(const std::string& s, std::size_t at) {
  std::uint64_t n;
  std::memcpy(&n, s.data() + at, 8);
  return n;
}

// The bytes of one appended array at `offset` (after the '_').
inline std::string appended_bytes(const std::string& data, std::size_t offset, bool zlib) {
  if (!zlib) return data.substr(offset + 8, u64(data, offset));
  const std::uint64_t blocks = u64(data, offset), block = u64(data, offset + 8),
                      last = u64(data, offset + 16);
  std::size_t at = offset + 24 + 8 * blocks;
  std::string out;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = u64(data, offset + 24 + 8 * b);
    std::string raw(b + 1 == blocks ? last : block, '\0');
    uLongf size = raw.size();
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &size,
                         reinterpret_cast<const Bytef*>(data.data() + at), compressed),
              Z_OK);
    EXPECT_EQ(size, raw.size());
    out += raw;
    at += compressed;
  }
  return out;
}

}  // namespace vtu_detail

// Every DataArray by name ("" for the points) as doubles.
inline std::map<std::string, std::vector<double>> read_vtu(const std::filesystem::path& path) {
  using namespace vtu_detail;
  const std::string text = file_bytes(path);
  const bool zlib = text.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos;
  const std::size_t data_at = text.find("<AppendedData encoding=\"raw\">");
  const std::string data =
      data_at == std::string::npos ? "" : text.substr(text.find('_', data_at) + 1);
  const std::string header = text.substr(0, data_at);  // the XML before the binary data
  std::map<std::string, std::vector<double>> arrays;
  const std::regex array_re(
      R"re(<DataArray type="(\w+)"( Name="(\w+)")?( NumberOfComponents="\d+")? format="(\w+)"( offset="(\d+)")?(/?)>)re");
  for (std::sregex_iterator it(header.begin(), header.end(), array_re), end; it != end; ++it) {
    const std::smatch& m = *it;
    const std::string type = m[1], name = m[3], format = m[5];
    std::vector<double>& out = arrays[name];
    if (format == "ascii") {
      const std::size_t begin = m.position(0) + m.length(0);
      std::istringstream in(header.substr(begin, header.find("</DataArray>", begin) - begin));
      for (double x; in >> x;) out.push_back(x);
      continue;
    }
    const std::string bytes = appended_bytes(data, std::stoul(m[7]), zlib);
    if (type == "Float64")
      for (std::size_t i = 0; i < bytes.size(); i += 8) {
        double x;
        std::memcpy(&x, bytes.data() + i, 8);
        out.push_back(x);
      }
    else if (type == "Int32")
      for (std::size_t i = 0; i < bytes.size(); i += 4) {
        std::int32_t x;
        std::memcpy(&x, bytes.data() + i, 4);
        out.push_back(x);
      }
    else
      for (unsigned char c : bytes) out.push_back(c);
  }
  return arrays;
}

}  // namespace fsi::testing
