// What a time run (SPEC §12) keeps in its checkpoint and takes back on --resume: the
// states (Newmark's, the fluid's), the history's rows and the frames written so far,
// each to its last bit (io/checkpoint.hpp), so that the resumed run continues as the
// interrupted one would have, to the same answer bit for bit.
//
// A checkpoint belongs to one case: its fingerprint is that of the resolved case
// without what does not change the numbers (its name, output.* but the probes, time.t_end,
// time.output_every, time.checkpoint_every), so a run can be resumed to a later t_end.
#pragma once

#include <string>
#include <vector>

#include "fluid/stokes_assembler.hpp"
#include "fluid/stokes_strategy.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "run/outputs/structure_history.hpp"
#include "solid/newmark.hpp"

namespace fsi {

std::string case_fingerprint(const Case& c);

// DIR/checkpoint.bin for case `c` run as `kind`; InputError (exit 2, nothing written)
// naming the file and what differs: no checkpoint there, another kind of run, another
// case, or a checkpoint past time.t_end.
Checkpoint read_resume_checkpoint(const std::string& dir, const Case& c, const char* kind);

// A checkpoint of `c`'s run of kind `kind` after `step` steps, at time t.
Checkpoint new_checkpoint(const Case& c, const char* kind, int step, double t);

void put_newmark(Checkpoint& k, const NewmarkState& s);
NewmarkState get_newmark(const Checkpoint& k, long dofs);

void put_fluid(Checkpoint& k, const std::string& name, const FluidSolution& s);
FluidSolution get_fluid(const Checkpoint& k, const std::string& name, int vertices, int triangles);

// The substructured fluid solve's near region (fluid/stokes_strategy.hpp); none if
// the checkpoint has none. A region that is not one of `triangles` is an InputError.
void put_near_region(Checkpoint& k, const NearRegionState& s);
NearRegionState get_near_region(const Checkpoint& k, int triangles);

void put_rows(Checkpoint& k, const StructureRow& initial, const std::vector<StructureRow>& rows);
void get_rows(const Checkpoint& k, StructureRow& initial, std::vector<StructureRow>& rows);

}  // namespace fsi
