#include "run/sweep.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/launch.hpp"
#include "common/timer.hpp"
#include "io/atomic_file.hpp"
#include "io/output_path.hpp"
#include "run/provenance.hpp"
#include "run/csv.hpp"
#include "run/outputs/output_dir.hpp"
#include "run/setup_cache.hpp"
#include "run/outputs/sweep_table.hpp"

namespace fsi {
namespace {

namespace fs = std::filesystem;

// Each column is "label", "paper.<name>" or a case key; output.dir is the sweep's to
// choose (row-NN), so a column of it is refused rather than silently overridden;
// a duplicate column would silently take the last.
void check_header(const CsvTable& csv, const std::string& path) {
  const std::vector<std::string> keys = case_keys();
  std::set<std::string> seen;
  for (std::size_t j = 0; j < csv.header.size(); ++j) {
    const std::string& h = csv.header[j];
    const std::string where = path + ": column " + std::to_string(j + 1) + " \"" + h + "\"";
    if (h.empty()) throw InputError(where + " has no name; allowed: a case key (section.key), paper.<name> or label");
    if (!seen.insert(h).second) throw InputError(where + " appears twice; allowed: each column once");
    if (h == "label" || (h.rfind("paper.", 0) == 0 && h.size() > 6)) continue;
    if (h == "output.dir")
      throw InputError(where + ": each row writes to <sweep directory>/row-NN; allowed: --out for the sweep's "
                       "directory, any other case key as a column");
    if (std::find(keys.begin(), keys.end(), h) == keys.end()) {
      std::string known;
      for (const auto& k : keys) known += (known.empty() ? "" : ", ") + k;
      throw InputError(where + " is not a case key; allowed: label, paper.<name>, " + known);
    }
  }
}

std::string row_dir(const std::string& out_dir, std::size_t i) {
  char name[32];
  std::snprintf(name, sizeof name, "row-%02zu", i + 1);
  return (fs::path(out_dir) / name).string();
}

// The rows' cases, validated: the sweep's defaults (no pictures unless
// --keep-outputs) first, so that a row's own output.png / output.vtu wins.
std::vector<SweepRow> read_rows(const CaseSource& source, const CsvTable& csv, const std::string& rows_csv,
                                const SweepOptions& options, const std::string& out_dir) {
  std::vector<SweepRow> rows;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    SweepRow row;
    std::vector<std::string> sets = options.overrides;
    if (!options.keep_outputs) sets.insert(sets.end(), {"output.png=false", "output.vtu=false"});
    for (std::size_t j = 0; j < csv.header.size(); ++j) {
      const std::string& key = csv.header[j];
      const std::string& value = csv.rows[i][j];
      if (key.rfind("paper.", 0) == 0) row.paper[key.substr(6)] = value;
      else if (key == "label") row.paper["label"] = value;
      else if (!value.empty()) sets.push_back(key + "=" + value);
    }
    try {
      row.c = source.load(sets, row_dir(out_dir, i));
    } catch (const InputError& e) {
      throw InputError(rows_csv + ": row " + std::to_string(i + 1) + " (line " + std::to_string(csv.line_of_row[i]) +
                       "): " + e.what());
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// Every row's meshes, built (and kept for the runs) and checked against its case
// before anything is written: a bad mesh file in row 7 is found before row 1 runs.
// A failure to mesh valid geometry is left to that row's run, which records it.
void check_row_meshes(const std::vector<SweepRow>& rows, SetupCache& cache, const std::string& rows_csv) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    try {
      cache.structure_mesh(rows[i].c);
      if (rows[i].c.fluid) cache.fluid_mesh(rows[i].c);
    } catch (const InputError& e) {
      throw InputError(rows_csv + ": row " + std::to_string(i + 1) + ": " + e.what());
    } catch (const SolverFailure&) {
    }
  }
}

// The sweep's own summary.json: what was run and how each row ended.
Json sweep_summary(const std::string& case_path, const std::string& rows_csv, const std::vector<SweepRow>& rows,
                   const SweepResult& r, const char* status) {
  Json j = {{"problem", "sweep"}, {"case", case_path}, {"rows_file", rows_csv}, {"status", status}};
  j["rows"] = rows.size();
  j["converged"] = r.converged;
  j["not_converged"] = r.not_converged;
  j["failed"] = r.failed;
  Json statuses = Json::array();
  for (const auto& row : rows) statuses.push_back(row.status);
  j["row_status"] = statuses;
  return j;
}

// The sweep's directory before the first row: created, marked "writing", cleared of
// an earlier sweep's tables and of rows beyond this sweep's count.
void begin_sweep_dir(const std::string& out_dir, std::size_t rows, const Json& header) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw OutputError(out_dir, ec.value());
  Json marked = header;
  marked["program"] = provenance_json();
  write_json((fs::path(out_dir) / "summary.json").string(), marked);
  remove_stale_outputs(out_dir, "summary.json");
  std::vector<std::string> keep;
  for (std::size_t i = 0; i < rows; ++i) keep.push_back(fs::path(row_dir(out_dir, i)).filename().string());
  remove_stale_subdirs(out_dir, "row-", keep);
}

std::string status_of(const RunResult& r, SweepResult& result) {
  std::string status;
  if (r.exit_status == 1) status = "failed: " + r.failure, ++result.failed;
  else if (r.exit_status > 128) status = "interrupted", result.interrupted_by = r.exit_status - 128;
  else if (r.exit_status == 3) status = "not converged", ++result.not_converged;
  else status = "converged", ++result.converged;
  if (!r.measures.convergence_warning.empty()) status += ", unsettled (see its history.csv)";
  return status;
}

}  // namespace

