// What made a result (issue 31): the program's version, the commit it was built from,
// and the versions of the libraries it was built with (the Debian packages' headers:
// the .deb's dependencies name the same packages). `fsicontact --version` prints it,
// and every summary.json carries it as "program", so that a result can be traced to
// the program that made it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "run/outputs/summary.hpp"  // Json

namespace fsi {

struct Provenance {
  std::string version;  // the project's (CMakeLists.txt)
  std::string commit;   // git describe at build time; "unknown" outside a checkout
  std::vector<std::pair<std::string, std::string>> libraries;  // name, version
};

const Provenance& provenance();
// {"version", "commit", "libraries": {name: version}}: summary.json's "program".
Json provenance_json();
// The lines of `fsicontact --version`.
std::string provenance_text();

}  // namespace fsi
