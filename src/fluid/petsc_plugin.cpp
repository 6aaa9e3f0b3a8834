// libfsicontact_petsc.so: the fluid's linear systems through PETSc (petsc_plugin.hpp).
//
// "petsc-mumps": KSPPREONLY with MUMPS's LU (LDLᵀ when symmetric), PETSc's interface
// to the same library the default path calls directly, so that it can run on several
// ranks. "petsc-iterative": GMRES or BiCGStab, right-preconditioned (so that the
// tolerance is on the true residual ‖b − A x‖ / ‖b‖), by the upper block factorisation
// of the saddle point [A Bᵀ; B −C] (petsc_schur.hpp; Elman, Silvester, Wathen 2014,
// ch. 9): the velocity block, which holds the penalty (1/ε) χ M, by one V-cycle of
// hypre's BoomerAMG; the Schur complement by BoomerAMG on
// S_p = −C − B diag(A)⁻¹ Bᵀ (PETSc's "selfp"), which follows the
// penalty (where χ = 1, diag(A) ~ M/ε and S ~ ε B M⁻¹ Bᵀ, where a pressure mass
// matrix would be off by 1/ε), less the fluid's weighted pressure mass matrix when
// the caller gives it (set_pressure_mass; finish_iterative says why). S_p is built
// here from the distributed operator's blocks (petsc_blocks.hpp): a rank holds its own
// rows only, and so not the diagonal of its neighbours' velocity rows that its
// pressure rows need. The methods' defaults and PETSC_OPTIONS: petsc_ksp_defaults.hpp.
#include "fluid/petsc_plugin.hpp"

#include <petscksp.h>

#include "fluid/petsc_block_operator.hpp"
#include "fluid/petsc_blocks.hpp"
#include "fluid/petsc_field_vectors.hpp"
#include "fluid/petsc_ksp_defaults.hpp"
#include "fluid/petsc_schur.hpp"
#include "fluid/petsc_try.hpp"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <string>

namespace fsi {
namespace {

// The first message of the last error (PETSc's own words: what, where), recorded by
// the error handler; PETSc then returns the code up the stack, printing nothing.
std::string last_message;

PetscErrorCode record_error(MPI_Comm, int, const char* function, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL)
    last_message = std::string(message ? message : "") + " (in " + function + ")";
  return code;
}

}  // namespace

std::string petsc_error_text(PetscErrorCode code, const char* call) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::string out =
      std::string("PETSc: ") + call + ": " + (text ? text : "error " + std::to_string(code));
  if (!last_message.empty()) out += ": " + last_message;
  last_message.clear();
  return out;
}

namespace {

// Every rank owns a contiguous block of the rows, PETSc's even split (row_block):
// [first, last) of the unknowns, and of the pressure's unknowns (the Schur
// preconditioner's rows) [p_first, p_last); it is given those rows alone
// (petsc_plugin.hpp).
struct Solver {
  PetscSolverConfig config;
  PetscInt n = -1, first = 0, last = 0, p_first = 0, p_last = 0;
  Mat A = nullptr;     // the operator as given (direct; the iterative solver splits it)
  KBlocks blocks;      // iterative, between set_operator and finish_set_up (petsc_blocks.hpp)
  Mat op = nullptr;    // iterative: the operator by its blocks (petsc_block_operator.hpp)
  PetscCsr borrowed;  // the caller's arrays A uses in place, if it does (borrowed.borrowed)
  Mat M = nullptr;  // the pressure mass matrix M_w, if given
  Vec b = nullptr, x = nullptr;
  Vec all = nullptr;  // x gathered on every rank, on several ranks (x itself on one)
  VecScatter to_all = nullptr;
  KSP ksp = nullptr;
  bool set_up_once = false;  // since ksp was made
  IS fields[2] = {nullptr, nullptr};
  std::vector<PetscReal> history;
};

void row_block(int n, int& first, int& last) {
  PetscMPIInt rank = 0, ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const int base = n / ranks, extra = n % ranks;
  first = rank * base + std::min(rank, extra);
  last = first + base + (rank < extra ? 1 : 0);
}

std::string sum_over_ranks(double* values, int count) {
  FSI_TRY(MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD)
              ? PETSC_ERR_MPI
              : 0);
  return "";
}

