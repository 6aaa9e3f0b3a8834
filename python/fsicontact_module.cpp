// The Python module's native part, fsicontact._fsicontact (issue 31): a case run, a
// sweep or a convergence study through the command line's own path (one validation,
// the same messages and summary.json), with the GIL released while it solves, progress
// lines handed to a Python callable, Ctrl-C stopping the run after its current
// iteration as SIGINT stops the program, and each run's final fields as NumPy arrays.
// Errors become the exceptions python/fsicontact/__init__.py defines.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "io/case.hpp"
#include "run/provenance.hpp"
#include "run/run_case.hpp"
#include "run/sweep.hpp"
#include "study/converge.hpp"

namespace py = pybind11;

namespace {

// Points as an (n, 2) array.
py::array_t<double> points(const std::vector<fsi::Point>& p) {
  py::array_t<double> a({static_cast<py::ssize_t>(p.size()), py::ssize_t{2}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < p.size(); ++i) m(i, 0) = p[i].x(), m(i, 1) = p[i].y();
  return a;
}

// A VTU field as (n,) for a scalar, (n, 2) for a vector (VTK pads 2D vectors to 3).
py::array_t<double> field_values(const fsi::VtuField& f) {
  const auto n = static_cast<py::ssize_t>(f.values.size() / f.components);
  if (f.components == 1) return py::array_t<double>(n, f.values.data());
  py::array_t<double> a({n, py::ssize_t{2}});
  auto m = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) m(i, 0) = f.values[i * f.components], m(i, 1) = f.values[i * f.components + 1];
  return a;
}

py::object arrays(const std::optional<fsi::FieldArrays>& a) {
  if (!a) return py::none();
  py::dict d;
  d["vertices"] = points(a->vertices);
  if (!a->deformed.empty()) d["deformed"] = points(a->deformed);
  d["triangles"] = py::array_t<int>({static_cast<py::ssize_t>(a->cells.rows()), static_cast<py::ssize_t>(a->cells.cols())},
                                    a->cells.data());
  for (const fsi::VtuField& f : a->fields) d[py::str(f.name)] = field_values(f);
  return d;
}

// What the Python side builds a Result from; the summary as JSON text (its numbers
// written to the digit, read back by json.loads to the same doubles).
py::dict run_dict(const fsi::RunResult& r, const std::string& out_dir) {
  py::dict d;
  d["exit_status"] = r.exit_status;
  d["summary"] = r.summary.dump();
  d["report"] = r.report;
  d["failure"] = r.failure;
  d["out_dir"] = out_dir;
  d["structure"] = arrays(r.fields.structure);
  d["fluid"] = arrays(r.fields.fluid);
  return d;
}

// A line handler calling `progress` (None: no handler) with the GIL held; a Python
// exception there ends the run as a failure naming it.
std::function<void(const std::string&)> progress_lines(const py::object& progress) {
  if (progress.is_none()) return {};
  return [&progress](const std::string& line) {
    py::gil_scoped_acquire gil;
    progress(line);
  };
}

// `solve` with the GIL released and Ctrl-C as SIGINT; whether it was interrupted.
template <class Solve>
bool solve_released(Solve&& solve) {
  {
    py::gil_scoped_release release;
    fsi::clear_interrupt();
    const fsi::ScopedInterruptHandler sigint;
    solve();
  }
  const bool interrupted = fsi::interrupt_requested();
  fsi::clear_interrupt();
  return interrupted;
}

fsi::CaseSource source(const std::string& case_text, const std::string& origin, bool is_path) {
  return is_path ? fsi::CaseSource(case_text) : fsi::CaseSource::text_named(case_text, origin);
}

py::dict run(const std::string& case_text, const std::string& origin, bool is_path,
             const std::vector<std::string>& sets, const std::string& out, const py::object& progress, bool fields) {
  const fsi::Case c = source(case_text, origin, is_path).load(sets, out);
  fsi::RunOptions options;
  options.progress = progress_lines(progress);
  options.keep_fields = fields;
  fsi::RunResult r;
  const bool interrupted = solve_released([&] { r = fsi::run_case(c, options); });
  py::dict d = run_dict(r, c.output.dir);
  d["interrupted"] = interrupted;
  return d;
}

// Each row's or level's result dict, as it ends, under its key (the GIL held).
struct Collected {
  py::dict runs;
  template <class Key>
  void add(const Key& key, const fsi::RunResult& r, const std::string& out_dir) {
    py::gil_scoped_acquire gil;
    runs[py::cast(key)] = run_dict(r, out_dir);
  }
};

py::dict sweep(const std::string& case_text, const std::string& origin, bool is_path, const std::string& rows,
               const std::vector<std::string>& sets, const std::string& out, bool keep_outputs,
               const py::object& progress, bool fields) {
  fsi::SweepOptions options;
  options.overrides = sets;
  options.out_dir = out;
  options.keep_outputs = keep_outputs;
  options.progress = progress_lines(progress);
  options.keep_fields = fields;
  Collected rows_run;
  fsi::SweepResult r;
  options.on_row = [&](std::size_t i, const std::string& dir, const fsi::RunResult& row) { rows_run.add(i, row, dir); };
  const bool interrupted = solve_released([&] { r = fsi::run_sweep(source(case_text, origin, is_path), rows, options); });
  py::dict d;
  d["exit_status"] = r.exit_status();
  d["out_dir"] = r.out_dir;
  d["report"] = r.table_markdown;
  d["runs"] = rows_run.runs;
  d["interrupted"] = interrupted;
  return d;
}

py::dict converge(const std::string& case_text, const std::string& origin, bool is_path,
                  const std::vector<std::string>& sets, const std::string& out, int levels, double ratio,
                  const std::vector<std::string>& schemes, const std::string& refine, const py::object& progress,
                  bool fields) {
  fsi::ConvergeOptions options;
  options.overrides = sets;
  options.out_dir = out;
  options.levels = levels;
  options.ratio = ratio;
  options.schemes = schemes;
  options.refine = refine;
  options.progress = progress_lines(progress);
  options.keep_fields = fields;
  Collected runs;
  fsi::ConvergeResult r;
  options.on_run = [&](const std::string& dir, const fsi::RunResult& run) {
    runs.add(std::filesystem::path(dir).filename().string(), run, dir);
  };
  const bool interrupted = solve_released([&] { r = fsi::run_convergence(source(case_text, origin, is_path), options); });
  py::dict d;
  d["exit_status"] = r.exit_status;
  d["summary"] = r.summary.dump();
  d["out_dir"] = r.out_dir;
  d["report"] = r.report;
  d["runs"] = runs.runs;
  d["interrupted"] = interrupted;
  return d;
}

}  // namespace

