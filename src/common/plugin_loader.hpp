// Finding and loading our plugins (libfsicontact_<name>.so: Gmsh, PETSc), libraries
// that link a large dependency and are loaded (dlopen) only by the runs that need it,
// so that the others do not pay for loading it (docs/performance.md, "Start-up").
//
// A plugin lives where the program (or the module holding this code: the Python
// module) lives: <dir>/../lib/fsicontact/, the layout of both the build tree
// (build/app/fsicontact, build/lib/fsicontact/) and an install (P/bin/fsicontact,
// P/lib/fsicontact/), so that an installed program moved anywhere finds its own
// plugins and never a build tree's (no build path is compiled in).
#pragma once

#include <string>

#include "common/errors.hpp"

namespace fsi {

// dlopen of the first candidate that exists, RTLD_NOW | RTLD_LOCAL; `what` names it in
// errors ("the Gmsh plugin") and `package` says where its dependency comes from. A
// plugin missing or broken is the installation's failure, not the input's:
// SolverFailure (exit 1). `path` receives the file loaded. Never unloaded.
// `deep_bind`: RTLD_DEEPBIND, the plugin and its libraries bound to their own symbols
// before the program's (fluid/petsc_solver.cpp says why).
void* open_plugin(const std::string& file, const std::string& what, const std::string& package, std::string& path,
                  bool deep_bind = false);

// The plugin's entry point `symbol` (a function taking nothing), or SolverFailure.
void* plugin_symbol(void* library, const char* symbol, const std::string& what, const std::string& path);

// The plugin's table of functions: the library opened (open_plugin), its entry point
// `symbol` called, the table's `version` checked against the program's (SolverFailure
// for a plugin of another build).
template <class Table>
const Table* load_plugin_table(const std::string& file, const char* symbol, const std::string& what,
                               const std::string& package, int version, bool deep_bind = false) {
  std::string path;
  void* library = open_plugin(file, what, package, path, deep_bind);
  using Entry = const Table* (*)();
  const Table* table = reinterpret_cast<Entry>(plugin_symbol(library, symbol, what, path))();
  if (!table || table->version != version)
    throw SolverFailure(what + " " + path + " is of another build (rebuild with make program, or reinstall)");
  return table;
}

}  // namespace fsi
