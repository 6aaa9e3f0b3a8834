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
// field, [start, end). Rows and columns in PETSc's numbering.
struct FieldView {
  int n, first, last;  // this rank's rows [first, last) of n
  const std::vector<char>& is_pressure;
  std::vector<PetscInt> number;
  PetscInt start[2] = {0, 0}, end[2] = {0, 0};
  FieldView(int size, int first_row, int end_row, const std::vector<char>& pressure);
  int field(int i) const { return is_pressure[static_cast<std::size_t>(i)] ? 1 : 0; }
  bool here(int i) const { return i >= first && i < last; }  // a row of this rank's
  PetscInt rows(int f) const { return end[f] - start[f]; }
  bool whole() const { return last - first == n; }
  // Row i's number in its field's blocks, from 0 on this rank.
  std::size_t row_in_block(int i) const {
    return static_cast<std::size_t>(number[static_cast<std::size_t>(i)] - start[field(i)]);
  }
};

FieldView::FieldView(int size, int first_row, int end_row, const std::vector<char>& pressure)
    : n(size), first(first_row), last(end_row), is_pressure(pressure), number(pressure.size()) {
  PetscInt count[2] = {0, 0};
  for (std::size_t i = 0; i < number.size(); ++i) number[i] = count[field(static_cast<int>(i))]++;
  for (int i = 0; i < last; ++i) ++(i < first ? start : end)[field(i)];
  for (int f = 0; f < 2; ++f) end[f] += start[f];
}

// Block (r, c)'s entries in each of its rows: in columns on this rank (PETSc's
// "diagonal" part) and elsewhere, for an exact preallocation.
struct BlockShape {
  std::vector<PetscInt> local, other;
};

using Shapes = std::array<std::array<BlockShape, 2>, 2>;

Shapes empty_shapes(const FieldView& v) {
  Shapes shape;
  for (int r = 0; r < 2; ++r)
    for (auto& s : shape[static_cast<std::size_t>(r)])
      s.local.assign(static_cast<std::size_t>(v.rows(r)), 0), s.other = s.local;
  return shape;
}

// Entry (i, j) of this rank's rows counted in its block's row.
void count_entry(const FieldView& v, Shapes& shape, int i, int j) {
  BlockShape& s = shape[static_cast<std::size_t>(v.field(i))][static_cast<std::size_t>(v.field(j))];
  ++(v.here(j) ? s.local : s.other)[v.row_in_block(i)];
}

Shapes block_shapes(const FieldView& v, const PetscCsr& m) {
  Shapes shape = empty_shapes(v);
  for (int i = m.first; i < m.last; ++i)
    for (int k = m.row_start[i - m.first]; k < m.row_start[i - m.first + 1]; ++k)
      count_entry(v, shape, i, m.column[k]);
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
void fill_blocks(const FieldView& v, const PetscCsr& m, int r, const std::array<BlockArrays*, 2>& out) {
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
  return matrix_on(v.rows(r), v.rows(c), v.whole(), std::move(arrays), out);
}

}  // namespace

// One pass over the rows counts each block's entries a row; a pass a field fills its
// blocks. On several ranks this replaced K's own copy in PETSc and four
// MatCreateSubMatrix (docs/performance.md, "Huge pages, and the set-up on two ranks").
std::string split_blocks(const PetscCsr& m, const std::vector<char>& is_pressure, bool own_transpose,
                         KBlocks& out) {
  const FieldView v(m.n, m.first, m.last, is_pressure);
  const Shapes shape = block_shapes(v, m);
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
    fill_blocks(v, m, r, {arrays[0].get(), arrays[1].get()});
    for (int c = 0; c < 2; ++c)
      if (block[r][c])
        if (std::string e = make_block(v, r, c, std::move(arrays[static_cast<std::size_t>(c)]), *block[r][c]);
            !e.empty())
          return e;
  }
  return "";
}

namespace {

// f(i, j, value) for each entry of this rank's rows held by m, numbered as PETSc's:
// in m's order (by_new_columns false), or column by column in PETSc's order, so that
// each row's entries come with their columns sorted.
template <class F>
void for_each_entry(const PetscColumns& m, bool by_new_columns, F&& f) {
  for (int c = 0; c < m.n; ++c) {
    const int j = by_new_columns ? m.from[c] : c;
    for (int k = m.column_start[j]; k < m.column_start[j + 1]; ++k) {
      const int i = m.to[m.row[k]];
      if (i >= m.first && i < m.last) f(i, m.to[j], m.value[k]);
    }
  }
}

// A block's arrays, sized by its shape, and where each of its rows is filled next.
struct BlockFill {
  std::unique_ptr<BlockArrays> arrays = std::make_unique<BlockArrays>();
  std::vector<PetscInt> next, other_next;
  explicit BlockFill(const BlockShape& s) {
    BlockArrays& b = *arrays;
    b.i = row_starts(s.local), b.oi = row_starts(s.other);
    b.j.resize(static_cast<std::size_t>(b.i.back())), b.a.resize(b.j.size());
    b.oj.resize(static_cast<std::size_t>(b.oi.back())), b.oa.resize(b.oj.size());
    next.assign(b.i.begin(), b.i.end() - 1), other_next.assign(b.oi.begin(), b.oi.end() - 1);
  }
  void add(const FieldView& v, std::size_t row, int j, PetscScalar value) {
    BlockArrays& b = *arrays;
    const PetscInt number = v.number[static_cast<std::size_t>(j)];
    if (v.here(j)) {
      const auto at = static_cast<std::size_t>(next[row]++);
      b.j[at] = number - v.start[v.field(j)], b.a[at] = value;
    } else {
      const auto at = static_cast<std::size_t>(other_next[row]++);
      b.oj[at] = number, b.oa[at] = value;
    }
  }
};

}  // namespace

// One pass in m's order counts each block's entries a row; one in PETSc's order of the
// columns fills the four blocks. On several ranks this replaced a copy of this rank's
// rows in PETSc's order (petsc_solver.cpp's ordered_rows) and two passes over it
// (docs/performance.md, "Each rank's unknowns in the assembler's order, and the split from
// the columns").
std::string split_columns(const PetscColumns& m, const std::vector<char>& is_pressure, KBlocks& out) {
  const FieldView v(m.n, m.first, m.last, is_pressure);
  Shapes shape = empty_shapes(v);
  for_each_entry(m, false, [&](int i, int j, double) { count_entry(v, shape, i, j); });
  std::vector<BlockFill> fill;  // block (r, c) at 2 r + c
  for (const auto& row_field : shape)
    for (const BlockShape& s : row_field) fill.emplace_back(s);
  for_each_entry(m, true, [&](int i, int j, double value) {
    fill[static_cast<std::size_t>(2 * v.field(i) + v.field(j))].add(v, v.row_in_block(i), j, value);
  });
  Mat* const block[4] = {&out.A_u, &out.Bt, &out.B, &out.D};
  for (std::size_t b = 0; b < 4; ++b)
    if (std::string e = make_block(v, static_cast<int>(b / 2), static_cast<int>(b % 2), std::move(fill[b].arrays),
                                   *block[b]);
        !e.empty())
      return e;
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

}  // namespace fsi
