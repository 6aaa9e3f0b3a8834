#include "run/provenance.hpp"

#include <CGAL/version_macros.h>
#include <coin/IpoptConfig.h>
#include <dmumps_c.h>
#include <gif_lib.h>
#include <gmsh.h>
#include <SuiteSparse_config.h>

#include <Eigen/Core>
#include <toml++/impl/version.h>

#include "common/huge_pages.hpp"
#include "fsicontact_commit.hpp"  // generated: cmake/Commit.cmake

namespace fsi {
namespace {

std::string dotted(int a, int b, int c) {
  return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c);
}

}  // namespace

const Provenance& provenance() {
  static const Provenance p{
      FSICONTACT_VERSION,
      FSICONTACT_COMMIT,
      {{"MUMPS", MUMPS_VERSION},
       {"IPOPT", IPOPT_VERSION},
       {"Gmsh API", GMSH_API_VERSION},  // the SDK headers (the plugin, src/mesh/gmsh_plugin.cpp)
       {"CGAL", CGAL_VERSION_STR},
       {"Eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
       {"SuiteSparse", dotted(SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION)},
       {"toml++", dotted(TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH)},
       {"nlohmann-json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
       {"giflib", dotted(GIFLIB_MAJOR, GIFLIB_MINOR, GIFLIB_RELEASE)}}};
  return p;
}

Json provenance_json() {
  const Provenance& p = provenance();
  Json libraries = Json::object();
  for (const auto& [name, version] : p.libraries) libraries[name] = version;
  return {{"version", p.version}, {"commit", p.commit}, {"libraries", libraries}, {"huge_pages", uses_huge_pages()}};
}

std::string provenance_text() {
  const Provenance& p = provenance();
  std::string text = "fsicontact " + p.version + " (commit " + p.commit + ")\nbuilt with";
  for (std::size_t i = 0; i < p.libraries.size(); ++i)
    text += std::string(i ? ", " : " ") + p.libraries[i].first + " " + p.libraries[i].second;
  return text + "\n";
}

}  // namespace fsi
