// The layers point down (STYLE: mesh → fem → solid/fluid → coupling → run → study): no
// file of src/<layer>/ includes a header of a layer that is not below it. The build
// links each layer only to those below (src/CMakeLists.txt), which catches upward
// calls; this catches upward includes of header-only code as well.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace fsi::layering_test {
namespace {

namespace fs = std::filesystem;

// Each layer and the layers it may use (the same table as src/CMakeLists.txt).
const std::map<std::string, std::set<std::string>> kBelow = {
    {"common", {}},
    {"qp", {"common"}},
    {"mesh", {"common"}},
    {"fem", {"mesh", "common"}},
    {"solid", {"common", "fem", "mesh", "qp"}},
    {"fluid", {"common", "fem", "mesh"}},
    {"coupling", {"common", "fem", "fluid", "mesh", "qp", "solid"}},
    {"io", {"common", "mesh"}},
    {"run", {"common", "coupling", "fem", "fluid", "io", "mesh", "qp", "solid"}},
    {"study", {"common", "io", "run", "coupling", "fem", "fluid", "mesh", "qp", "solid"}},
};

TEST(Layering, NoLayerIncludesALayerAboveIt) {
  const fs::path src = fs::path(FSICONTACT_SOURCE_DIR) / "src";
  const std::regex include(R"re(#include "([a-z_]+)/)re");
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    // The layer is the folder under src/ (run/outputs/ belongs to run).
    const std::string layer = entry.path().lexically_relative(src).begin()->string();
    ASSERT_TRUE(kBelow.count(layer)) << entry.path() << ": a folder that is no layer";
    std::ifstream in(entry.path());
    ++files;
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string used = m[1];
      EXPECT_TRUE(used == layer || kBelow.at(layer).count(used))
          << entry.path().lexically_relative(src) << " (" << layer << ") includes " << used << "/: " << line;
    }
  }
  EXPECT_GT(files, 100);
}

}  // namespace
}  // namespace fsi::layering_test
