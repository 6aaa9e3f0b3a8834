// Valid .msh files load, in MSH 4.1 and 2.2, ASCII and binary; a clockwise surface
// is turned as a whole; the repository's meshes load as before.
#include <gtest/gtest.h>

#include "mesh/gmsh_io.hpp"

namespace fsi::msh_reading_test {
namespace {

const std::string kSeeds = FSICONTACT_SOURCE_DIR "/tests/data/fuzz-msh/";
const std::string kCases = FSICONTACT_SOURCE_DIR "/cases/meshes/";
const std::vector<std::string> kStructure = {"Gamma_D", "Gamma_C", "Gamma_N"};

Mesh read_structure(const std::string& path) {
  return read_gmsh_file(path, kStructure, "Omega_S");
}

TEST(MshReading, TheRectangleLoads) {
  const Mesh m = read_structure(kSeeds + "valid-4.1.msh");
  EXPECT_EQ(m.num_triangles(), 4);
  EXPECT_EQ(m.num_vertices(), 6);
  EXPECT_EQ(m.label_names, kStructure);
  EXPECT_EQ(m.edges_on(m.label("Gamma_N")).size(), 4u);
  // Vertices are numbered in order of first use: nodes 1, 2, 5, 6, 3, 4.
  EXPECT_EQ(m.vertices_on(m.label("Gamma_C")), (std::vector<int>{1, 4}));
  double area = 0;
  for (int t = 0; t < m.num_triangles(); ++t) area += m.area(t);
  EXPECT_DOUBLE_EQ(area, 2.0);
}

TEST(MshReading, Msh22GivesTheSameMeshAs41) {
  const Mesh a = read_structure(kSeeds + "valid-4.1.msh"),
             b = read_structure(kSeeds + "valid-2.2.msh");
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
  ASSERT_EQ(a.boundary_edges.size(), b.boundary_edges.size());
  for (std::size_t i = 0; i < a.boundary_edges.size(); ++i) {
    EXPECT_EQ(a.boundary_edges[i].v, b.boundary_edges[i].v);
    EXPECT_EQ(a.boundary_edges[i].label, b.boundary_edges[i].label);
  }
}

// A surface whose normal is −z: every triangle clockwise. Turned as a whole, it is
// the valid rectangle with each triangle's last two vertices swapped.
TEST(MshReading, AClockwiseSurfaceIsTurned) {
  const Mesh cw = read_structure(kSeeds + "clockwise.msh"),
             ccw = read_structure(kSeeds + "valid-4.1.msh");
  ASSERT_EQ(cw.num_triangles(), ccw.num_triangles());
  for (int t = 0; t < cw.num_triangles(); ++t) EXPECT_DOUBLE_EQ(cw.area(t), ccw.area(t));
}

// Gmsh orients each surface by its own normal: a surface drawn the other way round
// is clockwise throughout and is turned alone (its neighbour stays as it is).
TEST(MshReading, EachSurfaceIsTurnedOnItsOwn) {
  const Mesh m = read_structure(kSeeds + "two-surfaces-opposite-normals.msh");
  const Mesh ref = read_structure(kSeeds + "valid-4.1.msh");
  ASSERT_EQ(m.num_triangles(), 4);
  for (int t = 0; t < 4; ++t) EXPECT_DOUBLE_EQ(m.area(t), ref.area(t));
}

// Physical groups are merged by name; a surface in two groups of one name is one
// surface (it was read twice: "triangles 7 and 7 overlap").
TEST(MshReading, ASurfaceInTwoGroupsOfOneNameCountsOnce) {
  EXPECT_EQ(read_structure(kSeeds + "one-surface-in-two-groups-of-one-name.msh").num_triangles(),
            4);
}

// Counts as before the checks were added (the vertices are bit for bit the same too).
TEST(MshReading, TheRepositorysMeshesLoadAsBefore) {
  const Mesh beam = read_structure(kCases + "paper-7.1-beam.msh");
  EXPECT_EQ(beam.num_triangles(), 335);
  EXPECT_EQ(beam.num_vertices(), 213);
  EXPECT_EQ(beam.boundary_edges.size(), 89u);
  const Mesh box = read_gmsh_file(kCases + "paper-7.2-box-h0.02.msh",
                                  {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4", "Sigma_5"}, "D");
  EXPECT_EQ(box.num_triangles(), 2432);
  EXPECT_EQ(box.num_vertices(), 1295);
  EXPECT_EQ(box.boundary_edges.size(), 158u);
}

TEST(MshReading, ABinaryFileGivesTheSameMeshAsItsAsciiTwin) {
  const Mesh a = read_structure(kCases + "paper-7.1-beam.msh");
  const Mesh b =
      read_structure(FSICONTACT_SOURCE_DIR "/tests/data/meshes/paper-7.1-beam-binary.msh");
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.boundary_edges.size(), b.boundary_edges.size());
}

TEST(MshReading, TooShortALimitStopsTheReader) {
  EXPECT_THROW(
      read_gmsh_file(kCases + "paper-7.1-beam.msh", kStructure, "Omega_S", GmshLimits{1e-6}),
      MeshError);
}

}  // namespace
}  // namespace fsi::msh_reading_test