int SweepResult::exit_status() const {
  if (interrupted_by) return 128 + interrupted_by;
  if (failed) return 1;
  return not_converged ? 3 : 0;
}

SweepResult run_sweep(const CaseSource& source, const std::string& rows_csv, const SweepOptions& options) {
  const CsvTable csv = read_csv(rows_csv);
  check_header(csv, rows_csv);
  const Case base = source.load(options.overrides);
  SweepResult result;
  result.out_dir = options.out_dir.empty() ? "out/" + base.name + "-sweep" : options.out_dir;
  check_output_dir(result.out_dir, options.out_dir.empty() ? base.source + " (name)" : "--out");
  std::vector<SweepRow> rows = read_rows(source, csv, rows_csv, options, result.out_dir);
  SetupCache cache;
  check_row_meshes(rows, cache, rows_csv);

  // Nothing was written so far. Rows run grouped by fluid mesh (each mesh and its
  // setup built once) and are reported in the file's order.
  begin_sweep_dir(result.out_dir, rows.size(), sweep_summary(source.name(), rows_csv, rows, result, "writing"));
  std::vector<std::size_t> order(rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const std::string ka = rows[a].c.fluid ? fluid_mesh_key(rows[a].c) : "";
    const std::string kb = rows[b].c.fluid ? fluid_mesh_key(rows[b].c) : "";
    return ka < kb;
  });
  for (std::size_t i : order) {
    if (interrupt_requested()) {
      result.interrupted_by = interrupt_signal();
      break;
    }
    const Stopwatch clock;
    RunOptions run_options;
    run_options.cache = &cache;
    run_options.keep_fields = options.keep_fields && options.on_row;  // nobody to hand them to otherwise
    const std::string prefix = "[row " + std::to_string(i + 1) + "] ";
    if (options.progress) run_options.progress = [&, prefix](const std::string& l) { options.progress(prefix + l); };
    const RunResult r = run_case(rows[i].c, run_options);
    rows[i].measures = r.measures;
    rows[i].status = status_of(r, result);
    rows[i].wall_s = clock.elapsed();
    ++result.rows;
    if (options.progress) options.progress(prefix + (r.exit_status == 1 ? rows[i].status : r.report));
    if (options.on_row) options.on_row(i, rows[i].c.output.dir, r);
  }

  result.table_markdown = sweep_table_markdown(rows);
  write_atomically((fs::path(result.out_dir) / "table.md").string(), [&](std::ostream& o) { o << result.table_markdown; });
  write_atomically((fs::path(result.out_dir) / "table.csv").string(), [&](std::ostream& o) { o << sweep_table_csv(rows); });
  Json summary = sweep_summary(source.name(), rows_csv, rows, result, result.interrupted_by ? "interrupted" : "complete");
  summary["program"] = provenance_json();  // what made it (issue 31)
  summary["ranks"] = launched_ranks();       // SPEC §13
  write_json((fs::path(result.out_dir) / "summary.json").string(), summary);
  return result;
}

}  // namespace fsi
