// fsicontact command line: parses arguments, runs, maps errors to exit statuses
// (SPEC §8: 0 converged, 1 solver failure, 2 invalid input, 3 iteration limit).
// No numerics here.
#include <CLI/CLI.hpp>
#include <iostream>

#include "io/case.hpp"
#include "io/errors.hpp"
#include "run/run_case.hpp"

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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (app.get_subcommands().empty()) {
    std::cerr << app.help();
    return 2;
  }
  try {
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
