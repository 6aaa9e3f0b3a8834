// The Python module's native part, fsicontact._fsicontact (issue 31): one case run
// through the command line's own path (load_case → run_case: one validation, the same
// messages), with the GIL released while it solves, progress lines handed to a Python
// callable, and Ctrl-C stopping the run after its current iteration as SIGINT stops the
// program. Errors become the exceptions python/fsicontact/__init__.py defines.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <new>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "io/case.hpp"
#include "run/provenance.hpp"
#include "run/run_case.hpp"

namespace py = pybind11;

namespace {

// What the Python side builds its Result from; the summary as JSON text (its numbers
// written to the digit, read back by json.loads to the same doubles).
py::dict run(const std::string& case_text, const std::string& origin, bool is_path,
             const std::vector<std::string>& sets, const std::string& out, const py::object& progress) {
  fsi::Case c = is_path ? fsi::load_case(case_text, sets, out) : fsi::load_case_text(case_text, origin, sets, out);
  fsi::RunOptions options;
  if (!progress.is_none())
    options.progress = [&progress](const std::string& line) {
      py::gil_scoped_acquire gil;
      progress(line);  // a Python exception here ends the run as a failure naming it
    };
  fsi::RunResult r;
  {
    py::gil_scoped_release release;
    fsi::clear_interrupt();
    const fsi::ScopedInterruptHandler sigint;
    r = fsi::run_case(c, options);
  }
  py::dict d;
  d["exit_status"] = r.exit_status;
  d["summary"] = r.summary.dump();
  d["report"] = r.report;
  d["failure"] = r.failure;
  d["out_dir"] = c.output.dir;
  d["interrupted"] = fsi::interrupt_requested();
  fsi::clear_interrupt();
  return d;
}

}  // namespace

PYBIND11_MODULE(_fsicontact, m) {
  m.doc() = "fsicontact's native part: use the fsicontact package (fsicontact.run).";
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
        py::arg("progress"));
  m.def("version", [] { return fsi::provenance_text(); });
}
