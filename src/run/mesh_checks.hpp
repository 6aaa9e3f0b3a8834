// A mesh against the case it is used for: keys that contradict a given mesh, a
// structure outside the fluid box or inside the obstacle, boundary parts on the wrong
// side, an unlabelled boundary edge. Each is an input error (exit 2, nothing
// written) naming the key, the mesh file and the defect.
#pragma once

#include "io/case.hpp"
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace fsi {

// A user's mesh file given by `key` ("structure.mesh", "fluid.mesh"): read with its
// boundary curves and domain surface; a bad file, or one over `max_triangles`, is an
// InputError naming the case file and the key. `optional_curves` become labels, empty
// if the file has none.
Mesh read_case_mesh(const Case& c, const std::string& key, const std::string& path,
                    const std::vector<std::string>& curves, const std::string& surface, double max_triangles,
                    const std::vector<std::string>& optional_curves = {});

// The structure's mesh (generated or read): Γ_C inside the obstacle's span with a
// vertex strictly inside it (else no contact row exists), every part joined to Γ_D
// (else A_S is singular), no vertex inside the disk, every boundary edge labelled,
// inside the fluid box (FSI), Γ_D off an inflow on Σ1; a file's (mesh or script) extent
// must equal structure.L × structure.H from (0, 0) if either is given, and its loads
// strain it little; every output.probes point lies in it.
void check_structure_mesh(const Case& c, const Mesh& mesh);

// A fluid mesh file: its box equals (0, L1) × (−H2, H1), Σ1…Σ4 are the left,
// bottom, right and top sides (fluid.left, ... are applied on the labels whatever
// the coordinates), Σ5 is the obstacle's circle and D excludes the disk (with
// [[obstacles]]: a hole per obstacle, check_mesh_holes), every boundary edge labelled.
void check_fluid_mesh(const Case& c, const Mesh& mesh);
// output.fluid_probes (SPEC §10) in D, generated or read, up to fluid.h / 10
// (InputError naming the probe otherwise).
void check_fluid_probes_inside(const Case& c, const Mesh& mesh);

// The first boundary edge of the triangulation (used by one triangle) that carries
// no label, as its two vertex indices; {-1, -1} if none.
std::array<int, 2> unlabelled_boundary_edge(const Mesh& mesh);

}  // namespace fsi
