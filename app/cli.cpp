#include "cli.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <sstream>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/launch.hpp"
#include "io/case.hpp"
#include "run/provenance.hpp"
#include "run/run_case.hpp"
#include "run/sweep.hpp"
#include "study/converge.hpp"

namespace fsi {
namespace {

struct Streams {
  std::ostream& out;
  std::ostream& err;
};

// --resume DIR writes into DIR (it continues the run there): --out may name it too.
std::string resumed_out_dir(const std::string& resume, const std::string& out_dir) {
  if (resume.empty()) return out_dir;
  if (!out_dir.empty() && out_dir != resume)
    throw InputError("--resume " + resume + " writes into that directory; --out " + out_dir +
                     " names another (omit --out, or give the same directory)");
  return resume;
}

int run_command(const std::string& case_path, const std::vector<std::string>& sets, const std::string& out_dir,
                const std::string& resume, bool quiet, Streams io) {
  // --out taken verbatim, never parsed
  const Case c = load_case(case_path, sets, resumed_out_dir(resume, out_dir));
  RunOptions options;
  options.resume_dir = resume;
  if (!quiet) options.progress = [&io](const std::string& line) { io.err << line << '\n'; };
  const RunResult r = run_case(c, options);
  if (!r.report.empty()) io.out << r.report << std::endl;  // the numbers, even after a failure
  if (r.exit_status == 1) io.err << "fsicontact: failed: " << r.failure << std::endl;
  return r.exit_status;
}

int sweep_command(const std::string& case_path, const std::string& rows, const std::vector<std::string>& sets,
                  const std::string& out_dir, bool keep_outputs, bool quiet, Streams io) {
  SweepOptions options;
  options.overrides = sets;
  options.out_dir = out_dir;
  options.keep_outputs = keep_outputs;
  if (!quiet) options.progress = [&io](const std::string& line) { io.err << line << '\n'; };
  const SweepResult r = run_sweep(case_path, rows, options);
  io.out << r.table_markdown << '\n'
         << r.rows << " rows: " << r.converged << " converged, " << r.not_converged
         << " reached the iteration limit, " << r.failed << " failed"
         << (r.interrupted_by ? "; interrupted, the tables hold the rows run so far" : "") << ". Tables in "
         << r.out_dir << "/ (table.md, table.csv, summary.json; one directory per row)." << std::endl;
  return r.exit_status();
}

// --schemes "all" | a comma-separated list.
std::vector<std::string> scheme_list(const std::string& text) {
  if (text.empty()) return {};
  if (text == "all") return {"constant", "aitken", "iqn-ils"};
  std::vector<std::string> list;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    list.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return list;
}

int converge_command(const std::string& case_path, const std::vector<std::string>& sets, const std::string& out_dir,
                     int levels, double ratio, const std::string& schemes, const std::string& refine, bool quiet,
                     Streams io) {
  ConvergeOptions options;
  options.overrides = sets;
  options.out_dir = out_dir;
  options.levels = levels;
  options.ratio = ratio;
  options.schemes = scheme_list(schemes);
  options.refine = refine;
  if (!quiet) options.progress = [&io](const std::string& line) { io.err << line << '\n'; };
  const ConvergeResult r = run_convergence(case_path, options);
  io.out << r.report << "\nResults in " << r.out_dir << "/ (convergence.md, convergence.csv, convergence.png, "
         << "summary.json; one directory per level)." << std::endl;
  return r.exit_status;
}

// The values of the command line, bound to CLI11's options; --set, --out and
// --quiet are shared by the subcommands.
struct CliArgs {
  std::string case_path, out_dir, resume;
  std::vector<std::string> sets;
  bool quiet = false;
  std::string sweep_case, sweep_rows;
  bool keep_outputs = false;
  std::string converge_case, schemes, refine = "all";
  int levels = 3;
  double ratio = 2;
};

void add_run_command(CLI::App& app, CliArgs& a) {
  CLI::App* run = app.add_subcommand("run", "run one case (default: the paper's section 7.2 case)");
  run->add_option("case", a.case_path, "case file (TOML); omit for the paper's section 7.2 case");
  run->add_option("--set", a.sets, "override a case key: section.key=value")->type_name("KEY=VALUE");
  run->add_option("--out", a.out_dir, "output directory (overrides output.dir; taken as it is)");
  run->add_option("--resume", a.resume,
                  "continue a time run from the checkpoint in this output directory (written at its end, when "
                  "stopped, and every time.checkpoint_every steps), writing there")
      ->type_name("DIR");
  run->add_flag("-q,--quiet", a.quiet, "no progress lines on stderr");
}

CLI::App* add_sweep_command(CLI::App& app, CliArgs& a) {
  CLI::App* sweep = app.add_subcommand("sweep", "run one case per row of a CSV file (e.g. the paper's Table 1)");
  sweep->add_option("case", a.sweep_case, "base case file (TOML)")->required();
  sweep->add_option("rows", a.sweep_rows, "CSV: headers are section.key overrides; paper.* columns are references")->required();
  sweep->add_option("--set", a.sets, "override a key in every row: section.key=value")->type_name("KEY=VALUE");
  sweep->add_option("--out", a.out_dir, "output directory (default out/<name>-sweep)");
  sweep->add_flag("--keep-outputs", a.keep_outputs, "write each row's .vtu and .png too");
  sweep->add_flag("-q,--quiet", a.quiet, "no progress lines on stderr");
  return sweep;
}

CLI::App* add_converge_command(CLI::App& app, CliArgs& a) {
  CLI::App* converge = app.add_subcommand(
      "converge", "run a case on refined levels: observed order, Richardson extrapolation and GCI per quantity");
  converge->add_option("case", a.converge_case, "case file (TOML)")->required();
  converge->add_option("--levels", a.levels, "number of levels, the case itself the coarsest (3 to 10; default 3)");
  converge->add_option("--ratio", a.ratio, "size ratio between consecutive levels (default 2)");
  converge->add_option("--schemes", a.schemes,
                       "coupling schemes run at every level, the first gives the values: a list "
                       "(constant,aitken,iqn-ils) or all (default: the case's own)");
  converge->add_option("--refine", a.refine,
                       "which meshes the levels refine: all (default), fluid (fluid.h, fluid.h_near, eps by its rule) "
                       "or structure (structure.h); the other stays as given");
  converge->add_option("--set", a.sets, "override a key on every level: section.key=value")->type_name("KEY=VALUE");
  converge->add_option("--out", a.out_dir, "output directory (default out/<name>-converge)");
  converge->add_flag("-q,--quiet", a.quiet, "no progress lines on stderr");
  return converge;
}

// Runs the parsed subcommand (run when neither sweep nor converge) and maps its
// errors to exit statuses.
int run_subcommand(const CliArgs& a, const CLI::App& sweep, const CLI::App& converge, Streams io) {
  try {
    if (sweep.parsed()) return sweep_command(a.sweep_case, a.sweep_rows, a.sets, a.out_dir, a.keep_outputs, a.quiet, io);
    if (converge.parsed())
      return converge_command(a.converge_case, a.sets, a.out_dir, a.levels, a.ratio, a.schemes, a.refine, a.quiet, io);
    return run_command(a.case_path, a.sets, a.out_dir, a.resume, a.quiet, io);
  } catch (const InputError& e) {
    io.err << "fsicontact: error: " << e.what() << std::endl;
    return 2;
  } catch (const SolverFailure& e) {
    io.err << "fsicontact: failed: " << e.what() << std::endl;
    return 1;
  } catch (const OutputError& e) {
    io.err << "fsicontact: failed: " << e.what() << std::endl;
    return 1;
  } catch (const std::bad_alloc&) {
    io.err << "fsicontact: failed: out of memory" << std::endl;
    return 1;
  }
}

// Under mpirun every rank runs the whole command, so that each takes part in the
// fluid's distributed solves (SPEC §13); the ranks but 0 print nothing and write into
// a directory of their own, removed at the end, so that the outputs are rank 0's
// alone. Their computations are the same as rank 0's, so they fail where it fails.
int run_on_other_rank(CliArgs a, const CLI::App& sweep, const CLI::App& converge, std::ostream& err) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path own = fs::temp_directory_path(ec) / ("fsicontact-rank-" + std::to_string(launched_rank()) + "-" +
                                                     std::to_string(::getpid()));
  if (ec || !fs::create_directories(own, ec)) {  // mpirun then ends every rank
    err << "fsicontact: failed: rank " << launched_rank() << " cannot create its private directory " << own
        << " for the outputs it discards: " << ec.message() << " (is TMPDIR writable?)\n";
    return 1;
  }
  a.out_dir = own.string();
  a.quiet = true;
  std::ostringstream ignored;
  const int status = run_subcommand(a, sweep, converge, Streams{ignored, ignored});
  fs::remove_all(own, ec);
  return status;
}

}  // namespace

int fsicontact_main(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"fsicontact: fluid-structure interaction with contact against a rigid obstacle (Murea 2017)"};
  app.require_subcommand(0, 1);
  // The version, the commit and the libraries (run/provenance.hpp), as summary.json's "program".
  std::string version = provenance_text();
  version.pop_back();  // CLI11 ends the line itself
  app.set_version_flag("--version", version, "print the version, the commit and the libraries, and exit");
  CliArgs args;
  add_run_command(app, args);
  CLI::App* sweep = add_sweep_command(app, args);
  CLI::App* converge = add_converge_command(app, args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e, out, err) == 0 ? 0 : 2;
  }
  if (app.get_subcommands().empty()) {
    err << app.help();
    return 2;
  }
  const int ranks = launched_ranks();
  if (ranks > 1 && !args.resume.empty()) {
    err << "fsicontact: error: --resume runs on one rank; this run has " << ranks << " (start it without mpirun)\n";
    return 2;
  }
  install_interrupt_handler();
  if (ranks > 1 && launched_rank() > 0) return run_on_other_rank(args, *sweep, *converge, err);
  return run_subcommand(args, *sweep, *converge, Streams{out, err});
}

}  // namespace fsi
