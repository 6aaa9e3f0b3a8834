// The fluid alone on the Taylor–Hood element (fluid.element = "taylor-hood",
// structure.shape = "none"): what a run builds once from the case — the mesh of D,
// its P2 space, the isoparametric geometry with every disk of the case curved, the
// system with the box's boundary conditions, and its Newton solver — and what the runs
// read of it: the data at a time, the forces on the holes, summary.json's "fluid".
#pragma once

#include <memory>
#include <vector>

#include "fem/iso_p2.hpp"
#include "fluid/taylor_hood_flow.hpp"
#include "io/case.hpp"
#include "run/outputs/summary.hpp"

namespace fsi {

struct TaylorHoodSetup {
  std::unique_ptr<Mesh> mesh;  // owned here: the space, geometry and system refer to it
  std::unique_ptr<P2Space> space;
  std::unique_ptr<IsoP2Geometry> geometry;
  std::unique_ptr<TaylorHoodSystem> system;
  std::unique_ptr<TaylorHoodFlow> flow;
};

// The case's disks as circles of the mesh's hole labels ([obstacle]'s disk: Sigma_5;
// [[obstacles]]: Sigma_5_i for each disk). None for a mesh file (fluid.mesh): its holes'
// shapes are the file's, met at their nodes.
std::vector<CircleBoundary> disk_holes(const Case& c, const Mesh& mesh);

// The set-up with the data at time t. A hole's edge that folds its triangle when
// curved is a SolverFailure naming the hole's size (the mesh is too coarse there).
TaylorHoodSetup make_taylor_hood(const Case& c, Mesh mesh, double t = 0);
// fluid.f and the box's inflow at time t (SPEC §12).
void set_taylor_hood_data(TaylorHoodSetup& s, const Case& c, double t);
// The fluid's force on each of the case's holes (obstacle_hole_names order), by the
// residual method at the flow's state with the data and time derivative of its solve.
std::vector<Point> taylor_hood_hole_forces(TaylorHoodSetup& s, const Case& c);
// summary.json's "fluid_at" (output.fluid_probes): v and p of the P2/P1 state at each
// point (the nearest point of D for one outside it).
Json taylor_hood_probes_json(const Case& c, const TaylorHoodSetup& s);
// summary.json's "fluid" for it: the element, sizes, the curved triangles, the solver
// and its timings, Newton's report.
Json taylor_hood_json(const TaylorHoodSetup& s);

}  // namespace fsi
