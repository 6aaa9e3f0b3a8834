#include "mesh/generated_mesh.hpp"

#include <cmath>
#include <stdexcept>

#include "mesh/gmsh_io.hpp"
#include "mesh/lattice_mesher.hpp"
#include "mesh/mesh_validation.hpp"

namespace fsi {

MeshGenerator mesh_generator(const std::string& name) {
  if (name == "lattice") return MeshGenerator::lattice;
  if (name == "gmsh") return MeshGenerator::gmsh;
  throw std::invalid_argument("\"lattice\" or \"gmsh\"");
}

std::vector<int> hole_labels(const Mesh& mesh) {
  // Sigma_5_i first: a file read for [[obstacles]] may also hold Sigma_5, empty.
  std::vector<int> labels;
  for (int i = 1; mesh.has_label("Sigma_5_" + std::to_string(i)); ++i)
    labels.push_back(mesh.label("Sigma_5_" + std::to_string(i)));
  if (labels.empty() && mesh.has_label("Sigma_5")) return {mesh.label("Sigma_5")};
  return labels;
}

namespace {

BoundaryPiece segment(const Point& a, const Point& b, int label, int min_segments = 1) {
  BoundaryPiece p{a, b};
  p.label = label;
  p.min_segments = min_segments;
  return p;
}

// In units of u: the bottom cut at the ends of Γ_C, so that they are vertices. Γ_C's
// points stay equally spaced: sliding them (to better angles) tripled the pointwise
// penetration of the weak contact on §7.1's beam (measured: 2.0e-5 against 0.67e-5 m
// of the gap's linearisation alone, tests/solid/normal_contact_test.cpp).
PlanarDomain structure_domain(const StructureGeometry& g, double u) {
  enum { gamma_d, gamma_c, gamma_n };
  const double L = g.L / u, H = g.H / u, c0 = g.xc_min / u, c1 = g.xc_max / u;
  PlanarDomain d{{}, {"Gamma_D", "Gamma_C", "Gamma_N"}};
  BoundaryPiece contact = segment({c0, 0}, {c1, 0}, gamma_c);
  contact.slide = false;
  d.loops.push_back({segment({0, 0}, {c0, 0}, gamma_n), contact, segment({c1, 0}, {L, 0}, gamma_n),
                     segment({L, 0}, {L, H}, gamma_n), segment({L, H}, {0, H}, gamma_n),
                     segment({0, H}, {0, 0}, gamma_d)});
  return d;
}

// In units of u. A circle needs six segments at least (the case's check: h ≤ r);
// a polygon's side two (SPEC §9: every side of a hole is cut).
PlanarDomain fluid_domain(const FluidGeometry& g, double u) {
  const double L1 = g.L1 / u, H1 = g.H1 / u, H2 = g.H2 / u;
  PlanarDomain d{{}, {"Sigma_1", "Sigma_2", "Sigma_3", "Sigma_4"}};
  d.loops.push_back({segment({0, -H2}, {L1, -H2}, 1), segment({L1, -H2}, {L1, H1}, 2),
                     segment({L1, H1}, {0, H1}, 3), segment({0, H1}, {0, -H2}, 0)});
  const std::vector<FluidHole> holes =
      g.holes ? *g.holes : std::vector<FluidHole>{{g.x0, g.y0, g.r}};
  for (std::size_t k = 0; k < holes.size(); ++k) {
    d.labels.push_back(g.holes ? "Sigma_5_" + std::to_string(k + 1) : "Sigma_5");
    const int label = static_cast<int>(d.labels.size()) - 1;
    const FluidHole& hole = holes[k];
    std::vector<BoundaryPiece> loop;
    if (hole.corners.empty()) {
      BoundaryPiece circle;
      circle.c = Point(hole.x0, hole.y0) / u;
      circle.r = hole.r / u;
      circle.label = label;
      circle.min_segments = 6;
      loop.push_back(circle);
    } else {
      const std::size_t m = hole.corners.size();
      for (std::size_t i = 0; i < m; ++i)
        loop.push_back(segment(hole.corners[i] / u, hole.corners[(i + 1) % m] / u, label, 2));
    }
    d.loops.push_back(std::move(loop));
  }
  return d;
}

// The generator's mesh in the case's units, checked as a mesh from a file would be:
// a fault of ours must not reach the solver.
Mesh in_case_units(Mesh mesh, double u) {
  if (u != 1)
    for (Point& p : mesh.vertices) p *= u;
  MeshOrigin origin;
  for (int v = 1; v <= mesh.num_vertices(); ++v)
    origin.node_tags.push_back(static_cast<std::size_t>(v));
  for (int t = 1; t <= mesh.num_triangles(); ++t)
    origin.triangle_tags.push_back(static_cast<std::size_t>(t));
  origin.triangle_surfaces.assign(mesh.triangles.size(), 1);
  for (std::size_t e = 1; e <= mesh.boundary_edges.size(); ++e) origin.edge_tags.push_back(e);
  orient_and_validate(mesh, origin);
  return mesh;
}

}  // namespace

Mesh generate_structure_mesh(const StructureGeometry& g, MeshGenerator by) {
  if (by == MeshGenerator::gmsh) return gmsh_structure_mesh(g);
  const double u = reference_length(std::max(std::abs(g.L), std::abs(g.H)));
  try {
    return in_case_units(lattice_mesh(structure_domain(g, u), SizeField{g.h / u}), u);
  } catch (const MeshError& e) {
    throw MeshError(std::string("meshing the structure: ") + e.what());
  }
}

Mesh generate_fluid_mesh(const FluidGeometry& g, MeshGenerator by) {
  if (by == MeshGenerator::gmsh) return gmsh_fluid_mesh(g);
  if (g.h_holes > 0) throw MeshError("the refinement at the holes (fluid.h_obstacles) is a Gmsh size field");
  const double u = reference_length(std::max(std::abs(g.L1), std::abs(g.H1) + std::abs(g.H2)));
  SizeField size{g.h / u};
  if (g.h_near > 0)
    size = {g.h / u,
            g.h_near / u,
            {g.band[0] / u, g.band[1] / u, g.band[2] / u, g.band[3] / u},
            kBandGrowth};
  try {
    return in_case_units(lattice_mesh(fluid_domain(g, u), size), u);
  } catch (const MeshError& e) {
    throw MeshError(std::string("meshing the fluid box: ") + e.what());
  }
}

}  // namespace fsi
