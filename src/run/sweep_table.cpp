#include "run/sweep_table.hpp"

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

// A number of a summary by its path of keys; NaN if any key is missing or the value
// is not a number (a failed row's summary has few keys; NaN is written as null).
double number_at(const Json& s, std::initializer_list<const char*> path) {
  const Json* node = &s;
  for (const char* key : path) {
    if (!node->is_object() || !node->contains(key)) return NAN;
    node = &(*node)[key];
  }
  return node->is_number() ? node->get<double>() : NAN;
}

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
    const Json& s = row.summary;
    const std::string& status = row.status;
    const double wall = row.wall_s;
    auto num = [&](const char* key) { return number_at(s, {key}); };
    auto paper = [&](const char* key) {
      auto it = row.paper.find(key);
      return it == row.paper.end() ? std::string("") : it->second;
    };
    const double k = c.fluid ? num("paper_k") : NAN;
    const double x_min = number_at(s, {"contact", "x_min"}), x_max = number_at(s, {"contact", "x_max"});
    const double ft_n = number_at(s, {"mesh", "fluid", "triangles"}), st_n = number_at(s, {"mesh", "structure", "triangles"});
    const int ft = std::isfinite(ft_n) ? static_cast<int>(ft_n) : 0, st = std::isfinite(st_n) ? static_cast<int>(st_n) : 0;
    const double iterations_n = num("iterations");
    const int iterations = std::isfinite(iterations_n) ? static_cast<int>(iterations_n) : 0;
    const double fluid_s = number_at(s, {"timing_s", "fluid"});
    const double hF = c.fluid ? c.fluid->h : NAN;
    md << "| " << i + 1 << " | " << fmt(c.coupling.eps) << " | " << fmt(c.coupling.omega) << " | " << fmt(hF)
       << " | " << fmt(c.structure.h) << " | " << fmt(k) << " | " << paper("k") << " | "
       << fmt(num("final_increment_l2")) << " | " << paper("increment") << " | "
       << fmt(num("fluid_velocity_l2_in_structure")) << " | " << paper("v_norm") << " | "
       << fmt(num("fluid_velocity_l2_in_structure_over_eps")) << " | " << paper("v_over_eps") << " | "
       << fmt(num("max_displacement"), 4) << " | " << fmt(x_min, 4) << "–" << fmt(x_max, 4) << " | " << ft
       << " / " << st << " | " << fmt(wall, 3) << " | " << md_cell(status) << " |\n";
    csv_out << std::setprecision(10) << i + 1 << ',' << c.coupling.eps << ',' << c.coupling.omega << ',' << hF
            << ',' << c.structure.h << ',' << c.coupling.scheme << ',' << (c.fluid ? c.fluid->chi : std::string()) << ',' << k << ',' << paper("k") << ','
            << iterations << ',' << num("final_increment_l2") << ','
            << paper("increment") << ',' << num("fluid_velocity_l2_in_structure") << ',' << paper("v_norm")
            << ',' << num("fluid_velocity_l2_in_structure_over_eps") << ',' << paper("v_over_eps") << ','
            << num("max_displacement") << ',' << x_min << ',' << x_max << ',' << ft << ',' << st << ','
            << wall << ',' << fluid_s << ',' << quoted(status) << '\n';
  }
  return {md.str(), csv_out.str()};
}

}  // namespace

std::string sweep_table_markdown(const std::vector<SweepRow>& rows) { return sweep_tables(rows).first; }
std::string sweep_table_csv(const std::vector<SweepRow>& rows) { return sweep_tables(rows).second; }

}  // namespace fsi
