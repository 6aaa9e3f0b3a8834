// The bytes a Gmsh child sends: what is encoded comes back, and malformed bytes are
// a MeshError, never a read past the end or an allocation the bytes cannot back.
#include "mesh/raw_mesh.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "mesh/mesh_error.hpp"

namespace fsi::raw_mesh_test {
namespace {

RawMesh sample() {
  RawMesh raw;
  raw.node_tags = {4, 7, 9};
  raw.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  raw.groups = {{2, "Omega_S", {1}}, {1, "Gamma_D", {3, 5}}};
  raw.elements = {{2, 1, 2, 3, {11}, {4, 7, 9}}, {1, 3, 1, 2, {12}, {9, 4}}};
  raw.log = {"Info: Skipping duplicate node 7"};
  return raw;
}

TEST(RawMesh, RoundTrips) {
  const RawMesh a = sample(), b = decode(encode(a));
  EXPECT_EQ(b.node_tags, a.node_tags);
  EXPECT_EQ(b.coords, a.coords);
  ASSERT_EQ(b.groups.size(), 2u);
  EXPECT_EQ(b.groups[1].name, "Gamma_D");
  EXPECT_EQ(b.groups[1].entities, (std::vector<int>{3, 5}));
  ASSERT_EQ(b.elements.size(), 2u);
  EXPECT_EQ(b.elements[0].nodes, (std::vector<std::size_t>{4, 7, 9}));
  EXPECT_EQ(b.elements[1].gmsh_type, 1);
  EXPECT_EQ(b.log, a.log);
}

TEST(RawMesh, EveryTruncationIsAMeshError) {
  const std::vector<char> whole = encode(sample());
  for (std::size_t n = 0; n < whole.size(); ++n)
    EXPECT_THROW(decode(std::vector<char>(whole.begin(), whole.begin() + n)), MeshError) << n;
  std::vector<char> longer = whole;
  longer.push_back(0);
  EXPECT_THROW(decode(longer), MeshError);
}

TEST(RawMesh, AHugeCountIsRefusedBeforeAllocating) {
  std::vector<char> bytes(16, 0);
  const std::uint64_t huge = std::uint64_t{1} << 60;
  std::memcpy(bytes.data(), &huge, sizeof huge);
  EXPECT_THROW(decode(bytes), MeshError);
}

}  // namespace
}  // namespace fsi::raw_mesh_test
