// Pieces of summary.json (SPEC §8).
#pragma once

#include <nlohmann/json.hpp>

#include <optional>

#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "qp/qp_problem.hpp"
#include "common/timer.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

using Json = nlohmann::ordered_json;

// The resolved case, every key (summary.json's "parameters"); each section alone too,
// which also keys the sweep's setup cache (run/setup_cache.cpp).
Json to_json(const Case& c);
Json to_json(const StructureParams& s);
Json to_json(const ObstacleParams& o);
Json to_json(const FluidParams& f);
Json to_json(const CouplingParams& k);
Json to_json(const ContactParams& c);
Json to_json(const OutputParams& o);
Json to_json(const MeshStatistics& s);
Json to_json(const KktResiduals& k);
Json to_json(const ContactSummary& s);
// timing_s: total, mesh, fluid, structure, transfer (always present), then any other phase.
Json timing_json(const PhaseTimes& times, double total);

// JSON text; bytes that are not UTF-8 (in a path) become U+FFFD.
std::string json_text(const Json& j, int indent = -1);
void write_json(const std::string& path, const Json& j);

// [x, y] as a JSON array.
Json point_json(const Point& p);
// The structure's tip: the middle of its free end, (L, H/2) in the reference
// configuration (summary.json's tip_displacement); none for a structure from a file
// or script without structure.L and H (its "free end" is not known).
std::optional<Point> tip_of(const Case& c);
// u at the tip, [x, y], or null without one.
Json tip_displacement_json(const Case& c, const Mesh& reference, const Eigen::VectorXd& u,
                           const P2Space* p2 = nullptr);

// summary.json's displacement_at (SPEC §11): [{"point": [x, y], "u": [ux, uy]}, ...], u
// at each of output.probes in its order (P1 interpolation); no key without probes.
void add_displacement_at(Json& j, const Case& c, const Mesh& reference, const Eigen::VectorXd& u,
                         const P2Space* p2 = nullptr);

// max |u| over the vertices of u = (u1, u2) (hypot: nothing under- or overflows).
double max_displacement(const Eigen::VectorXd& u);

}  // namespace fsi
