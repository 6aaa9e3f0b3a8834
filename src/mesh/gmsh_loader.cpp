// Loads libfsicontact_gmsh.so (gmsh_model.hpp) on first use.
#include <dlfcn.h>

#include <mutex>
#include <string>

#include "mesh/gmsh_model.hpp"
#include "mesh/mesh_error.hpp"

namespace fsi {
namespace {

// Where the build put the plugin (src/CMakeLists.txt); else the loader's search path.
#ifdef FSICONTACT_GMSH_PLUGIN
constexpr const char* kPluginPath = FSICONTACT_GMSH_PLUGIN;
#else
constexpr const char* kPluginPath = "libfsicontact_gmsh.so";
#endif

const GmshPlugin* load() {
  void* library = ::dlopen(kPluginPath, RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = ::dlerror();
    throw MeshError(
        std::string("cannot load the Gmsh plugin ") + kPluginPath + ": " +
        (why ? why : "unknown error") +
        " (rebuild with make build; Gmsh itself comes from the Debian package libgmsh-dev)");
  }
  using Entry = const GmshPlugin* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(library, "fsicontact_gmsh_plugin"));
  const GmshPlugin* plugin = entry ? entry() : nullptr;
  if (!plugin || plugin->version != kGmshPluginVersion)
    throw MeshError(std::string("the Gmsh plugin ") + kPluginPath +
                    " is of another build (rebuild with make build)");
  if (const std::string error = plugin->initialise(); !error.empty())
    throw MeshError("cannot initialise Gmsh: " + error);
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