int largest_over_ranks(int local) {
  int largest = local;
  if (MPI_Allreduce(&local, &largest, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD) != MPI_SUCCESS)
    return SIGTERM;  // a failed exchange stops the run
  return largest;
}

std::string set_layout(Solver& s, PetscInt n) {
  if (s.n == n) return "";
  if (s.n >= 0)
    return "the operator's size changed from " + std::to_string(s.n) + " to " + std::to_string(n);
  int first = 0, last = 0;
  row_block(n, first, last);
  s.n = n, s.first = first, s.last = last;
  const auto& p = s.config.is_pressure;
  if (!p.empty()) {
    s.p_first = static_cast<PetscInt>(std::count(p.begin(), p.begin() + s.first, 1));
    s.p_last =
        s.p_first + static_cast<PetscInt>(std::count(p.begin() + s.first, p.begin() + s.last, 1));
  }
  return "";
}

std::string initialise(int& rank, int& ranks) {
  static std::string error = [] {
    // Before PetscInitialize: the program handles its signals itself (common/interrupt),
    // and PETSc's options left over are no one's concern at exit.
    FSI_TRY(PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr));
    FSI_TRY(PetscOptionsSetValue(nullptr, "-options_left", "no"));
    FSI_TRY(PetscInitializeNoArguments());
    FSI_TRY(PetscPushErrorHandler(record_error, nullptr));
    std::atexit([] { PetscFinalize(); });
    return std::string();
  }();
  if (!error.empty()) return error;
  FSI_TRY(MPI_Comm_rank(PETSC_COMM_WORLD, &rank) ? PETSC_ERR_MPI : 0);
  FSI_TRY(MPI_Comm_size(PETSC_COMM_WORLD, &ranks) ? PETSC_ERR_MPI : 0);
  return "";
}

// The velocity's and the pressure's unknowns as index sets, this rank's rows of each.
std::string split_fields(Solver& s) {
  const auto& p = s.config.is_pressure;
  if (std::count(p.begin(), p.end(), 1) == 0 || std::count(p.begin(), p.end(), 0) == 0)
    return "the Schur preconditioner needs velocity and pressure unknowns";
  if (std::string e = set_layout(s, static_cast<PetscInt>(p.size())); !e.empty()) return e;
  std::vector<PetscInt> index[2];
  for (PetscInt i = s.first; i < s.last; ++i)
    index[p[static_cast<std::size_t>(i)] ? 1 : 0].push_back(i);
  for (int f = 0; f < 2; ++f)
    FSI_TRY(ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(index[f].size()),
                            index[f].data(), PETSC_COPY_VALUES, &s.fields[f]));
  return "";
}

void destroy(void* handle) {
  auto* s = static_cast<Solver*>(handle);
  if (!s) return;
  KSPDestroy(&s->ksp);
  MatDestroy(&s->A);
  s->blocks.free();
  MatDestroy(&s->op);
  MatDestroy(&s->M);
  VecDestroy(&s->b);
  VecDestroy(&s->x);
  VecDestroy(&s->all);
  VecScatterDestroy(&s->to_all);
  ISDestroy(&s->fields[0]);
  ISDestroy(&s->fields[1]);
  delete s;
}

std::string make_ksp(Solver& s) {
  FSI_TRY(KSPCreate(PETSC_COMM_WORLD, &s.ksp));
  FSI_TRY(KSPSetOptionsPrefix(s.ksp, s.config.iterative ? "fluid_" : "fluid_direct_"));
  const std::string e =
      s.config.iterative ? set_iterative(s.ksp, s.config.krylov) : set_direct(s.ksp, s.config.symmetric);
  if (!e.empty()) return e;
  FSI_TRY(KSPSetTolerances(s.ksp, s.config.tol, 0.0, 1e30, s.config.max_iterations));
  s.history.resize(static_cast<std::size_t>(s.config.max_iterations) + 1);
  FSI_TRY(KSPSetResidualHistory(s.ksp, s.history.data(), static_cast<PetscInt>(s.history.size()),
                                PETSC_TRUE));
  FSI_TRY(KSPSetFromOptions(s.ksp));
  return "";
}

