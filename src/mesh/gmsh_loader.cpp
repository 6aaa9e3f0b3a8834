// Loads libfsicontact_gmsh.so (gmsh_model.hpp) on first use (common/plugin_loader.hpp:
// where it is looked for). A plugin missing or broken is the installation's failure,
// not the input's: a SolverFailure (exit 1), which the callers that make a mesh error
// an input error (a user's .geo or .msh) let through.
#include <mutex>
#include <string>

#include "common/errors.hpp"
#include "common/plugin_loader.hpp"
#include "mesh/gmsh_model.hpp"

namespace fsi {
namespace {

const GmshPlugin* load() {
  const GmshPlugin* plugin =
      load_plugin_table<GmshPlugin>("libfsicontact_gmsh.so", "fsicontact_gmsh_plugin", "the Gmsh plugin",
                                    "Gmsh itself comes from the Debian package libgmsh-dev", kGmshPluginVersion);
  if (const std::string error = plugin->initialise(); !error.empty())
    throw SolverFailure("cannot initialise Gmsh: " + error);
  return plugin;  // never unloaded: Gmsh keeps its state for the process
}

}  // namespace

const GmshPlugin& gmsh_plugin() {
  static std::once_flag once;
  static const GmshPlugin* plugin = nullptr;
  std::call_once(once,
                 [] { plugin = load(); });  // a throw leaves the flag unset: the next call retries
  return *plugin;
}

}  // namespace fsi
