// What the penalised and the body-fitted runs share (run/penalised_problem.hpp,
// run/body_fitted_problem.cpp): the case, the structure's set-up, the coupling's
// result and the deformed structure; and the steps by which a coupled kind (SPEC §5)
// and the fluid alone around the structure at rest (SPEC §3) differ.
#pragma once

#include <string>

#include "coupling/coupling_result.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/run_case.hpp"
#include "run/setup_cache.hpp"
#include "run/structure_setup.hpp"

namespace fsi {

class FluidStructureProblem : public Problem {
 public:
  FluidStructureProblem(const Case& c, const RunOptions& options)
      : c_(c), options_(options), cache_(options.cache ? *options.cache : local_cache_) {}
  const char* kind() const override { return "fsi"; }

 protected:
  // The structure's part of each step: a coupled kind's stop and contact, its summary
  // keys and files (history.csv, structure.vtu and .png); none at rest.
  virtual void measure_structure(RunMeasures& m) = 0;
  virtual void summarise_structure(Json& j, const RunMeasures& m) = 0;
  virtual void write_structure(RunOutputs& out, bool fluid_vtu_written) = 0;
  virtual std::string report(const RunMeasures& m) const = 0;
  virtual const char* picture_name() const = 0;   // fsi.png, or fluid.png at rest
  virtual std::string picture_state() const = 0;  // the picture's note: how the run ended

  // The final state's ũ measured (the solution if converged, after a failure the last
  // good one): deformed_, and in r the displacement, the status and the exit status
  // (r.measures from coupled_measures, its meshes and the structure's part set).
  void measure_final_state(RunResult& r, const MeshStatistics& fluid_mesh);
  // A coupled kind's parts: the loop's stop and ũ's contact; its summary keys
  // (add_coupled_structure); "N iterations" for the picture's note.
  void measure_coupled_structure(RunMeasures& m) const;
  void summarise_coupled_structure(Json& j, const RunMeasures& m) const;
  std::string passes_note() const;

  const Case& c_;
  const RunOptions& options_;
  SetupCache local_cache_;
  SetupCache& cache_;
  StructureSetup* s_ = nullptr;
  MeshStatistics s_stats_;
  CouplingResult result_;
  Mesh deformed_;
};

}  // namespace fsi
