// The discrete penalised Stokes problem of the mini element (paper eqs. 25–26, SPEC
// §3) on the free dofs: the prescribed velocities, the condensed element of each
// triangle for a penalty κ = χ/ε, the assembled K and rhs (updated only where χ
// changed), and the fields from a solution vector. How K x = rhs is solved is not
// its business: that is a StokesSolveStrategy's (stokes_strategy.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <vector>

#include "fem/integration.hpp"  // TriangleRule
#include "fem/vector_p1.hpp"  // VectorField
#include "fluid/mini_element.hpp"
#include "fluid/region_schur.hpp"
#include "mesh/mesh.hpp"

namespace fsi {

struct FluidBoundaryConditions {
  std::vector<int> dirichlet_labels;                 // velocity prescribed here
  VectorField g = [](const Point&) { return Point(0, 0); };  // its value
  // A value of its own on some of those labels (the inflow on Σ4): boundary
  // conditions belong to labels, never to coordinates. At a vertex on two labels the
  // later label in dirichlet_labels decides.
  std::vector<std::pair<int, VectorField>> dirichlet_values;
  std::vector<std::pair<int, VectorField>> tractions;  // σ n = h on these labels
};

// The discrete fluid state: P1 parts at the vertices, bubble coefficients per triangle.
struct FluidSolution {
  Eigen::VectorXd v1, v2, p;
  Eigen::Matrix2Xd bubble;
  // Null: the fields are the solution everywhere. Otherwise only on the triangles t
  // with (*exact_on)[t] (a solve that deferred the far field, SubstructuredSolve);
  // FluidField refuses to evaluate elsewhere (FieldNotComputed).
  const std::vector<char>* exact_on = nullptr;
};

// A state's 8 velocity coefficients on triangle t in the mini space's basis order
// (v1 at its 3 vertices, v2 at the 3, then the bubble's 2): what a term that depends
// on a velocity (convection, the time derivative's history) reads.
inline Eigen::Matrix<double, 8, 1> velocity_coefficients(const Mesh& mesh, const FluidSolution& s, int t) {
  Eigen::Matrix<double, 8, 1> c;
  const auto& tri = mesh.triangles[t];
  for (int a = 0; a < 3; ++a) c[a] = s.v1[tri[a]], c[3 + a] = s.v2[tri[a]];
  c[6] = s.bubble(0, t), c[7] = s.bubble(1, t);
  return c;
}

// Local dof k (0..8 = v1×3, v2×3, p×3) of triangle `tri` → full dof index.
inline int fluid_dof(const std::array<int, 3>& tri, int k, int nv) {
  return (k / 3) * nv + tri[k % 3];
}

class StokesAssembler {
 public:
  // order_now: start order_in_background() before the set-up (the substructured
  // solve needs the order; it then overlaps this constructor too).
  StokesAssembler(const Mesh& mesh, double mu, const VectorField& f,
                  const FluidBoundaryConditions& bc, bool order_now = false);

