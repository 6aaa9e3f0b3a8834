// One kind of run (SPEC §2, §3, §5, §9): the steps that run() (run/run_case.hpp) takes in
// turn, the shape of a deal.II tutorial's run(). Each kind is a type, chosen once from
// the case by make_problem (run/problem_kinds.hpp); run() owns what every kind shares: the output directory,
// the timing of each phase, failures and interruption.
//
//   make_problem(case) ─► set_up ─► solve ─► measure ─► summarise ─► write
//                          (mesh,     (the      (RunMeasures,  (summary.json's  (the files
//                          structure, coupled   exit status)   keys, report)    beside
//                          fluid)     loop)                                     summary.json)
//
// A time-dependent kind (SPEC §12) is one more type whose solve is the loop over time
// steps (each the coupling's window) and which writes as it goes: its frames and
// checkpoints reach the output directory during solve(), which run() opens for it
// after set_up (streams(), open()); a resumed run (resume()) keeps the frames up to its
// checkpoint's step there.
#pragma once

#include <memory>
#include <optional>

#include "common/timer.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"

namespace fsi {

struct RunOptions;
struct RunResult;
struct FinalFields;
class RunOutputs;

class Problem {
 public:
  virtual ~Problem() = default;
  // summary.json's "problem": "contact", "fluid" or "fsi".
  virtual const char* kind() const = 0;
  // The meshes and what the solvers build once, each timed as its phase ("mesh",
  // "structure", "fluid"). InputError (exit 2) before anything is written;
  // SolverFailure if validated input cannot be set up.
  virtual void set_up(PhaseTimes& times) = 0;
  // The solve, its phases timed. A failure with a last good state to write is kept
  // for measure(); one without (a set-up or contact-only failure) throws SolverFailure.
  virtual void solve(PhaseTimes& times) = 0;
  // r.measures, r.displacement, r.exit_status and r.failure, from the final state.
  virtual void measure(RunResult& r) = 0;
  // r.summary (summary.json's keys, SPEC §8–§11, but "timing_s") and r.report.
  virtual void summarise(RunResult& r) = 0;
  // The files beside summary.json (fields, pictures, history.csv, case.toml); a failed
  // write is recorded by `out`, not thrown.
  virtual void write(RunOutputs& out) = 0;
  // The final state's fields as arrays (run/outputs/field_arrays.hpp), what write()'s
  // structure.vtu and fluid.vtu hold, asked for after write() when
  // RunOptions::keep_fields (the Python module's Result.structure and .fluid).
  virtual void final_fields(FinalFields& /*out*/) const {}

  // Whether it writes during solve() (a time run): run() then opens the directory
  // after set_up() and calls open() before solve().
  virtual bool streams() const { return false; }
  virtual void open(RunOutputs& /*out*/) {}
  // --resume: continue from `k`, a checkpoint of this case and kind
  // (run/time_checkpoint.hpp); before set_up(). Only time kinds override it: run_case
  // refuses --resume without [time] first.
  virtual void resume(Checkpoint k);
  // A resumed run keeps its checkpoint and its frame files up to this step (−1: none
  // listed); nullopt: not resumed.
  virtual std::optional<int> resumed_frames_to() const { return std::nullopt; }
};

}  // namespace fsi
