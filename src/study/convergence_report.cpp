#include "study/convergence_report.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "common/format.hpp"
#include "io/chart.hpp"

namespace fsi {
namespace {

// The size the levels refine: the fluid's at the structure, or the structure's when
// only the structure is refined (or there is no fluid).
double size_of(const Study& s, const Case& c) {
  return c.fluid && s.refine != "structure" ? c.fluid->size_near() : c.structure.h;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string cell(double v, int digits = 6) { return std::isfinite(v) ? approx(v, digits) : "–"; }

}  // namespace

std::vector<const LevelRun*> runs_of(const Study& s, const std::string& scheme) {
  std::vector<const LevelRun*> out;
  for (const auto& r : s.runs)
    if (r.spec.scheme == scheme) out.push_back(&r);
  return out;
}

// A quantity some level does not have (no contact there, a failed run) has no kind.
static std::string kind_of(const QuantityStudy& q) {
  const bool complete = std::all_of(q.values.begin(), q.values.end(), [](double v) { return std::isfinite(v); });
  return complete ? to_string(q.estimate.kind) : "not at every level";
}

static void choose_error_bar(QuantityStudy& q) {
  const ConvergenceEstimate& e = q.estimate;
  const bool asymptotic = e.asymptotic.value_or(false);
  if (std::isfinite(e.gci_abs) && (asymptotic || !e.asymptotic.has_value())) {
    q.error_bar = e.gci_abs, q.error_bar_method = "GCI";
  } else if (std::isfinite(q.least_squares.uncertainty)) {
    q.error_bar = q.least_squares.uncertainty, q.error_bar_method = "least squares";
  } else if (std::isfinite(e.error_bar)) {
    q.error_bar = e.error_bar, q.error_bar_method = "oscillation range";
  }
}

// What add_penalty_error appends to error_bar_method (summary.json's contract).
static const std::string kPenaltySuffix = " + penalty";

// The penalty's part (study/penalty_error.hpp) added to the levels' error bar.
static void add_penalty_error(QuantityStudy& q, const Study& study) {
  const LevelRun& check = study.penalty_check;
  if (check.status != "converged" || q.values.empty()) return;
  const Case& finest = runs_of(study, study.schemes.front()).back()->spec.c;
  q.penalty = penalty_error(finest.coupling.eps, q.values.back(), q.quantity.read(check.result.summary), study.ratio);
  q.error_bar_h = q.error_bar;
  if (!std::isfinite(q.penalty.error_bar)) return;
  q.penalty_dominates = !(q.penalty.error_bar <= q.error_bar_h);
  if (q.penalty_dominates) q.estimate.asymptotic = false;
  if (std::isfinite(q.error_bar)) q.error_bar += q.penalty.error_bar, q.error_bar_method += kPenaltySuffix;
}

double agreement_allowed(const QuantityStudy& q) {
  const double gci = q.estimate.gci_abs;
  const double base = std::isfinite(gci) && gci > 0 ? 0.1 * gci : 1e-6 * std::abs(q.values.empty() ? 0.0 : q.values.back());
  return std::max(base, q.coupling_floor);
}

// The fixed point is the map's, whatever the scheme: a scheme restarted from another's
// end state either stays there (that state is a fixed point for it too, so the map has
// two where the schemes' own runs ended), or leaves it (that end state was a stop
// short of a fixed point, which a tighter coupling.tol would have gone on from).
void judge_restart(Restart& r, double allowed) {
  const std::string other = r.run.spec.scheme;
  const Json& s = r.run.result.summary;
  const int passes = s.is_object() && s.contains("iterations") && s["iterations"].is_number() ? s["iterations"].get<int>() : 0;
  if (r.run.status != "converged") {
    r.verdict = other + " restarted from " + r.from + "'s end state did not converge (" + r.run.status + ")";
  } else if (passes == 1) {
    r.verdict = other + " restarted from " + r.from + "'s end state stops at once (its first increment is below "
                "coupling.tol): within that tolerance both end states are fixed points, " + approx(std::abs(r.own - r.start), 3) +
                " apart in max |u|; rerun with a smaller coupling.tol to tell whether they are distinct";
  } else if (std::abs(r.value - r.start) <= allowed) {
    r.verdict = other + " restarted from " + r.from + "'s end state stays there: both end states are fixed points "
                "(distinct solutions on this level)";
  } else if (std::abs(r.value - r.own) <= allowed) {
    r.verdict = other + " restarted from " + r.from + "'s end state returns to its own: " + r.from +
                "'s end state is not a fixed point (a stop short of one: tighten coupling.tol)";
  } else {
    r.verdict = other + " restarted from " + r.from + "'s end state reaches a third state";
  }
}

void evaluate(Study& study, const Case& base) {
  const bool with_fluid = base.fluid.has_value();
  const std::vector<const LevelRun*> primary = runs_of(study, study.schemes.front());
  study.quantities.clear();
  for (const Quantity& q : quantities(base)) {
    QuantityStudy qs;
    qs.quantity = q;
    for (const LevelRun* r : primary) qs.values.push_back(r->result.summary.is_null() ? NAN : q.read(r->result.summary));
    const bool complete = std::all_of(qs.values.begin(), qs.values.end(), [](double v) { return std::isfinite(v); });
    if (complete) qs.estimate = estimate_convergence(qs.values, study.ratio);
    std::vector<double> h;
    for (const LevelRun* r : primary) h.push_back(size_of(study, r->spec.c));
    if (complete) qs.least_squares = least_squares_estimate(h, qs.values);
    choose_error_bar(qs);
    add_penalty_error(qs, study);
    qs.scheme_difference.assign(qs.values.size(), NAN);
    for (std::size_t s = 1; s < study.schemes.size(); ++s) {
      const std::vector<const LevelRun*> other = runs_of(study, study.schemes[s]);
      for (std::size_t i = 0; i < other.size() && i < qs.values.size(); ++i) {
        // Only a converged run says where its scheme's fixed point is.
        const bool both = other[i]->status == "converged" && primary[i]->status == "converged";
        const double d = both ? std::abs(q.read(other[i]->result.summary) - qs.values[i]) : NAN;
        if (std::isfinite(d)) qs.scheme_difference[i] = std::isfinite(qs.scheme_difference[i]) ? std::max(qs.scheme_difference[i], d) : d;
      }
    }
    for (double d : qs.scheme_difference)
      if (std::isfinite(d)) qs.max_scheme_difference = std::isfinite(qs.max_scheme_difference) ? std::max(qs.max_scheme_difference, d) : d;
    if (with_fluid && !primary.empty()) {
      const Json& s = primary.back()->result.summary;
      const double norm = s.is_object() && s.contains("final_norm_l2") && s["final_norm_l2"].is_number()
                              ? s["final_norm_l2"].get<double>() : NAN;
      if (norm > 0 && std::isfinite(qs.values.back()))
        qs.coupling_floor = std::abs(qs.values.back()) * primary.back()->spec.c.coupling.tol / norm;
    }
    qs.schemes_agree = !(qs.max_scheme_difference > agreement_allowed(qs));
    study.quantities.push_back(std::move(qs));
  }
  // The stopping test's increment is an L² norm over Ω_S0 (m²): a displacement change
  // δ spread over the structure is δ·sqrt(|Ω_S0|). Tied to the discretisation, the
  // tolerance should be below a thousandth of max |u|'s GCI so measured.
  const Case& finest = primary.back()->spec.c;
  // The contact problem, or the fluid alone: no coupling, nothing to advise.
  if (!finest.fluid || finest.structure.shape == "none") return;
  study.tol_used = finest.coupling.tol;
  const double gci = study.quantities.front().estimate.gci_abs;
  study.tol_advised = std::isfinite(gci) ? 1e-3 * gci * std::sqrt(finest.structure.L * finest.structure.H) : NAN;
}

std::string convergence_csv(const Study& study) {
  std::ostringstream out;
  out << std::setprecision(12) << "level,scheme,structure_h,fluid_h,fluid_h_near,eps,structure_triangles,fluid_triangles,"
      << "iterations,wall_s,status";
  for (const auto& q : study.quantities) out << ',' << q.quantity.name;
  out << '\n';
  std::vector<const LevelRun*> rows;
  for (const LevelRun& r : study.runs) rows.push_back(&r);
  if (study.penalty_check.status != "not run") rows.push_back(&study.penalty_check);
  for (const LevelRun* row : rows) {
    const LevelRun& r = *row;
    const Case& c = r.spec.c;
    const Json& s = r.result.summary;
    auto mesh = [&](const char* part) {
      return s.is_object() && s.contains("mesh") && s["mesh"].contains(part) ? s["mesh"][part]["triangles"].get<int>() : 0;
    };
    out << r.spec.index << ',' << r.spec.scheme << ',' << c.structure.h << ',' << (c.fluid ? c.fluid->h : NAN) << ','
        << (c.fluid ? c.fluid->h_near : NAN) << ',' << c.coupling.eps << ',' << mesh("structure") << ',' << mesh("fluid")
        << ',' << (s.is_object() && s.contains("iterations") ? s["iterations"].get<int>() : 0) << ',' << r.wall_s << ",\""
        << r.status << '"';
    for (const auto& q : study.quantities) out << ',' << (s.is_null() ? NAN : q.quantity.read(s));
    out << '\n';
  }
  return out.str();
}

std::string tolerance_note(const Study& study) {
  if (!(study.tol_used > study.tol_advised)) return "";
  return "coupling.tol = " + approx(study.tol_used, 3) + " is coarse against the discretisation error: the schemes' "
         "agreement and the values carry the coupling's own error; for it to be under a thousandth of max |u|'s GCI, "
         "rerun with --set coupling.tol=" + approx(study.tol_advised, 2);
}

// "φ ± U (method)", with a penalty check "φ ± U (GCI 0.1 + penalty 0.2)".
static std::string error_bar_cell(const QuantityStudy& q) {
  if (!std::isfinite(q.error_bar)) return "–";
  std::string parts = q.error_bar_method;
  const std::size_t suffix = parts.rfind(kPenaltySuffix);
  if (suffix != std::string::npos && suffix + kPenaltySuffix.size() == parts.size())
    parts = parts.substr(0, suffix) + " " + cell(q.error_bar_h, 2) + kPenaltySuffix + " " + cell(q.penalty.error_bar, 2) +
            (q.penalty_dominates ? ", dominant" : "");
  return cell(q.values.back(), 8) + " ± " + cell(q.error_bar, 2) + " (" + parts + ")";
}

static std::string penalty_note(const Study& study) {
  const LevelRun& c = study.penalty_check;
  if (c.status == "not run") return "";
  return "\nPenalty check: the finest level again with ε = " + cell(c.spec.c.coupling.eps, 3) + " (ε·r²): " + c.status +
         (c.status == "converged" ? "; its difference, times " + approx(kPenaltySafety / (study.ratio - 1), 3) +
                                        ", is each quantity's penalty error bar (ε^(1/2) assumed)"
                                  : "; the error bars are the levels' alone") + ".\n";
}

std::string convergence_markdown(const Study& study) {
  std::ostringstream md;
  md << "| level | h | ε |";
  for (const auto& q : study.quantities) md << ' ' << q.quantity.name << " (" << q.quantity.unit << ") |";
  md << "\n|---|---|---|";
  for (std::size_t i = 0; i < study.quantities.size(); ++i) md << "---|";
  md << '\n';
  for (const LevelRun* r : runs_of(study, study.schemes.front())) {
    md << "| " << r->spec.index << " | " << cell(size_of(study, r->spec.c), 4) << " | " << cell(r->spec.c.coupling.eps, 3) << " |";
    for (const auto& q : study.quantities) md << ' ' << cell(q.values[static_cast<std::size_t>(r->spec.index - 1)], 8) << " |";
    md << '\n';
  }
  md << "\n| quantity | kind | observed order | extrapolated | GCI | least-squares limit (order) | finest ± error bar | "
        "asymptotic | schemes' largest difference |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& q : study.quantities) {
    const ConvergenceEstimate& e = q.estimate;
    md << "| " << q.quantity.name << " | " << kind_of(q) << " | " << cell(e.observed_order, 3) << " | "
       << cell(e.extrapolated, 8) << " | " << (std::isfinite(e.gci) ? approx(100 * e.gci, 3) + " %" : "–") << " | "
       << (std::isfinite(q.least_squares.limit)
               ? cell(q.least_squares.limit, 8) + " (" + approx(q.least_squares.order, 3) + ")"
               : std::string("–"))
       << " | " << error_bar_cell(q) << " | "
       << (e.asymptotic ? (*e.asymptotic ? "yes" : "no") : "needs 4 levels") << " | "
       << (study.schemes.size() > 1 ? cell(q.max_scheme_difference, 3) + (q.schemes_agree ? "" : " (disagree)") : "–")
       << " |\n";
  }
  for (const Restart& r : study.restarts)
    md << "\nLevel " << r.run.spec.index << ": " << r.verdict << " (max |u| " << cell(r.start, 8) << " → "
       << cell(r.value, 8) << "; from rest " << r.run.spec.scheme << " ended at " << cell(r.own, 8) << ").\n";
  md << penalty_note(study);
  const std::string note = tolerance_note(study);
  if (!note.empty()) md << "\nNote: " << note << ".\n";
  return md.str();
}

void write_convergence_png(const std::string& path, const Study& study) {
  std::vector<Series> series;
  const std::vector<const LevelRun*> primary = runs_of(study, study.schemes.front());
  for (std::size_t k = 0; k < study.quantities.size(); ++k) {
    const QuantityStudy& q = study.quantities[k];
    Series s;
    s.label = q.quantity.name;
    const double n = static_cast<double>(study.quantities.size());
    s.colour = viridis(n > 1 ? static_cast<double>(k) / (n - 1) : 0.0);
    const double scale = std::abs(q.values.back());
    for (std::size_t i = 0; i + 1 < q.values.size(); ++i) {
      const double d = std::abs(q.values[i] - q.values[i + 1]) / (scale > 0 ? scale : 1.0);
      if (std::isfinite(d) && d > 0) s.x.push_back(size_of(study, primary[i]->spec.c)), s.y.push_back(d);
    }
    if (!s.x.empty()) series.push_back(std::move(s));
  }
  ChartOptions options;
  options.title = "Differences between consecutive levels (relative to the finest value)";
  options.x_label = "mesh size h (m)";
  options.y_label = "|phi_i - phi_i+1| / |phi_finest|";
  write_chart(path, options, series);
}

// One quantity's entry of summary.json's "quantities".
static Json quantity_json(const QuantityStudy& q) {
  const ConvergenceEstimate& e = q.estimate;
  Json values = Json::array(), orders = Json::array(), diffs = Json::array();
  for (double v : q.values) values.push_back(number_or_null(v));
  for (double p : e.orders) orders.push_back(number_or_null(p));
  for (double d : q.scheme_difference) diffs.push_back(number_or_null(d));
  return {{"unit", q.quantity.unit},
          {"values", values},
          {"observed_order", number_or_null(e.observed_order)},
          {"orders", orders},
          {"kind", kind_of(q)},
          {"extrapolated", number_or_null(e.extrapolated)},
          {"gci", number_or_null(e.gci)},
          {"gci_abs", number_or_null(e.gci_abs)},
          {"error_bar", number_or_null(q.error_bar)},
          {"error_bar_method", q.error_bar_method},
          {"least_squares",
           {{"limit", number_or_null(q.least_squares.limit)},
            {"order", number_or_null(q.least_squares.order)},
            {"sigma", number_or_null(q.least_squares.sigma)},
            {"safety", number_or_null(q.least_squares.safety)},
            {"uncertainty", number_or_null(q.least_squares.uncertainty)},
            {"order_at_bound", q.least_squares.order_at_bound}}},
          {"asymptotic", e.asymptotic ? Json(*e.asymptotic) : Json(nullptr)},
          {"error_bar_h", number_or_null(q.error_bar_h)},
          {"penalty",
           {{"eps", number_or_null(q.penalty.eps)},
            {"eps_check", number_or_null(q.penalty.eps_check)},
            {"value_check", number_or_null(q.penalty.value_check)},
            {"error_bar", number_or_null(q.penalty.error_bar)},
            {"dominates", q.penalty_dominates}}},
          {"scheme_difference", diffs},
          {"schemes_agree", q.schemes_agree}};
}

Json convergence_json(const Study& study) {
  Json levels = Json::array();
  for (const LevelRun& r : study.runs) {
    const Case& c = r.spec.c;
    Json l = {{"level", r.spec.index}, {"scheme", r.spec.scheme}, {"structure_h", c.structure.h},
              {"eps", c.coupling.eps}, {"status", r.status}, {"wall_s", number_or_null(r.wall_s)},
              {"dir", c.output.dir}};
    if (c.fluid) l["fluid_h"] = c.fluid->h, l["fluid_h_near"] = c.fluid->h_near;
    const Json& s = r.result.summary;
    if (s.is_object() && s.contains("mesh")) l["mesh"] = s["mesh"];
    if (s.is_object() && s.contains("iterations")) l["iterations"] = s["iterations"];
    levels.push_back(l);
  }
  Json quantities = Json::object();
  for (const auto& q : study.quantities) quantities[q.quantity.name] = quantity_json(q);
  Json restarts = Json::array();
  for (const Restart& r : study.restarts)
    restarts.push_back({{"level", r.run.spec.index}, {"scheme", r.run.spec.scheme}, {"from", r.from},
                        {"start", number_or_null(r.start)}, {"own", number_or_null(r.own)},
                        {"value", number_or_null(r.value)}, {"status", r.run.status}, {"verdict", r.verdict},
                        {"dir", r.run.spec.c.output.dir}});
  const LevelRun& pc = study.penalty_check;
  const Json penalty_check = pc.status == "not run" ? Json(nullptr)
                             : Json{{"status", pc.status}, {"eps", pc.spec.c.coupling.eps}, {"dir", pc.spec.c.output.dir},
                                    {"wall_s", number_or_null(pc.wall_s)}, {"safety", kPenaltySafety}};
  return {{"ratio", study.ratio},
          {"penalty_check", penalty_check},
          {"refine", study.refine},
          {"restarts", restarts},
          {"schemes", study.schemes},
          {"levels", levels},
          {"quantities", quantities},
          {"coupling_tolerance",
           {{"used", number_or_null(study.tol_used)}, {"advised", number_or_null(study.tol_advised)},
            {"note", tolerance_note(study)}}}};
}

}  // namespace fsi
