// Pieces of summary.json (SPEC §8).
#pragma once

#include <nlohmann/json.hpp>

#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "qp/qp_problem.hpp"
#include "common/timer.hpp"
#include "solid/contact_solver.hpp"

namespace fsi {

using Json = nlohmann::ordered_json;

Json to_json(const Case& c);
Json to_json(const MeshStatistics& s);
Json to_json(const KktResiduals& k);
Json to_json(const ContactSummary& s);
// timing_s: total, mesh, fluid, structure, transfer (always present), then any other phase.
Json timing_json(const PhaseTimes& times, double total);

void write_json(const std::string& path, const Json& j);

}  // namespace fsi
