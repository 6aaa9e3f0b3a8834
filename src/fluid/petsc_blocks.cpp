#include "fluid/petsc_blocks.hpp"

#include "fluid/petsc_try.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <numeric>
#include <vector>

namespace fsi {

void KBlocks::free() { MatDestroy(&A_u), MatDestroy(&Bt), MatDestroy(&D), MatDestroy(&B); }

namespace {

// This rank's rows of K seen by the fields (velocity 0, pressure 1): each unknown's
// number among its field's unknowns, as the index sets split them (petsc_plugin.cpp's
// split_fields) and the field vectors are laid out, and this rank's numbers of each
// field, [start, end).
struct FieldView {
  const PetscCsr& m;
  const std::vector<char>& is_pressure;
  std::vector<PetscInt> number;
  PetscInt start[2] = {0, 0}, end[2] = {0, 0};
  FieldView(const PetscCsr& rows, const std::vector<char>& pressure);
  int field(int i) const { return is_pressure[static_cast<std::size_t>(i)] ? 1 : 0; }
  bool here(int i) const { return i >= m.first && i < m.last; }  // a row of this rank's
  PetscInt rows(int f) const { return end[f] - start[f]; }
};

FieldView::FieldView(const PetscCsr& rows, const std::vector<char>& pressure)
    : m(rows), is_pressure(pressure), number(pressure.size()) {
  PetscInt count[2] = {0, 0};
  for (std::size_t i = 0; i < number.size(); ++i) number[i] = count[field(static_cast<int>(i))]++;
  for (int i = 0; i < m.last; ++i) ++(i < m.first ? start : end)[field(i)];
  for (int f = 0; f < 2; ++f) end[f] += start[f];
}

// Block (r, c)'s entries in each of its rows: in columns on this rank (PETSc's
// "diagonal" part) and elsewhere, for an exact preallocation.
struct BlockShape {
  std::vector<PetscInt> local, other;
};

using Shapes = std::array<std::array<BlockShape, 2>, 2>;

Shapes block_shapes(const FieldView& v) {
  Shapes shape;
  for (int r = 0; r < 2; ++r)
    for (auto& s : shape[static_cast<std::size_t>(r)])
      s.local.assign(static_cast<std::size_t>(v.rows(r)), 0), s.other = s.local;
  const PetscCsr& m = v.m;
  for (int i = m.first; i < m.last; ++i) {
    const int r = v.field(i);
    const auto row = static_cast<std::size_t>(v.number[static_cast<std::size_t>(i)] - v.start[r]);
    for (int k = m.row_start[i - m.first]; k < m.row_start[i - m.first + 1]; ++k) {
      BlockShape& s = shape[static_cast<std::size_t>(r)][static_cast<std::size_t>(v.field(m.column[k]))];
      ++(v.here(m.column[k]) ? s.local : s.other)[row];
    }
  }
  return shape;
}

// A block's compressed rows, which its matrix uses in place and frees with itself (a
// container composed with it): its columns on this rank (numbered from the first) and,
// on several ranks, those elsewhere (their global numbers). No copy, and no entry set
// one by one: through MatSetValues the blocks took 1.25 s to make on one rank at 1.4 M
// unknowns, against 0.9 s for MatCreateSubMatrix of a K held whole (docs/performance.md,
// "Huge pages, and the set-up on two ranks").
struct BlockArrays {
  std::vector<PetscInt> i, j, oi, oj;
  std::vector<PetscScalar> a, oa;
};

PetscErrorCode free_block_arrays(void* arrays) {
  delete static_cast<BlockArrays*>(arrays);
  return 0;
}

std::vector<PetscInt> row_starts(const std::vector<PetscInt>& count) {
  std::vector<PetscInt> start(count.size() + 1, 0);
  std::partial_sum(count.begin(), count.end(), start.begin() + 1);
  return start;
}

// The blocks (r, 0) and (r, 1)'s entries (out[c]; null: not made), in one pass over
// the rows of field r, row by row in order (a row's columns stay sorted): a pass a
// block read each row twice.
void fill_blocks(const FieldView& v, int r, const std::array<BlockArrays*, 2>& out) {
  const PetscCsr& m = v.m;
  std::array<std::size_t, 2> on_rank{}, off_rank{};  // entries filled of each part
  for (BlockArrays* b : out)
    if (b) {
      b->j.resize(static_cast<std::size_t>(b->i.back())), b->a.resize(b->j.size());
      b->oj.resize(static_cast<std::size_t>(b->oi.back())), b->oa.resize(b->oj.size());
    }
  for (int i = m.first; i < m.last; ++i) {
    if (v.field(i) != r) continue;
    for (int k = m.row_start[i - m.first]; k < m.row_start[i - m.first + 1]; ++k) {
      const int col = m.column[k], c = v.field(col);
      BlockArrays* const b = out[static_cast<std::size_t>(c)];
      if (!b) continue;
      const PetscInt number = v.number[static_cast<std::size_t>(col)];
      if (v.here(col)) {
        std::size_t& at = on_rank[static_cast<std::size_t>(c)];
        b->j[at] = number - v.start[c], b->a[at++] = m.value[k];
      } else {
        std::size_t& at = off_rank[static_cast<std::size_t>(c)];
        b->oj[at] = number, b->oa[at++] = m.value[k];
      }
    }
  }
}

// A matrix of this rank's rows × cols on filled arrays, which it then owns: compressed
// rows, their columns on this rank numbered from the first and, on several ranks (whole
// false), those elsewhere by their global numbers.
std::string matrix_on(PetscInt rows, PetscInt cols, bool whole, std::unique_ptr<BlockArrays> arrays, Mat& out) {
  BlockArrays& b = *arrays;
  // Never empty: an empty vector's data() may be null, which PETSc refuses (the entry
  // past the last row's end is never read).
  if (b.j.empty()) b.j.push_back(0), b.a.push_back(0.0);
  if (b.oj.empty()) b.oj.push_back(0), b.oa.push_back(0.0);
  if (whole)
    FSI_TRY(MatCreateSeqAIJWithArrays(PETSC_COMM_WORLD, rows, cols, b.i.data(), b.j.data(), b.a.data(), &out));
  else
    FSI_TRY(MatCreateMPIAIJWithSplitArrays(PETSC_COMM_WORLD, rows, cols, PETSC_DETERMINE, PETSC_DETERMINE,
                                           b.i.data(), b.j.data(), b.a.data(), b.oi.data(), b.oj.data(),
                                           b.oa.data(), &out));
  PetscContainer owner = nullptr;
  FSI_TRY(PetscContainerCreate(PETSC_COMM_SELF, &owner));
  FSI_TRY(PetscContainerSetPointer(owner, arrays.release()));
  FSI_TRY(PetscContainerSetUserDestroy(owner, free_block_arrays));
  FSI_TRY(PetscObjectCompose(reinterpret_cast<PetscObject>(out), "fsi_block_arrays",
                             reinterpret_cast<PetscObject>(owner)));
  FSI_TRY(PetscContainerDestroy(&owner));  // out holds it now
  return "";
}

// Block (r, c)'s matrix on its filled arrays.
std::string make_block(const FieldView& v, int r, int c, std::unique_ptr<BlockArrays> arrays, Mat& out) {
  return matrix_on(v.rows(r), v.rows(c), v.m.last - v.m.first == v.m.n, std::move(arrays), out);
}

}  // namespace

// One pass over the rows counts each block's entries a row; a pass a field fills its
// blocks. On several ranks this replaced K's own copy in PETSc and four
// MatCreateSubMatrix (docs/performance.md, "Huge pages, and the set-up on two ranks").
std::string split_blocks(const PetscCsr& m, const std::vector<char>& is_pressure, bool own_transpose,
                         KBlocks& out) {
  const FieldView v(m, is_pressure);
  const Shapes shape = block_shapes(v);
  Mat* const block[2][2] = {{&out.A_u, &out.Bt}, {own_transpose ? nullptr : &out.B, &out.D}};
  for (int r = 0; r < 2; ++r) {
    std::array<std::unique_ptr<BlockArrays>, 2> arrays;
    for (int c = 0; c < 2; ++c)
      if (block[r][c]) {
        const BlockShape& s = shape[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
        arrays[static_cast<std::size_t>(c)] = std::make_unique<BlockArrays>();
        arrays[static_cast<std::size_t>(c)]->i = row_starts(s.local);
        arrays[static_cast<std::size_t>(c)]->oi = row_starts(s.other);
      }
    fill_blocks(v, r, {arrays[0].get(), arrays[1].get()});
    for (int c = 0; c < 2; ++c)
      if (block[r][c])
        if (std::string e = make_block(v, r, c, std::move(arrays[static_cast<std::size_t>(c)]), *block[r][c]);
            !e.empty())
          return e;
  }
  return "";
}

namespace {

// What schur_matrix makes and then destroys, destroyed on every path.
struct SchurScratch {
  Vec inverse = nullptr;
  Mat up = nullptr, product = nullptr;
  ~SchurScratch() { VecDestroy(&inverse), MatDestroy(&up), MatDestroy(&product); }
};

// A term of a sum of matrices of one layout: the matrix, its sign and, while a row is
// added, that row (its global columns, sorted) and how far it has been read.
struct Term {
  Mat A;
  PetscScalar sign;
  PetscInt n = 0, at = 0;
  const PetscInt* column = nullptr;
  const PetscScalar* value = nullptr;
};

// This rank's row of Σ sign A over the terms, appended to b: the union of the terms'
// columns, merged in order, each entry summed in the terms' order.
void add_row(std::vector<Term>& terms, PetscInt first_column, PetscInt end_column, BlockArrays& b) {
  for (;;) {
    PetscInt c = PETSC_MAX_INT;
    for (const Term& t : terms)
      if (t.at < t.n) c = std::min(c, t.column[t.at]);
    if (c == PETSC_MAX_INT) return;
    PetscScalar sum = 0.0;
    for (Term& t : terms)
      if (t.at < t.n && t.column[t.at] == c) sum += t.sign * t.value[t.at++];
    if (c >= first_column && c < end_column)
      b.j.push_back(c - first_column), b.a.push_back(sum);
    else
      b.oj.push_back(c), b.oa.push_back(sum);
  }
}

// Σ sign A over the terms, a new matrix, in one pass over their rows. Two MatAXPY of
// different patterns, each making a new matrix through MatSetValues, took 0.28 s on one
// rank and 0.25 s a rank on two for S_p at 1.4 M unknowns (docs/performance.md,
// "Chebyshev smoothing, and the set-up by parts again").
std::string sum_of(std::vector<Term> terms, Mat& S) {
  PetscInt first = 0, last = 0, first_column = 0, end_column = 0;
  FSI_TRY(MatGetOwnershipRange(terms[0].A, &first, &last));
  FSI_TRY(MatGetOwnershipRangeColumn(terms[0].A, &first_column, &end_column));
  PetscMPIInt ranks = 1;  // a rank could hold all of S's rows and still not be alone
  MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(terms[0].A)), &ranks);
  auto arrays = std::make_unique<BlockArrays>();
  BlockArrays& b = *arrays;
  double entries = 0.0;  // at most, the terms' own, reserved so that no array grows twice
  for (const Term& t : terms) {
    MatInfo info;
    FSI_TRY(MatGetInfo(t.A, MAT_LOCAL, &info));
    entries += info.nz_used;
  }
  b.i.reserve(static_cast<std::size_t>(last - first) + 1), b.oi.reserve(b.i.capacity());
  b.j.reserve(static_cast<std::size_t>(entries)), b.a.reserve(b.j.capacity());
  b.i.push_back(0), b.oi.push_back(0);
  for (PetscInt row = first; row < last; ++row) {
    for (Term& t : terms) {
      FSI_TRY(MatGetRow(t.A, row, &t.n, &t.column, &t.value));
      t.at = 0;
    }
    add_row(terms, first_column, end_column, b);
    for (Term& t : terms) FSI_TRY(MatRestoreRow(t.A, row, &t.n, &t.column, &t.value));
    b.i.push_back(static_cast<PetscInt>(b.j.size())), b.oi.push_back(static_cast<PetscInt>(b.oj.size()));
  }
  return matrix_on(last - first, end_column - first_column, ranks == 1, std::move(arrays), S);
}

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
    FSI_TRY(MatMatMult(k.B, x.up, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &x.product));
  else
    FSI_TRY(MatTransposeMatMult(k.Bt, x.up, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &x.product));
  FSI_TRY(MatProductClear(x.product));
  FSI_TRY(MatDestroy(&x.up));
  std::vector<Term> terms{{k.D, 1.0}, {x.product, -1.0}};  // S = D − B diag(A_u)⁻¹ Bᵀ
  if (M) terms.push_back({M, -1.0});                        // − M_w
  return sum_of(std::move(terms), S);
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

FieldVectors::~FieldVectors() {
  VecDestroy(&a_u), VecDestroy(&a_p), VecDestroy(&b_u), VecDestroy(&b_p);
  VecScatterDestroy(&to_u), VecScatterDestroy(&to_p);
}

}  // namespace fsi