PYBIND11_MODULE(_fsicontact, m) {
  m.doc() = "fsicontact's native part: use the fsicontact package (fsicontact.run, sweep, converge).";
  static py::exception<fsi::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<fsi::SolverFailure> solver_failure(m, "SolverFailure", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fsi::InputError& e) {
      input_error(e.what());
    } catch (const fsi::SolverFailure& e) {
      solver_failure(e.what());
    } catch (const fsi::OutputError& e) {
      solver_failure(e.what());
    }
  });
  m.def("run", &run, py::arg("case"), py::arg("origin"), py::arg("is_path"), py::arg("sets"), py::arg("out"),
        py::arg("progress"), py::arg("fields"));
  m.def("sweep", &sweep, py::arg("case"), py::arg("origin"), py::arg("is_path"), py::arg("rows"), py::arg("sets"),
        py::arg("out"), py::arg("keep_outputs"), py::arg("progress"), py::arg("fields"));
  m.def("converge", &converge, py::arg("case"), py::arg("origin"), py::arg("is_path"), py::arg("sets"), py::arg("out"),
        py::arg("levels"), py::arg("ratio"), py::arg("schemes"), py::arg("refine"), py::arg("progress"),
        py::arg("fields"));
  m.def("version", [] { return fsi::provenance_text(); });
}
