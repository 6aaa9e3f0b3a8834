#include "run/sweep.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/timer.hpp"
#include "io/atomic_file.hpp"
#include "run/output_dir.hpp"
#include "run/setup_cache.hpp"

namespace fsi {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (char ch : line) {
    if (ch == '"') quoted = !quoted;
    else if (ch == ',' && !quoted) cells.push_back(trim(cell)), cell.clear();
    else cell += ch;
  }
  cells.push_back(trim(cell));
  return cells;
}

struct Row {
  Case c;
  std::map<std::string, std::string> paper;  // paper.* reference values
  std::vector<std::string> settings;         // "key=value" of this row, for the table
};

std::string fmt(double v, int digits = 6) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

}  // namespace

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": no such rows file");
  CsvTable t;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> cells = split_csv_line(line);
    if (t.header.empty()) {
      t.header = cells;
      continue;
    }
    if (cells.size() != t.header.size())
      throw InputError(path + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                       " cells; allowed: " + std::to_string(t.header.size()) + " (one per header column)");
    t.rows.push_back(cells);
  }
  if (t.header.empty()) throw InputError(path + ": empty rows file; allowed: a header line and rows");
  return t;
}

SweepResult run_sweep(const std::string& case_path, const std::string& rows_csv, const SweepOptions& options) {
  const CsvTable csv = read_csv(rows_csv);
  const Case base = load_case(case_path, options.overrides);
  SweepResult result;
  result.out_dir = options.out_dir.empty() ? "out/" + base.name + "-sweep" : options.out_dir;

  // Validate every row before writing anything.
  std::vector<Row> rows;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    Row row;
    std::vector<std::string> sets = options.overrides;
    for (std::size_t j = 0; j < csv.header.size(); ++j) {
      const std::string& key = csv.header[j];
      const std::string& value = csv.rows[i][j];
      if (key.rfind("paper.", 0) == 0) {
        row.paper[key.substr(6)] = value;
      } else if (key == "label") {
        row.paper["label"] = value;
      } else if (!value.empty()) {
        sets.push_back(key + "=" + value);
        row.settings.push_back(key + "=" + value);
      }
    }
    char dir[32];
    std::snprintf(dir, sizeof dir, "/row-%02zu", i + 1);
    sets.push_back("output.dir=\"" + result.out_dir + dir + "\"");
    if (!options.keep_outputs) sets.insert(sets.end(), {"output.png=false", "output.vtu=false"});
    try {
      row.c = load_case(case_path, sets);
    } catch (const InputError& e) {
      throw InputError(rows_csv + ": row " + std::to_string(i + 1) + ": " + e.what());
    }
    rows.push_back(std::move(row));
  }
  prepare_output_dir(result.out_dir, rows_csv);

  // Run rows grouped by fluid mesh (so each mesh and its setup is built once),
  // report them in the file's order.
  std::vector<std::size_t> order(rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const std::string ka = rows[a].c.fluid ? fluid_mesh_key(rows[a].c) : "";
    const std::string kb = rows[b].c.fluid ? fluid_mesh_key(rows[b].c) : "";
    return ka < kb;
  });
  SetupCache cache;
  std::vector<Json> summaries(rows.size());
  std::vector<std::string> statuses(rows.size());
  std::vector<double> walls(rows.size(), NAN);
  std::fill(statuses.begin(), statuses.end(), "not run (interrupted)");
  for (std::size_t i : order) {
    if (interrupt_requested()) {
      result.interrupted = true;
      break;
    }
    const Case& c = rows[i].c;
    const Stopwatch clock;
    std::string status = "converged";
    try {
      RunOptions run_options;
      run_options.cache = &cache;
      if (options.progress)
        run_options.progress = [&, i](const std::string& l) { options.progress("[row " + std::to_string(i + 1) + "] " + l); };
      const RunResult r = run_case(c, run_options);
      summaries[i] = r.summary;
      if (r.exit_status == kInterruptedExitStatus) status = "interrupted", result.interrupted = true;
      else if (r.exit_status == 3) status = "not converged", ++result.not_converged;
      else ++result.converged;
      if (r.summary.contains("convergence_warning")) status += ", unsettled (see its history.csv)";
      if (options.progress) options.progress("[row " + std::to_string(i + 1) + "] " + r.report);
    } catch (const SolverFailure& e) {
      status = std::string("failed: ") + e.what();
      ++result.failed;
      if (options.progress) options.progress("[row " + std::to_string(i + 1) + "] " + status);
    }
    ++result.rows;
    statuses[i] = status;
    walls[i] = clock.elapsed();
  }

  std::ostringstream md, csv_out;
  md << "| row | eps | omega | hF | hS | k | paper k | last increment | paper | ‖v‖_{0,Ω_S^u} | paper "
        "| ‖v‖/ε | paper | max \\|u\\| (m) | contact X1 (m) | fluid / structure triangles | wall (s) | "
        "status |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv_out << "row,eps,omega,hF,hS,scheme,chi,k,paper_k,iterations,final_increment_l2,paper_increment,"
             "v_l2_in_structure,paper_v_norm,v_over_eps,paper_v_over_eps,max_displacement,contact_x_min,"
             "contact_x_max,fluid_triangles,structure_triangles,wall_s,fluid_s,status\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    const Case& c = row.c;
    const Json& s = summaries[i];
    const std::string& status = statuses[i];
    const double wall = walls[i];
    auto num = [&](const char* key) { return s.contains(key) ? s[key].get<double>() : NAN; };
    auto paper = [&](const char* key) {
      auto it = row.paper.find(key);
      return it == row.paper.end() ? std::string("") : it->second;
    };
    const bool has = !s.is_null();
    const double k = has && c.fluid && s.contains("paper_k") ? s["paper_k"].get<double>() : NAN;
    const double x_min = has && s.contains("contact") && !s["contact"]["x_min"].is_null() ? s["contact"]["x_min"].get<double>() : NAN;
    const double x_max = has && s.contains("contact") && !s["contact"]["x_max"].is_null() ? s["contact"]["x_max"].get<double>() : NAN;
    const int ft = has && s["mesh"].contains("fluid") ? s["mesh"]["fluid"]["triangles"].get<int>() : 0;
    const int st = has ? s["mesh"]["structure"]["triangles"].get<int>() : 0;
    const double fluid_s = has ? s["timing_s"]["fluid"].get<double>() : NAN;
    const double hF = c.fluid ? c.fluid->h : NAN;
    md << "| " << i + 1 << " | " << fmt(c.coupling.eps) << " | " << fmt(c.coupling.omega) << " | " << fmt(hF)
       << " | " << fmt(c.structure.h) << " | " << fmt(k) << " | " << paper("k") << " | "
       << fmt(num("final_increment_l2")) << " | " << paper("increment") << " | "
       << fmt(num("fluid_velocity_l2_in_structure")) << " | " << paper("v_norm") << " | "
       << fmt(num("fluid_velocity_l2_in_structure_over_eps")) << " | " << paper("v_over_eps") << " | "
       << fmt(num("max_displacement"), 4) << " | " << fmt(x_min, 4) << "–" << fmt(x_max, 4) << " | " << ft
       << " / " << st << " | " << fmt(wall, 3) << " | " << status << " |\n";
    csv_out << std::setprecision(10) << i + 1 << ',' << c.coupling.eps << ',' << c.coupling.omega << ',' << hF
            << ',' << c.structure.h << ',' << c.coupling.scheme << ',' << (c.fluid ? c.fluid->chi : std::string()) << ',' << k << ',' << paper("k") << ','
            << (has ? s["iterations"].get<int>() : 0) << ',' << num("final_increment_l2") << ','
            << paper("increment") << ',' << num("fluid_velocity_l2_in_structure") << ',' << paper("v_norm")
            << ',' << num("fluid_velocity_l2_in_structure_over_eps") << ',' << paper("v_over_eps") << ','
            << num("max_displacement") << ',' << x_min << ',' << x_max << ',' << ft << ',' << st << ','
            << wall << ',' << fluid_s << ',' << '"' << status << '"' << '\n';
  }
  namespace fs = std::filesystem;
  write_atomically((fs::path(result.out_dir) / "table.md").string(), [&](std::ostream& o) { o << md.str(); });
  write_atomically((fs::path(result.out_dir) / "table.csv").string(), [&](std::ostream& o) { o << csv_out.str(); });
  result.table_markdown = md.str();
  return result;
}

}  // namespace fsi
