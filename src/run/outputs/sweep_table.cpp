#include "run/outputs/sweep_table.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace fsi {
namespace {

std::string fmt(double v, int digits = 6) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// A measured value as summary.json states it: a non-finite one is null there, and
// a blank (NaN) here.
double stated(double v) { return std::isfinite(v) ? v : NAN; }

// A CSV cell in quotes, its quotes doubled (RFC 4180).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

// A Markdown cell: '|' would end it, a newline the row.
std::string md_cell(std::string text) {
  std::string out;
  for (char ch : text) out += ch == '|' ? std::string("\\|") : ch == '\n' ? std::string(" ") : std::string(1, ch);
  return out;
}

// Both tables in one pass over the rows (they share every lookup).
std::pair<std::string, std::string> sweep_tables(const std::vector<SweepRow>& rows) {
  std::ostringstream md, csv_out;
  md << "| row | eps | omega | hF | hS | k | paper k | last increment | paper | ‖v‖_{0,Ω_S^u} | paper "
        "| ‖v‖/ε | paper | max \\|u\\| (m) | contact X1 (m) | fluid / structure triangles | wall (s) | "
        "status |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv_out << "row,eps,omega,hF,hS,scheme,chi,k,paper_k,iterations,final_increment_l2,paper_increment,"
             "v_l2_in_structure,paper_v_norm,v_over_eps,paper_v_over_eps,max_displacement,contact_x_min,"
             "contact_x_max,fluid_triangles,structure_triangles,wall_s,fluid_s,status\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SweepRow& row = rows[i];
    const Case& c = row.c;
    const RunMeasures& m = row.measures;
    const std::string& status = row.status;
    const double wall = row.wall_s;
    auto paper = [&](const char* key) {
      auto it = row.paper.find(key);
      return it == row.paper.end() ? std::string("") : it->second;
    };
    const double k = c.fluid && m.stop ? static_cast<double>(m.stop->paper_k) : NAN;
    const double increment = m.stop ? stated(m.stop->final_increment) : NAN;
    const double v = m.fluid_in_structure ? stated(m.fluid_in_structure->v) : NAN;
    const double v_over_eps = m.fluid_in_structure ? stated(m.fluid_in_structure->v_over_eps) : NAN;
    const double max_u = m.displacement ? stated(m.displacement->max) : NAN;
    const bool touching = m.contact && m.contact->active_nodes > 0;  // x_min, x_max: null without contact
    const double x_min = touching ? m.contact->x_min : NAN, x_max = touching ? m.contact->x_max : NAN;
    const int ft = m.fluid_mesh.triangles, st = m.structure_mesh.triangles;
    const double hF = c.fluid ? c.fluid->h : NAN;
    md << "| " << i + 1 << " | " << fmt(c.coupling.eps) << " | " << fmt(c.coupling.omega) << " | " << fmt(hF)
       << " | " << fmt(c.structure.h) << " | " << fmt(k) << " | " << paper("k") << " | "
       << fmt(increment) << " | " << paper("increment") << " | " << fmt(v) << " | " << paper("v_norm") << " | "
       << fmt(v_over_eps) << " | " << paper("v_over_eps") << " | " << fmt(max_u, 4) << " | " << fmt(x_min, 4)
       << "–" << fmt(x_max, 4) << " | " << ft << " / " << st << " | " << fmt(wall, 3) << " | " << md_cell(status)
       << " |\n";
    csv_out << std::setprecision(10) << i + 1 << ',' << c.coupling.eps << ',' << c.coupling.omega << ',' << hF
            << ',' << c.structure.h << ',' << c.coupling.scheme << ',' << (c.fluid ? c.fluid->chi : std::string())
            << ',' << k << ',' << paper("k") << ',' << m.iterations << ',' << increment << ',' << paper("increment")
            << ',' << v << ',' << paper("v_norm") << ',' << v_over_eps << ',' << paper("v_over_eps") << ',' << max_u
            << ',' << x_min << ',' << x_max << ',' << ft << ',' << st << ',' << wall << ',' << m.fluid_s << ','
            << quoted(status) << '\n';
  }
  return {md.str(), csv_out.str()};
}

}  // namespace

std::string sweep_table_markdown(const std::vector<SweepRow>& rows) { return sweep_tables(rows).first; }
std::string sweep_table_csv(const std::vector<SweepRow>& rows) { return sweep_tables(rows).second; }

}  // namespace fsi