  const Mesh& mesh() const { return mesh_; }
  double mu() const { return mu_; }
  // The viscous term's form (SPEC §10 fluid.viscous_form; symmetric by default); the
  // next assemble() assembles everything.
  void set_viscous_form(ViscousForm form);
  ViscousForm viscous_form() const { return form_; }
  // A new body force f (its element loads); the next assemble() assembles everything.
  void set_body_force(const VectorField& f);
  // Whether the element loads are kept (the default) or computed when needed, the
  // same values a few hundred flops later (a solver that frees K: WholeSolve; 96 bytes
  // a triangle, issue 32's memory budget).
  void keep_element_loads(bool keep);
  // New boundary data on the same labels: the prescribed velocities' values and the
  // tractions (an inflow or a load that changes in time, SPEC §12); the next assemble()
  // assembles everything. std::invalid_argument if another set of dofs is prescribed.
  void set_boundary_data(const FluidBoundaryConditions& bc);
  // A further term of every element (mini_element.hpp ElementTerm: convection); the
  // next assemble() assembles everything. A term whose data change (a new velocity to
  // linearise about) needs forget_assembly() before the next assemble(): the update
  // of the triangles whose χ changed assumes nothing else did.
  void add_term(std::shared_ptr<const ElementTerm> term);
  // Whether K is symmetric (every term is): the solver paths that need it refuse
  // otherwise (PenalisedStokes::solve).
  bool symmetric() const { return symmetric_; }
  int unknowns() const { return static_cast<int>(free_.size()); }
  // Per unknown, 1 for a pressure's (the saddle point's second field).
  std::vector<char> pressure_unknowns() const;
  // The P1 pressure mass matrix Σ_T w_T ∫_T p q on the pressure unknowns, in their
  // order among all unknowns (one weight per triangle): the rows held (share_rows).
  Eigen::SparseMatrix<double> pressure_mass(const Eigen::VectorXd& weight) const;
  long nonzeros() const { return nonzeros_; }  // of the whole K (built only if needed)

