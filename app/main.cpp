// fsicontact command line: parses arguments, runs, maps errors to exit statuses
// (SPEC §8: 0 converged, 1 solver failure, 2 invalid input, 3 iteration limit).
// No numerics here.
#include <CLI/CLI.hpp>
#include <iostream>

#include "common/interrupt.hpp"
#include "io/case.hpp"
#include "common/errors.hpp"
#include "run/run_case.hpp"
#include "run/sweep.hpp"

namespace {

int run_command(const std::string& case_path, const std::vector<std::string>& sets,
                const std::string& out_dir, bool quiet) {
  std::vector<std::string> overrides = sets;
  if (!out_dir.empty()) overrides.push_back("output.dir=\"" + out_dir + "\"");
  const fsi::Case c = fsi::load_case(case_path, overrides);
  fsi::RunOptions options;
  if (!quiet) options.progress = [](const std::string& line) { std::cerr << line << '\n'; };
  const fsi::RunResult r = fsi::run_case(c, options);
  std::cout << r.report << std::endl;
  return r.exit_status;
}

int sweep_command(const std::string& case_path, const std::string& rows, const std::vector<std::string>& sets,
                  const std::string& out_dir, bool keep_outputs, bool quiet) {
  fsi::SweepOptions options;
  options.overrides = sets;
  options.out_dir = out_dir;
  options.keep_outputs = keep_outputs;
  if (!quiet) options.progress = [](const std::string& line) { std::cerr << line << '\n'; };
  const fsi::SweepResult r = fsi::run_sweep(case_path, rows, options);
  std::cout << r.table_markdown << '\n'
            << r.rows << " rows: " << r.converged << " converged, " << r.not_converged
            << " reached the iteration limit, " << r.failed << " failed"
            << (r.interrupted ? "; interrupted (Ctrl-C), the tables hold the rows run so far" : "")
            << ". Tables in " << r.out_dir << "/ (table.md, table.csv; one directory per row)." << std::endl;
  if (r.interrupted) return fsi::kInterruptedExitStatus;
  return r.failed > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fsicontact: fluid-structure interaction with contact against a rigid obstacle "
               "(Murea 2017)"};
  app.require_subcommand(0, 1);
  std::string case_path, out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  CLI::App* run = app.add_subcommand("run", "run one case (default: the paper's section 7.2 case)");
  run->add_option("case", case_path, "case file (TOML); omit for the paper's section 7.2 case");
  run->add_option("--set", sets, "override a case key: section.key=value")->type_name("KEY=VALUE");
  run->add_option("--out", out_dir, "output directory (overrides output.dir)");
  run->add_flag("-q,--quiet", quiet, "no progress lines on stderr");
  std::string sweep_case, sweep_rows;
  bool keep_outputs = false;
  CLI::App* sweep = app.add_subcommand("sweep", "run one case per row of a CSV file (e.g. the paper's Table 1)");
  sweep->add_option("case", sweep_case, "base case file (TOML)")->required();
  sweep->add_option("rows", sweep_rows, "CSV: headers are section.key overrides; paper.* columns are references")->required();
  sweep->add_option("--set", sets, "override a key in every row: section.key=value")->type_name("KEY=VALUE");
  sweep->add_option("--out", out_dir, "output directory (default out/<name>-sweep)");
  sweep->add_flag("--keep-outputs", keep_outputs, "write each row's .vtu and .png too");
  sweep->add_flag("-q,--quiet", quiet, "no progress lines on stderr");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  fsi::install_interrupt_handler();
  if (app.get_subcommands().empty()) {
    std::cerr << app.help();
    return 2;
  }
  try {
    if (sweep->parsed()) return sweep_command(sweep_case, sweep_rows, sets, out_dir, keep_outputs, quiet);
    return run_command(case_path, sets, out_dir, quiet);
  } catch (const fsi::InputError& e) {
    std::cerr << "fsicontact: error: " << e.what() << std::endl;
    return 2;
  } catch (const fsi::SolverFailure& e) {
    std::cerr << "fsicontact: solver failure: " << e.what() << std::endl;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fsicontact: internal error: " << e.what() << std::endl;
    return 1;
  }
}
