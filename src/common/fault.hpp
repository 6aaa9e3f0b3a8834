// Fault injection for the tests of the failure paths (docs/reliability.md): with the
// environment variable FSICONTACT_FAULT=<phase> (or <phase>:oom), fault_point(phase)
// throws as the phase's real failure would (SolverFailure, or std::bad_alloc), so
// that every path from a failure to its summary.json runs in the real program,
// deterministically. The real triggers (a Gmsh crash, a factorisation out of memory)
// depend on the machine: ulimit -v made OpenBLAS and libgomp hang, not fail.
// Unset, it costs one getenv per phase.
#pragma once

namespace fsi {

// Phases: "mesh" (after meshing), "structure" (its set-up), "contact" (the
// contact-only QP), "fluid" (the fluid set-up). Write failures need no injection:
// a file size limit (ulimit -f) fails them for real.
void fault_point(const char* phase);

// A time run's step (SPEC §12): with FSICONTACT_FAULT=sigterm@N the process sends itself
// SIGTERM at the end of step N, as a batch system's time limit would, so that the
// checkpoint and --resume are tested against a real signal at a known step.
void fault_step(int step);

}  // namespace fsi
