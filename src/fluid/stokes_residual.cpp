#include "fluid/stokes_residual.hpp"

#include "fem/quadrature.hpp"
#include "fluid/convection.hpp"
#include "fluid/mini_element.hpp"

namespace fsi {

Eigen::Matrix2Xd momentum_residual(const Mesh& mesh, const MomentumModel& model,
                                   const std::function<Point(const Point&)>& f,
                                   const FluidSolution& s, const std::vector<int>& vertices,
                                   const Eigen::VectorXd& kappa) {
  std::vector<int> column(mesh.num_vertices(), -1);
  for (std::size_t k = 0; k < vertices.size(); ++k) column[vertices[k]] = static_cast<int>(k);
  Eigen::Matrix2Xd R = Eigen::Matrix2Xd::Zero(2, static_cast<Eigen::Index>(vertices.size()));
  const TriangleRule rule =
      triangle_rule(6);  // as PenalisedStokes: the bubble (degree 3) × a smooth f
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (column[tri[0]] < 0 && column[tri[1]] < 0 && column[tri[2]] < 0) continue;
    const P1Triangle T(mesh, t);
    const double penalty = kappa.size() ? kappa[t] : 0.0;
    MiniLocal local = mini_local(T, model.mu, penalty, model.form);
    ElementLoad load = element_load(T, f, rule);
    if (model.rho != 0) {  // Newton's element at v_h: J v_h − (F + N(v_h)) = the residual
      const NewtonConvection convection(model.rho, mesh, s);
      convection.add(t, T, local);
      convection.add_load(t, T, load);
    }
    if (model.inertia) {
      model.inertia->add(t, T, local);
      model.inertia->add_load(t, T, load);
    }
    const CondensedElement e = condense(local, load);
    Vector9d z;  // [v1 at the 3 vertices, v2, p]
    for (int a = 0; a < 3; ++a)
      z[a] = s.v1[tri[a]], z[3 + a] = s.v2[tri[a]], z[6 + a] = s.p[tri[a]];
    const Vector9d r = e.K * z - e.F;
    for (int a = 0; a < 3; ++a)
      if (column[tri[a]] >= 0) R.col(column[tri[a]]) += Eigen::Vector2d(r[a], r[3 + a]);
  }
  return R;
}

Point hole_force(const Mesh& mesh, const MomentumModel& model, const std::function<Point(const Point&)>& f_F,
                 const FluidSolution& s, int label, const Eigen::VectorXd& kappa) {
  const Eigen::Matrix2Xd R = momentum_residual(mesh, model, f_F, s, mesh.vertices_on(label), kappa);
  return -R.rowwise().sum();
}

Point hole_force(const Mesh& mesh, const MomentumModel& model, const Point& f_F, const FluidSolution& s, int label,
                 const Eigen::VectorXd& kappa) {
  return hole_force(mesh, model, [f_F](const Point&) { return f_F; }, s, label, kappa);
}

}  // namespace fsi