  // K and rhs for χ and ε over all triangles.
  void assemble_full(const Eigen::VectorXd& chi, double eps);
  // The same, re-assembling only the triangles whose χ changed since the last call
  // (see the definition for when it assembles all of them instead).
  void assemble(const Eigen::VectorXd& chi, double eps);
  // The next assemble() assembles every triangle (a new run: its numbers must not
  // depend on the round-off of the last run's updates).
  void forget_assembly() { assembled_ = false; }
  // For a solver that holds its own blocks of K (SparseDirectSolver::
  // detaches_from_operator): K's assembly offsets freed once K is assembled (0.16 kB a
  // triangle), then K (0.38 kB) once the solver holds its blocks. matrix() is then
  // empty, and the next assemble() builds the pattern anew and assembles every triangle.
  void release_offsets();
  void release_matrix();
  // From now on K and rhs hold only the rows of the unknowns k with here[k] (one MPI
  // rank's share, SparseDirectSolver::rows_here), the other rows empty and zero: only
  // the triangles that touch one of them are visited, and K stores their pattern
  // alone. Empty: all the rows. std::invalid_argument unless one flag per unknown.
  void share_rows(std::vector<char> here);
  // The triangles an assembly visits: all, or those of this rank's share.
  int triangles_here() const;
  const Eigen::SparseMatrix<double>& matrix() const { return K_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

  // Triangle t's unknowns (−1 where prescribed) and its condensed element for the
  // penalty κ = χ_t/ε, prescribed columns lifted to the load.
  std::array<int, 9> element_dofs(int t) const;
  ElementSystem element_system(int t, double kappa) const;
  const Eigen::VectorXd& traction_load() const { return traction_load_; }  // ∫ h·w

  // The fields of the reduced solution x computed with χ and ε, everywhere; with a
  // range of triangles [first, last), the bubbles recovered there alone, zero elsewhere
  // (a rank's share, summed over the ranks by the caller: SparseDirectSolver::share).
  void fields(const Eigen::VectorXd& x, const Eigen::VectorXd& chi, double eps, FluidSolution& out) const;
  void fields(const Eigen::VectorXd& x, const Eigen::VectorXd& chi, double eps, FluidSolution& out, int first,
              int last) const;
  // The prescribed values and zero elsewhere (a solution about to be filled in part).
  void prescribed_fields(FluidSolution& out) const;
  // The reduced vector (free dofs) of a solution's vertex values.
  Eigen::VectorXd reduced(const FluidSolution& s) const;
  // Writes the reduced values x_part of unknowns `reduced[k]` into `out`.
  void scatter(const std::vector<int>& reduced, const Eigen::VectorXd& x_part, FluidSolution& out) const;
  // Triangle t's bubble coefficients from its vertex values in `out` (penalty κ).
  void recover_bubble(int t, double kappa, FluidSolution& out) const;

  // A fill-reducing order of the unknowns (position of each reduced dof), computed
  // once: METIS nested dissection of the vertex graph. order_in_background() starts
  // it on a second thread; dof_rank() waits for it (or computes it).
  void order_in_background();
  const std::vector<int>& dof_rank();
  // An order of the unknowns along a Hilbert curve through the vertices (each vertex's
  // v1, v2, p together; mesh/hilbert_order.hpp): contiguous blocks of it are compact
  // parts of the domain, one per MPI rank (SparseDirectSolver::set_locality_order; the
  // PETSc solver numbers each part's unknowns in the assembler's order again).
  std::vector<int> curve_rank() const;

 private:
  // Per unknown, its place when the vertices come in the order `vertices` (each
  // vertex's v1, v2, p in turn).
  std::vector<int> rank_of_unknowns(const std::vector<int>& vertices) const;
  static Eigen::VectorXd prescribed_values(const Mesh& mesh, const FluidBoundaryConditions& bc,
                                           std::vector<bool>& fixed);
  Eigen::VectorXd traction_load(const FluidBoundaryConditions& bc) const;
  void build_whole_pattern();
  bool holds(int row) const { return row_here_.empty() || row_here_[static_cast<std::size_t>(row)]; }
  // The k-th triangle an assembly visits (k < triangles_here()).
  int visited(int k) const { return triangles_here_.empty() ? k : triangles_here_[static_cast<std::size_t>(k)]; }
  // Triangle t's 81 positions in K_.valuePtr() (−1: a prescribed column or a row not held).
  const std::uint16_t* slots(int t) const;
  void add_element(int t, double kappa, double sign);
  // Triangle t's local system with the penalty κ: the Stokes terms and the added ones;
  // its load: the body force's and the added terms'.
  MiniLocal local(int t, double kappa) const;
  // Triangle t's area and gradients, computed when needed (a dozen flops beside the
  // element's hundreds) rather than kept: 104 bytes a triangle (issue 32's memory budget).
  P1Triangle geometry(int t) const { return P1Triangle(mesh_, t); }
  ElementLoad load(int t) const;

  const Mesh& mesh_;
  double mu_;
  ViscousForm form_ = ViscousForm::symmetric;
  VectorField f_;                      // the body force
  TriangleRule load_rule_ = triangle_rule(6);  // its elements' rule: bubble (degree 3) × smooth f
  bool keep_loads_ = true;
  std::vector<ElementLoad> loads_;     // empty unless keep_loads_
  std::vector<std::shared_ptr<const ElementTerm>> terms_;  // beyond Stokes (add_term)
  bool symmetric_ = true;
  Eigen::VectorXd z_fixed_;            // prescribed values of all 3nv dofs (0 where free)
  std::vector<int> free_index_;        // full dof → reduced index, −1 if prescribed
  std::vector<int> free_;              // reduced index → full dof
  // 81 per triangle here: the entry's offset in its column of K_ (16 bits: 162 bytes a
  // triangle less than positions, issue 32's memory budget); unused where not free–free.
  std::vector<std::uint16_t> slot_;
  // share_rows's: the rows held (empty: all), the triangles visited (all if empty),
  // and triangle t's place among them (its slots' block; −1: not visited).
  std::vector<char> row_here_;
  std::vector<int> triangles_here_, here_index_;
  long nonzeros_ = 0;
  std::vector<int> dof_rank_;
  std::future<std::vector<int>> vertex_order_;  // METIS's order of the vertices, until dof_rank()
  Eigen::VectorXd traction_load_;      // ∫ h·w on the reduced dofs
  Eigen::SparseMatrix<double> K_;
  Eigen::VectorXd rhs_;
  bool assembled_ = false;
  Eigen::VectorXd assembled_chi_;      // χ of the values now in K_ and rhs_
  double assembled_eps_ = 0;
  int updates_since_full_ = 0;
};

}  // namespace fsi
