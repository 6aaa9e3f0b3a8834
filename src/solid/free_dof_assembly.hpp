// The hyperelastic internal force and tangent assembled straight onto the free dofs
// (Dirichlet dofs eliminated), into the fixed sparsity of A_S's free block: what each
// Newton step (SPEC §11) needs, without triplets or selection products. Measured on the
// §7.2 beam (154 dofs): the triplet assembly and Pᵀ K P took about half of a step.
// One loop serves P1 (3 nodes, one point: F is constant on a triangle) and P2 (6 nodes,
// the degree-4 rule of solid/p2_elasticity.hpp): each element stores its nodes and, at
// each point, the basis gradients and the weight times the area.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "fem/p1.hpp"
#include "fem/p2.hpp"
#include "mesh/mesh.hpp"
#include "solid/hyperelastic.hpp"

namespace fsi {

class FreeDofAssembler {
 public:
  // `free_dofs`: the free dofs in increasing order (reduced index k ↔ free_dofs[k]);
  // `pattern`: a matrix on them with every free–free coupling of the mesh (A_S's).
  FreeDofAssembler(const Mesh& mesh, const std::vector<int>& free_dofs, const SparseMatrix& pattern);
  // The same on the P2 space (dofs c·n + node, n its nodes).
  FreeDofAssembler(const P2Space& space, const std::vector<int>& free_dofs, const SparseMatrix& pattern);

  // f_int(u) on the free dofs (u on all dofs). Throws SolverFailure for an inverted
  // point with the neo-Hookean model.
  Eigen::VectorXd force(const Material& m, const Eigen::VectorXd& u) const;
  // K_T(u) on the free dofs, written into K's values (K: a copy of `pattern`).
  void tangent(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const;

 private:
  struct QuadraturePoint {
    Eigen::Matrix<double, 6, 2> grad;  // rows 0 … nodes_ − 1: ∇N_a
    double dx;
  };
  void index_slots(const std::vector<int>& free_dofs, const SparseMatrix& pattern);
  template <int N>
  Matrix2 gradient(int e, const QuadraturePoint& q, const Eigen::VectorXd& u) const;
  template <int N>
  Eigen::VectorXd force_of(const Material& m, const Eigen::VectorXd& u) const;
  template <int N>
  void tangent_of(const Material& m, const Eigen::VectorXd& u, SparseMatrix& K) const;
  const QuadraturePoint* points_of(int e) const { return &points_[static_cast<std::size_t>(e * per_element_)]; }

  int nodes_ = 3;         // per element
  int per_element_ = 1;   // quadrature points per element
  int n_ = 0;             // nodes of the space (dof = c·n_ + node)
  std::vector<std::array<int, 6>> elements_;
  std::vector<QuadraturePoint> points_;
  std::vector<int> reduced_;  // dof → reduced index, −1 if fixed
  std::vector<int> slot_;     // (2 nodes_)² per element: (a + nodes_ c, b + nodes_ d) → position in K's values, −1 if fixed
};

}  // namespace fsi