void* create(const PetscSolverConfig& config, std::string& error) {
  auto* s = new Solver;
  s->config = config;
  error = make_ksp(*s);
  if (error.empty() && s->config.iterative) error = split_fields(*s);
  if (error.empty()) return s;
  destroy(s);
  return nullptr;
}

// "" if m (PetscCsr or PetscColumns) holds this rank's rows [first, last), else the error.
template <class Rows>
std::string wrong_rows(const Rows& m, PetscInt first, PetscInt last) {
  if (m.first == first && m.last == last) return "";
  return "rows [" + std::to_string(m.first) + ", " + std::to_string(m.last) + ") given, this rank's are [" +
         std::to_string(first) + ", " + std::to_string(last) + ")";
}

// A new matrix holding m, this rank's rows [first, last) of an n × n matrix (its
// pattern and values): sequential on one rank, distributed on several.
std::string matrix_from(const PetscCsr& m, PetscInt first, PetscInt last, Mat& out) {
  if (std::string e = wrong_rows(m, first, last); !e.empty()) return e;
  static_assert(sizeof(PetscInt) == sizeof(int), "PetscCsr's indices are PETSc's");
  FSI_TRY(MatCreate(PETSC_COMM_WORLD, &out));
  FSI_TRY(MatSetSizes(out, last - first, last - first, m.n, m.n));
  FSI_TRY(MatSetType(out, MATAIJ));
  // Each call does nothing on the other type's matrix.
  FSI_TRY(MatSeqAIJSetPreallocationCSR(out, m.row_start, m.column, m.value));
  FSI_TRY(MatMPIAIJSetPreallocationCSR(out, m.row_start, m.column, m.value));
  return "";
}

// The iterative solver's next set-up starts from nothing: its Krylov method and
// preconditioner (blocks, hierarchies) made anew, the last ones freed first. Reused,
// the split's copies of the blocks and both hierarchies stayed alive while the next
// S_p and its scratch were built: a run's later passes peaked 0.72 kB a triangle above
// its first (2 930 against 2 260 MB at 930 681 triangles; docs/performance.md, "The
// memory a triangle, continued"). The blocks and BoomerAMG's hierarchies are built
// anew at each set-up either way.
std::string release_preconditioner(Solver& s) {
  if (!s.config.iterative) return "";
  s.blocks.free();
  FSI_TRY(MatDestroy(&s.op));
  if (!s.set_up_once) return "";
  s.set_up_once = false;
  FSI_TRY(KSPDestroy(&s.ksp));
  return make_ksp(s);
}

// A new matrix each time (its pattern is fixed, but its set-up is small beside the
// multigrid's that follows).
std::string set_pressure_mass(void* handle, const PetscCsr& m) {
  auto& s = *static_cast<Solver*>(handle);
  if (std::string e = release_preconditioner(s); !e.empty()) return e;
  FSI_TRY(MatDestroy(&s.M));
  return matrix_from(m, s.p_first, s.p_last, s.M);
}

bool one_rank() {
  PetscMPIInt ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  return ranks == 1;
}

