#include "qp/boundary_last_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <stdexcept>

namespace fsi {
namespace {

std::vector<char> columns_touched(const Eigen::SparseMatrix<double>& C) {
  std::vector<char> touched(static_cast<std::size_t>(C.cols()), 0);
  for (int j = 0; j < C.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, j); it; ++it)
      if (it.value() != 0) touched[static_cast<std::size_t>(j)] = 1;
  return touched;
}

}  // namespace

BoundaryLastCholesky::SparseMatrix BoundaryLastCholesky::permuted(const SparseMatrix& A) const {
  SparseMatrix Ap;
  Ap = A.selfadjointView<Eigen::Lower>().twistedBy(P_);  // P A Pᵀ, both triangles
  return Ap;
}

void BoundaryLastCholesky::analyse(const SparseMatrix& A, const SparseMatrix& C) {
  const int n = static_cast<int>(A.rows());
  constrained_ = columns_touched(C);
  std::vector<int> interior, boundary;
  for (int i = 0; i < n; ++i) (constrained_[i] ? boundary : interior).push_back(i);
  g_ = static_cast<int>(boundary.size());
  // AMD on A's interior block: the fill-reducing order of the dofs eliminated first.
  SparseMatrix select(n, static_cast<int>(interior.size()));
  for (std::size_t k = 0; k < interior.size(); ++k) select.insert(interior[k], static_cast<int>(k)) = 1.0;
  const SparseMatrix A_II = select.transpose() * A * select;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
  Eigen::AMDOrdering<int>()(A_II, amd);  // amd.indices()[new] = old (Eigen's Pinv)
  P_.resize(n);
  for (std::size_t k = 0; k < interior.size(); ++k) P_.indices()[interior[amd.indices()[k]]] = static_cast<int>(k);
  for (int k = 0; k < g_; ++k) P_.indices()[boundary[k]] = static_cast<int>(interior.size()) + k;
  llt_.analyzePattern(permuted(A));
  rows_ = n;
  nonzeros_ = static_cast<int>(A.nonZeros());
}

bool BoundaryLastCholesky::fits(const SparseMatrix& A, const SparseMatrix& C) const {
  return rows_ == A.rows() && nonzeros_ == A.nonZeros() && touches_only_constrained(C);
}

bool BoundaryLastCholesky::touches_only_constrained(const SparseMatrix& C) const {
  if (C.cols() != rows_) return false;
  const std::vector<char> touched = columns_touched(C);
  for (std::size_t j = 0; j < touched.size(); ++j)
    if (touched[j] && !constrained_[j]) return false;
  return true;
}

bool BoundaryLastCholesky::factorize(const SparseMatrix& A) {
  llt_.factorize(permuted(A));
  return llt_.info() == Eigen::Success;
}

Eigen::VectorXd BoundaryLastCholesky::solve(const Eigen::VectorXd& b) const {
  const Eigen::VectorXd y = llt_.solve(Eigen::VectorXd(P_ * b));
  return P_.transpose() * y;
}

Eigen::MatrixXd BoundaryLastCholesky::solve(const Eigen::MatrixXd& B) const {
  const Eigen::MatrixXd Y = llt_.solve(Eigen::MatrixXd(P_ * B));
  return P_.transpose() * Y;
}

Eigen::MatrixXd BoundaryLastCholesky::schur(const SparseMatrix& C) const {
  if (!touches_only_constrained(C)) throw std::logic_error("BoundaryLastCholesky::schur: C touches other columns");
  const SparseMatrix PCt = P_ * SparseMatrix(C.transpose());
  const Eigen::MatrixXd C_G = Eigen::MatrixXd(PCt.bottomRows(g_));  // g × m
  const SparseMatrix& L = llt_.matrixL().nestedExpression();
  const Eigen::MatrixXd L_GG = Eigen::MatrixXd(L.bottomRightCorner(g_, g_));
  const Eigen::MatrixXd W = L_GG.triangularView<Eigen::Lower>().solve(C_G);
  return W.transpose() * W;
}

}  // namespace fsi
