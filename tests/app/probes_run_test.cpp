// output.probes end to end (SPEC §11, issue 14): summary.json's displacement_at is the
// P1 interpolant of the vertex displacements structure.vtu writes, in the order
// given; a coupled run's history.csv carries ũ at each probe per pass, its last row
// summary.json's value.
#include <gtest/gtest.h>

#include <array>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli.hpp"
#include "support/vtu_reader.hpp"

namespace fsi::probes_run_test {
namespace {

namespace fs = std::filesystem;
using Vertex = std::array<double, 2>;

struct StructureField {
  std::vector<Vertex> X, u;          // reference vertices and their displacement
  std::vector<std::array<int, 3>> triangles;
};

StructureField read_structure_vtu(const fs::path& path) {
  const auto vtu = testing::read_vtu(path);
  const std::vector<double>&points = vtu.at(""), &u = vtu.at("displacement"),
        &cells = vtu.at("connectivity");
  StructureField f;
  for (std::size_t v = 0; 3 * v + 2 < points.size(); ++v) {
    f.X.push_back({points[3 * v], points[3 * v + 1]});  // the reference configuration
    f.u.push_back({u[3 * v], u[3 * v + 1]});
  }
  for (std::size_t t = 0; 3 * t + 2 < cells.size(); ++t)
    f.triangles.push_back({int(cells[3 * t]), int(cells[3 * t + 1]), int(cells[3 * t + 2])});
  return f;
}

// Σ λ_a u_a over the triangle containing X, λ its barycentric coordinates, computed
// here from the vertices (not by the code under test).
Vertex p1_interpolant(const StructureField& f, const Vertex& X) {
  for (const auto& t : f.triangles) {
    const Vertex &a = f.X[t[0]], &b = f.X[t[1]], &c = f.X[t[2]];
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    const double l1 = ((X[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (X[1] - a[1])) / det;
    const double l2 = ((b[0] - a[0]) * (X[1] - a[1]) - (X[0] - a[0]) * (b[1] - a[1])) / det;
    const double l0 = 1 - l1 - l2;
    if (std::min({l0, l1, l2}) < -1e-12) continue;
    Vertex d{};
    for (int k = 0; k < 2; ++k) d[k] = l0 * f.u[t[0]][k] + l1 * f.u[t[1]][k] + l2 * f.u[t[2]][k];
    return d;
  }
  ADD_FAILURE() << "no triangle contains (" << X[0] << ", " << X[1] << ")";
  return {NAN, NAN};
}

TEST(ProbesRun, ContactSummaryIsTheP1InterpolantInTheOrderGiven) {
  const fs::path dir = testing::scratch_dir("probes-contact");
  const std::string case_path = std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.1-fig5-coarse.toml";
  // An interior point, then the beam's corner (L, H) (a vertex of every mesh of it).
  const std::vector<Vertex> probes = {{0.0301, 0.0023}, {0.06, 0.005}};
  const testing::CliRun r =
      testing::run_cli("run '" + case_path + "' --set 'output.probes=[[0.0301, 0.0023], [0.06, 0.005]]' --out res -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  const StructureField f = read_structure_vtu(dir / "res/structure.vtu");
  ASSERT_EQ(j["displacement_at"].size(), probes.size());
  // The VTU's 17 digits and λ's rounding: agreement to 1e-13 of |u| (≈ 8e-3 m here);
  // a wrong triangle or λ is off by the displacement's variation over a triangle, 1e-5.
  const double tol = 1e-13 * j["max_displacement"].get<double>();
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const auto& entry = j["displacement_at"][i];
    EXPECT_EQ(entry["point"][0].get<double>(), probes[i][0]) << i;
    EXPECT_EQ(entry["point"][1].get<double>(), probes[i][1]) << i;
    const Vertex expected = p1_interpolant(f, probes[i]);
    EXPECT_NEAR(entry["u"][0].get<double>(), expected[0], tol) << i;
    EXPECT_NEAR(entry["u"][1].get<double>(), expected[1], tol) << i;
  }
  // The corner is a vertex: its own value.
  bool found = false;
  for (std::size_t v = 0; v < f.X.size(); ++v)
    if (f.X[v] == probes[1]) {
      found = true;
      EXPECT_EQ(j["displacement_at"][1]["u"][0].get<double>(), f.u[v][0]);
      EXPECT_EQ(j["displacement_at"][1]["u"][1].get<double>(), f.u[v][1]);
    }
  EXPECT_TRUE(found) << "(L, H) is not a vertex";
  fs::remove_all(dir);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  return cells;
}

TEST(ProbesRun, CoupledHistoryEndsWithTheSummarysValue) {
  const fs::path dir = testing::scratch_dir("probes-fsi");
  const std::string case_path = std::string(FSICONTACT_SOURCE_DIR) + "/cases/paper-7.2.toml";
  // The tip (L, H/2), then a point inside the beam.
  const testing::CliRun r = testing::run_cli(
      "run '" + case_path + "' --set fluid.h=0.02 --set structure.h=0.03 --set 'output.probes=[[0.3, 0.015], [0.1, 0.01]]' "
      "--set output.png=false --set output.vtu=false --out res -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "res/summary.json"));
  ASSERT_EQ(j["converged"], true);
  std::istringstream history(testing::slurp(dir / "res/history.csv"));
  std::string line, last;
  std::getline(history, line);
  const std::vector<std::string> header = split(line);
  ASSERT_GE(header.size(), 14u);
  EXPECT_EQ(std::vector<std::string>(header.end() - 4, header.end()),
            (std::vector<std::string>{"u_x_1", "u_y_1", "u_x_2", "u_y_2"}));
  int rows = 0;
  while (std::getline(history, line)) last = line, ++rows;
  EXPECT_EQ(rows, j["iterations"].get<int>());
  const std::vector<std::string> cells = split(last);
  ASSERT_EQ(cells.size(), header.size());
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k)  // written in 17 digits: the same double
      EXPECT_EQ(std::stod(cells[header.size() - 4 + 2 * i + k]), j["displacement_at"][i]["u"][k].get<double>())
          << "probe " << i + 1 << " component " << k;
  // The first probe is the tip: the same interpolation as tip_displacement.
  EXPECT_EQ(j["displacement_at"][0]["u"], j["tip_displacement"]);
  EXPECT_LT(j["displacement_at"][0]["u"][1].get<double>(), -0.01);  // the tip rests on the disk, ~2.3 cm down
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::probes_run_test
