#include "fluid/petsc_blocks.hpp"

#include "fluid/petsc_try.hpp"

namespace fsi {

void KBlocks::free() { MatDestroy(&A_u), MatDestroy(&Bt), MatDestroy(&D), MatDestroy(&B); }

std::string take_blocks(Mat K, IS u, IS p, bool own_transpose, KBlocks& out) {
  FSI_TRY(MatCreateSubMatrix(K, u, p, MAT_INITIAL_MATRIX, &out.Bt));
  FSI_TRY(MatCreateSubMatrix(K, p, p, MAT_INITIAL_MATRIX, &out.D));
  if (!own_transpose) FSI_TRY(MatCreateSubMatrix(K, p, u, MAT_INITIAL_MATRIX, &out.B));
  FSI_TRY(MatCreateSubMatrix(K, u, u, MAT_INITIAL_MATRIX, &out.A_u));
  return "";
}

namespace {

// What schur_matrix makes and then destroys, destroyed on every path.
struct SchurScratch {
  Vec inverse = nullptr;
  Mat up = nullptr;
  ~SchurScratch() { VecDestroy(&inverse), MatDestroy(&up); }
};

}  // namespace

// Products of distributed blocks, so that a rank needs no row of another's;
// B diag(A_u)⁻¹ Bᵀ as (Bᵀ)ᵀ (diag(A_u)⁻¹ Bᵀ) where B is Bᵀ's transpose, the product's
// scratch (Bᵀ's transpose, kept for a reuse of the product) freed at once.
std::string schur_matrix(const KBlocks& k, Mat M, Mat& S) {
  SchurScratch x;
  FSI_TRY(MatCreateVecs(k.A_u, nullptr, &x.inverse));
  FSI_TRY(MatGetDiagonal(k.A_u, x.inverse));
  FSI_TRY(VecReciprocal(x.inverse));
  FSI_TRY(MatDuplicate(k.Bt, MAT_COPY_VALUES, &x.up));
  FSI_TRY(MatDiagonalScale(x.up, x.inverse, nullptr));
  if (k.B)
    FSI_TRY(MatMatMult(k.B, x.up, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &S));
  else
    FSI_TRY(MatTransposeMatMult(k.Bt, x.up, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &S));
  FSI_TRY(MatProductClear(S));
  FSI_TRY(MatDestroy(&x.up));
  FSI_TRY(MatAYPX(S, -1.0, k.D, DIFFERENT_NONZERO_PATTERN));  // S = D − B diag(A_u)⁻¹ Bᵀ
  if (M) FSI_TRY(MatAXPY(S, -1.0, M, DIFFERENT_NONZERO_PATTERN));
  return "";
}

std::string make_field_vectors(Mat Bt, Vec whole, IS u, IS p, std::shared_ptr<FieldVectors>& out) {
  auto v = std::make_shared<FieldVectors>();
  FSI_TRY(MatCreateVecs(Bt, &v->a_p, &v->a_u));
  FSI_TRY(VecDuplicate(v->a_u, &v->b_u));
  FSI_TRY(VecDuplicate(v->a_p, &v->b_p));
  FSI_TRY(VecScatterCreate(whole, u, v->a_u, nullptr, &v->to_u));
  FSI_TRY(VecScatterCreate(whole, p, v->a_p, nullptr, &v->to_p));
  out = std::move(v);
  return "";
}

PetscErrorCode FieldVectors::split(Vec whole) {
  PetscCall(VecScatterBegin(to_u, whole, a_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_u, whole, a_u, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterBegin(to_p, whole, a_p, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_p, whole, a_p, INSERT_VALUES, SCATTER_FORWARD));
  return 0;
}

PetscErrorCode FieldVectors::join(Vec u, Vec p, Vec whole) {
  PetscCall(VecScatterBegin(to_u, u, whole, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(to_u, u, whole, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterBegin(to_p, p, whole, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(to_p, p, whole, INSERT_VALUES, SCATTER_REVERSE));
  return 0;
}

void FieldVectors::free() {
  VecDestroy(&a_u), VecDestroy(&a_p), VecDestroy(&b_u), VecDestroy(&b_p);
  VecScatterDestroy(&to_u), VecScatterDestroy(&to_p);
}

}  // namespace fsi
