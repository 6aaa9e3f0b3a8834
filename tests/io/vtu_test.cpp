// VTU files (io/vtu.hpp) read back by the tests' own reader (support/vtu_reader.hpp,
// written from the VTK XML format's description, not from the writer): every array of
// every encoding must give back the values written, bit for bit.
#include "io/vtu.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "support/vtu_reader.hpp"

namespace fsi::vtu_test {
namespace {

namespace fs = std::filesystem;

Mesh two_triangles() {
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1.0 / 3}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(Vtu, EveryEncodingReadsBackTheValuesWritten) {
  const fs::path dir = fs::temp_directory_path() / "fsicontact-vtu-test";
  fs::create_directories(dir);
  const Mesh m = two_triangles();
  Eigen::VectorXd ux(4), uy(4), p(4), chi(2);
  ux << 0.1, -2.5e-300, 1.0 / 3, 7;
  uy << 1e300, 0, -0.0, std::numbers::pi;
  p << 1, 2, 3, 4;
  chi << 0, 1;
  for (VtuFormat format : {VtuFormat::binary, VtuFormat::zlib, VtuFormat::ascii}) {
    const fs::path path = dir / "f.vtu";
    write_vtu(path, m,
              {vector_field("velocity", ux, uy), scalar_field("pressure", p),
               scalar_field("chi", chi, true)},
              format);
    const auto a = testing::read_vtu(path);
    ASSERT_EQ(a.at("velocity").size(), 12u);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(a.at("velocity")[3 * i], ux[i]);  // also ascii: 17 digits give the double back
      EXPECT_EQ(a.at("velocity")[3 * i + 1], uy[i]);
      EXPECT_EQ(a.at("velocity")[3 * i + 2], 0);
      EXPECT_EQ(a.at("pressure")[i], p[i]);
      EXPECT_EQ(a.at("")[3 * i], m.vertices[i].x());
      EXPECT_EQ(a.at("")[3 * i + 1], m.vertices[i].y());
    }
    EXPECT_EQ(a.at("chi"), (std::vector<double>{0, 1}));
    EXPECT_EQ(a.at("connectivity"), (std::vector<double>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(a.at("offsets"), (std::vector<double>{3, 6}));
    EXPECT_EQ(a.at("types"), (std::vector<double>{5, 5}));
  }
  fs::remove_all(dir);
}

// Arrays over 32 KiB take several zlib blocks; the binary files are smaller than the
// text one.
TEST(Vtu, LargeArraysInSeveralZlibBlocks) {
  const fs::path dir = fs::temp_directory_path() / "fsicontact-vtu-large";
  fs::create_directories(dir);
  Mesh m;
  const int n = 100;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.emplace_back(i / double(n), j / double(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      m.triangles.push_back({a, a + 1, a + n + 2});
      m.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  Eigen::VectorXd f(m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v)
    f[v] = std::sin(13 * m.vertices[v].x()) * m.vertices[v].y();
  std::map<VtuFormat, std::uintmax_t> size;
  for (VtuFormat format : {VtuFormat::binary, VtuFormat::zlib, VtuFormat::ascii}) {
    write_vtu(dir / "g.vtu", m, {scalar_field("f", f)}, format);
    size[format] = fs::file_size(dir / "g.vtu");
    const auto a = testing::read_vtu(dir / "g.vtu");
    ASSERT_EQ(a.at("f").size(), static_cast<std::size_t>(m.num_vertices()));
    for (int v = 0; v < m.num_vertices(); ++v) ASSERT_EQ(a.at("f")[v], f[v]) << v;
    ASSERT_EQ(a.at("connectivity").size(), 3 * m.triangles.size());
    EXPECT_EQ(a.at("connectivity").back(), m.triangles.back()[2]);
  }
  EXPECT_LT(size[VtuFormat::binary], size[VtuFormat::ascii]);
  EXPECT_LT(size[VtuFormat::zlib], size[VtuFormat::binary]);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::vtu_test
