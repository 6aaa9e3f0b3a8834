#include "run/structure_setup.hpp"

#include "common/errors.hpp"
#include "mesh/gmsh_io.hpp"
#include "run/mesh_checks.hpp"
#include "qp/active_set_solver.hpp"
#include "qp/ipopt_solver.hpp"

namespace fsi {

std::unique_ptr<QpSolver> make_qp_solver(const std::string& name) {
  if (name == "ipopt") return std::make_unique<IpoptSolver>();
  return std::make_unique<ActiveSetSolver>();
}

Mesh build_structure_mesh(const Case& c) {
  const auto& s = c.structure;
  const auto& o = c.obstacle;
  if (s.mesh.empty()) {
    try {
      return generate_structure_mesh({s.L, s.H, o.xc_min(), o.xc_max(), s.h});
    } catch (const MeshError& e) {  // the geometry was validated: Gmsh's failure, or ours
      throw SolverFailure(std::string("meshing the structure failed: ") + e.what());
    }
  }
  return read_case_mesh(c, "structure.mesh", s.mesh, {"Gamma_D", "Gamma_C", "Gamma_N"}, "Omega_S",
                        case_limits().structure_triangles);
}

Mesh make_structure_mesh(const Case& c) {
  Mesh mesh = build_structure_mesh(c);
  check_structure_mesh(c, mesh);
  return mesh;
}

StructureSetup make_structure(const Case& c, Mesh mesh,
                              const std::function<void(const std::string&)>& progress) {
  StructureSetup s;
  s.lame = Lame::from_young_poisson(c.structure.E, c.structure.nu);
  s.foundation = std::make_unique<DiskFoundation>(c.obstacle.x0, c.obstacle.y0, c.obstacle.r);
  s.qp = make_qp_solver(c.contact.solver);
  s.qp->progress = progress;
  const int gamma_c = mesh.label("Gamma_C");
  const std::vector<int> fixed = clamped_dofs(mesh, mesh.label("Gamma_D"));
  try {
    s.solver = std::make_unique<ElasticContactSolver>(std::move(mesh), s.lame, *s.foundation,
                                                      gamma_c, fixed, *s.qp);
  } catch (const QpError& e) {
    throw SolverFailure(std::string("structure: ") + e.what());
  }
  const Point f = c.structure.f, h_N = c.structure.h_N;
  const Mesh& m = s.mesh();
  s.b_applied = assemble_volume_load(m, [f](const Point&) { return f; }, 1) +
                assemble_surface_load(m, m.label("Gamma_N"), [h_N](const Point&) { return h_N; }, 1);
  return s;
}

}  // namespace fsi
