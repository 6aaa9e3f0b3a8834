#include "solid/contact.hpp"

#include <map>
#include <stdexcept>

#include "fem/integration.hpp"
#include "fem/vector_p1.hpp"

namespace fsi {

ContactConstraint assemble_contact(const Mesh& mesh, int gamma_c_label, const Foundation& psi,
                                   int gauss_points) {
  const int nv = mesh.num_vertices();
  const std::vector<BoundaryEdge> edges = mesh.edges_on(gamma_c_label);
  // A vertex is strictly inside Γ_C when two Γ_C edges meet there.
  std::map<int, int> edges_at;
  for (const auto& e : edges)
    for (int v : e.v) ++edges_at[v];
  ContactConstraint out;
  std::map<int, int> row_of;
  for (const auto& [v, count] : edges_at)
    if (count == 2) {
      row_of[v] = static_cast<int>(out.row_vertex.size());
      out.row_vertex.push_back(v);
    }
  const int rows = static_cast<int>(out.row_vertex.size());
  out.c_lb = Eigen::VectorXd::Zero(rows);
  std::vector<Eigen::Triplet<double>> entries;
  integrate_on_edges(mesh, edges, gauss_legendre(gauss_points), [&](const BoundaryEdge& e, const EdgePoint& q) {
    const Point& X = q.x;
    if (!psi.defined_at(X.x())) throw std::domain_error("Gamma_C reaches beyond the obstacle's span");
    for (int a = 0; a < 2; ++a) {
      auto row = row_of.find(e.v[a]);
      if (row == row_of.end()) continue;
      const double weight = q.phi[a] * q.ds;
      out.c_lb[row->second] += (psi.psi(X.x()) - X.y()) * weight;
      for (int b = 0; b < 2; ++b) {
        entries.emplace_back(row->second, dof(e.v[b], 0, nv), -psi.dpsi(X.x()) * q.phi[b] * weight);
        entries.emplace_back(row->second, dof(e.v[b], 1, nv), q.phi[b] * weight);
      }
    }
  });
  out.C_S.resize(rows, 2 * nv);
  out.C_S.setFromTriplets(entries.begin(), entries.end());
  return out;
}

}  // namespace fsi