// Iterative: K's blocks made straight from this rank's rows m (split_blocks or
// split_columns), never K itself; the caller's arrays are not read once this returns.
// B is Bᵀ's transpose where K is its own transpose, which is known where the caller
// lends K (m.borrowed, checked by PetscSolver; one rank); a block of its own otherwise.
template <class Rows, class Split>
std::string split_operator(Solver& s, const Rows& m, Split split) {
  if (std::string e = release_preconditioner(s); !e.empty()) return e;
  if (std::string e = set_layout(s, m.n); !e.empty()) return e;
  if (std::string e = wrong_rows(m, s.first, s.last); !e.empty()) return e;
  if (!s.x) {
    FSI_TRY(VecCreateMPI(PETSC_COMM_WORLD, s.last - s.first, s.n, &s.x));
    FSI_TRY(VecDuplicate(s.x, &s.b));
    if (s.last - s.first < s.n) FSI_TRY(VecScatterCreateToAll(s.x, &s.to_all, &s.all));
  }
  if (std::string e = split(); !e.empty()) return e;
  if (s.config.symmetric)  // K's diagonal blocks are then symmetric too
    for (Mat block : {s.blocks.A_u, s.blocks.D}) {
      FSI_TRY(MatSetOption(block, MAT_SYMMETRIC, PETSC_TRUE));
      FSI_TRY(MatSetOption(block, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    }
  return "";
}

std::string set_operator_columns(void* handle, const PetscColumns& m) {
  auto& s = *static_cast<Solver*>(handle);
  if (!s.config.iterative) return "the operator by columns is the iterative solver's only";
  return split_operator(s, m, [&] { return split_columns(m, s.config.is_pressure, s.blocks); });
}

// S_p = D − B diag(A_u)⁻¹ Bᵀ − M_w for K = [A_u Bᵀ; B D] split by the fields (D = −C,
// so S_p, like the Schur complement, is negative definite; petsc_blocks.hpp's
// schur_matrix): PETSc's "selfp", which follows the penalty (diag(A_u) holds (1/ε)χM),
// less the fluid's pressure mass matrix M_w (w = (1 − χ)/μ), the Stokes Schur
// complement's spectral equivalent where χ = 0, which selfp underestimates on smooth
// pressures by ~h² (measured: 466 GMRES iterations at h = 0.005 on the §7.2 box with
// selfp alone, 61–71 with M_w from h = 0.02 to 0.0025; docs/performance.md "PETSc").
// The rest of the iterative set-up, from the blocks taken: S_p, the preconditioner's
// hierarchies, and the operator by its blocks, which the Krylov method multiplies by.
std::string finish_iterative(Solver& s) {
  KBlocks& k = s.blocks;
  Mat S = nullptr;
  PC pc = nullptr;
  std::shared_ptr<FieldVectors> v;  // the preconditioner's and the operator's work space
  std::string e = schur_matrix(k, s.M, S);
  MatDestroy(&s.M);  // in S_p now; the next set-up is given its own
  if (e.empty() && KSPGetPC(s.ksp, &pc)) e = "PETSc: KSPGetPC failed";
  if (e.empty()) e = make_field_vectors(s.x, s.fields[0], s.fields[1], v);
  if (e.empty()) e = set_schur_factorisation(pc, k.A_u, S, k.Bt, v);
  MatDestroy(&S);  // taken, unless an error came first
  if (e.empty()) e = make_block_operator(k, v, s.x, s.op);
  k.free();  // the preconditioner and the operator hold them
  if (!e.empty()) return e;
  FSI_TRY(KSPSetOperators(s.ksp, s.op, s.op));
  return "";
}

// On one rank, the caller's arrays as A's own (PETSc only reads them): no copy of the
// operator, 12 bytes a nonzero, 0.38 kB a triangle (docs/performance.md, "The memory a
// triangle").
std::string borrowed_matrix(Solver& s, const PetscCsr& m) {
  if (m.first != 0 || m.last != m.n) return "a borrowed operator must hold every row";
  FSI_TRY(MatCreateSeqAIJWithArrays(PETSC_COMM_WORLD, m.n, m.n, const_cast<PetscInt*>(m.row_start),
                                    const_cast<PetscInt*>(m.column), const_cast<PetscScalar*>(m.value),
                                    &s.A));
  s.borrowed = m;
  return "";
}

// A, from m: borrowed (one rank, m.borrowed) or copied.
std::string make_operator(Solver& s, const PetscCsr& m) {
  s.borrowed = {};
  const bool borrow = m.borrowed && one_rank();
  if (std::string e = borrow ? borrowed_matrix(s, m) : matrix_from(m, s.first, s.last, s.A); !e.empty())
    return e;
  if (s.config.symmetric) {
    FSI_TRY(MatSetOption(s.A, MAT_SYMMETRIC, PETSC_TRUE));
    FSI_TRY(MatSetOption(s.A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  }
  return "";
}

std::string first_operator(Solver& s, const PetscCsr& m) {
  if (std::string e = set_layout(s, m.n); !e.empty()) return e;
  if (std::string e = make_operator(s, m); !e.empty()) return e;
  FSI_TRY(MatCreateVecs(s.A, &s.x, &s.b));
  if (s.last - s.first < s.n) FSI_TRY(VecScatterCreateToAll(s.x, &s.to_all, &s.all));
  return "";
}

// This rank's rows' values, on the pattern fixed by the first call.
std::string update_values(Solver& s, const PetscCsr& m) {
  if (m.first != s.first || m.last != s.last)
    return "the operator's rows given are not this rank's";
  for (PetscInt r = s.first; r < s.last; ++r) {
    const int begin = m.row_start[r - s.first];
    FSI_TRY(MatSetValues(s.A, 1, &r, m.row_start[r - s.first + 1] - begin, m.column + begin,
                         m.value + begin, INSERT_VALUES));
  }
  FSI_TRY(MatAssemblyBegin(s.A, MAT_FINAL_ASSEMBLY));
  FSI_TRY(MatAssemblyEnd(s.A, MAT_FINAL_ASSEMBLY));
  return "";
}

// Whether m is a matrix other than the one A holds in place (or does not: copied).
bool other_arrays(const Solver& s, const PetscCsr& m) {
  if (!(m.borrowed && one_rank())) return s.borrowed.borrowed;
  return !s.borrowed.borrowed || m.row_start != s.borrowed.row_start || m.column != s.borrowed.column ||
         m.value != s.borrowed.value;
}

// The values on the pattern fixed by the first call: copied into A; or, borrowed, already
// in place, A's state moved on (MatAssemblyEnd) so that the preconditioner or the
// factorisation is redone and the diagonal PETSc caches forgotten. Other arrays (another
// matrix of the pattern, or a change between borrowed and copied) make a new A.
std::string set_operator(void* handle, const PetscCsr& m) {
  auto& s = *static_cast<Solver*>(handle);
  if (s.config.iterative)
    return split_operator(s, m, [&] {
      return split_blocks(m, s.config.is_pressure, m.borrowed && one_rank(), s.blocks);
    });
  if (std::string e = release_preconditioner(s); !e.empty()) return e;
  if (!s.x) return first_operator(s, m);
  if (m.n != s.n)
    return "the operator's size changed from " + std::to_string(s.n) + " to " + std::to_string(m.n);
  if (!s.A || other_arrays(s, m)) {
    FSI_TRY(MatDestroy(&s.A));
    return make_operator(s, m);
  }
  if (!s.borrowed.borrowed) return update_values(s, m);
  FSI_TRY(MatAssemblyBegin(s.A, MAT_FINAL_ASSEMBLY));
  FSI_TRY(MatAssemblyEnd(s.A, MAT_FINAL_ASSEMBLY));
  return "";
}

// The KSP's set-up (the factorisation, or the preconditioner's) and its check.
std::string set_up_ksp(Solver& s) {
  FSI_TRY(KSPSetUp(s.ksp));
  PC pc;
  FSI_TRY(KSPGetPC(s.ksp, &pc));
  PCFailedReason failed = PC_NOERROR;
  FSI_TRY(PCGetFailedReason(pc, &failed));
  if (failed != PC_NOERROR)
    return std::string("PETSc: the ") +
           (s.config.iterative ? "preconditioner's set-up" : "factorisation") +
           " failed: " + PCFailedReasons[failed];
  s.set_up_once = true;
  return "";
}

// Direct: the factorisation. Iterative: nothing more (set_operator split K into its
// blocks); finish_set_up does the rest (or the next solve, if the caller does not).
std::string set_up(void* handle) {
  auto& s = *static_cast<Solver*>(handle);
  if (s.config.iterative) return s.blocks.taken() ? "" : "set_up() before set_operator()";
  if (!s.A) return "set_up() before set_operator()";
  FSI_TRY(KSPSetOperators(s.ksp, s.A, s.A));
  return set_up_ksp(s);
}

std::string finish_set_up(void* handle) {
  auto& s = *static_cast<Solver*>(handle);
  if (!s.blocks.taken()) return "";  // direct, or done
  if (std::string e = finish_iterative(s); !e.empty()) return e;
  return set_up_ksp(s);
}

// ‖b − K x‖ / ‖b‖ for the iterative solution in s.x (one product, with the operator by
// blocks the Krylov method used): the solve's accuracy, which the caller, who freed K,
// checks. The direct solver's caller keeps K and computes it itself.
std::string true_residual(Solver& s, PetscReal bnorm, double& residual) {
  PetscReal rnorm = 0;
  if (std::string e = block_residual_norm(s.op, s.x, s.b, rnorm); !e.empty()) return e;
  residual = bnorm > 0 ? rnorm / bnorm : rnorm;
  return "";
}

// This rank's part of b and of the first iterate in; the whole solution out, on
// every rank.
std::string solve(void* handle, const double* b, double* x, bool warm, PetscSolveReport& report) {
  auto& s = *static_cast<Solver*>(handle);
  if (std::string e = finish_set_up(handle); !e.empty()) return e;
  if (!s.set_up_once) return "solve() before set_up()";
  PetscScalar* v = nullptr;
  FSI_TRY(VecGetArray(s.b, &v));
  std::copy(b + s.first, b + s.last, v);
  FSI_TRY(VecRestoreArray(s.b, &v));
  FSI_TRY(VecGetArray(s.x, &v));
  std::copy(x + s.first, x + s.last, v);
  FSI_TRY(VecRestoreArray(s.x, &v));
  FSI_TRY(KSPSetInitialGuessNonzero(s.ksp, warm && s.config.iterative ? PETSC_TRUE : PETSC_FALSE));
  FSI_TRY(KSPSolve(s.ksp, s.b, s.x));
  KSPConvergedReason reason;
  FSI_TRY(KSPGetConvergedReason(s.ksp, &reason));
  FSI_TRY(KSPGetIterationNumber(s.ksp, &report.iterations));
  report.reason = KSPConvergedReasons[reason];
  PetscReal bnorm = 0;
  FSI_TRY(VecNorm(s.b, NORM_2, &bnorm));
  const PetscReal* h = nullptr;
  PetscInt count = 0;
  FSI_TRY(KSPGetResidualHistory(s.ksp, &h, &count));
  report.history.clear();
  for (PetscInt k = 0; k < count; ++k) report.history.push_back(bnorm > 0 ? h[k] / bnorm : h[k]);
  if (s.config.iterative)
    if (std::string e = true_residual(s, bnorm, report.residual); !e.empty()) return e;
  if (reason < 0) return "PETSc: the solve did not converge (" + report.reason + ")";
  if (s.to_all) {
    FSI_TRY(VecScatterBegin(s.to_all, s.x, s.all, INSERT_VALUES, SCATTER_FORWARD));
    FSI_TRY(VecScatterEnd(s.to_all, s.x, s.all, INSERT_VALUES, SCATTER_FORWARD));
  }
  Vec whole = s.to_all ? s.all : s.x;
  FSI_TRY(VecGetArray(whole, &v));
  std::copy(v, v + s.n, x);
  FSI_TRY(VecRestoreArray(whole, &v));
  return "";
}

// M_w too, if no set-up took it: it was given for one (set_pressure_mass).
std::string release(void* handle) {
  auto& s = *static_cast<Solver*>(handle);
  FSI_TRY(MatDestroy(&s.M));
  return release_preconditioner(s);
}

const PetscPlugin kPlugin = {kPetscPluginVersion, initialise,        row_block,    sum_over_ranks,
                             largest_over_ranks,  create,            set_operator, set_operator_columns,
                             set_up,              finish_set_up,     set_pressure_mass, solve,
                             destroy,             release};

}  // namespace
}  // namespace fsi

extern "C" __attribute__((visibility("default"))) const fsi::PetscPlugin*
fsicontact_petsc_plugin() {
  return &fsi::kPlugin;
}
