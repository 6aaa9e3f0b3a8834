// A user's .msh with a defect is a MeshError naming it, never a mesh handed on. One
// small hand-written file per defect, in tests/data/fuzz-msh/ (also the fuzzer's
// seeds); each is the valid 2×1 rectangle of valid-4.1.msh with one thing wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mesh/gmsh_io.hpp"
#include "support/cli.hpp"
#include "support/sanitizers.hpp"

namespace fsi::msh_defects_test {
namespace {

const std::string kDir = FSICONTACT_SOURCE_DIR "/tests/data/fuzz-msh/";

struct Defect {
  std::string file;
  std::vector<std::string> said;  // in the message
};

void PrintTo(const Defect& d, std::ostream* os) {
  *os << d.file;
}

std::vector<Defect> defects() {
  return {
      {"not-a-mesh", {"is not a Gmsh mesh file", "$MeshFormat"}},
      {"leading-blank-line", {"is not a Gmsh mesh file"}},
      {"truncated", {"Gmsh failed while reading it", "Could not read nodes"}},
#if defined(FSICONTACT_ASAN)
      // AddressSanitizer's operator new aborts on exhaustion instead of throwing
      // std::bad_alloc (whatever allocator_may_return_null says): the child's end is
      // still a MeshError, with the signal.
      {"lying-header", {"Gmsh crashed (SIGABRT) while reading it"}},
#else
      {"lying-header",
       {"Gmsh ran out of memory while reading it", "promises more than the file holds"}},
#endif
      {"duplicate-node", {"node tag 3 is defined twice"}},
      {"duplicate-node-2.2", {"node tag 3 is defined twice"}},
      {"unknown-node", {"Unknown node 9 in element 10"}},
      {"no-domain-group", {"has no physical group named 'Omega_S'"}},
      {"empty-group", {"physical curve 'Gamma_C' holds no elements"}},
      {"second-order-triangle",
       {"'Omega_S' holds 6-node triangles (Gmsh element type 9), element 7 first"}},
      {"quadrangle",
       {"'Omega_S' holds 4-node quadrangles (Gmsh element type 3)", "only 3-node triangles"}},
      {"three-node-line",
       {"'Gamma_C' holds 3-node lines (Gmsh element type 8)", "only 2-node lines"}},
      {"zero-area", {"triangle 7 has zero area"}},
      {"repeated-node", {"triangle 7 uses node 2 twice"}},
      {"tangled", {"surface 1 is tangled", "triangle 10 is clockwise"}},
      {"tangled-2.2", {"surface 1 is tangled", "triangle 10 is clockwise"}},
      {"overlap", {"triangles 7 and 11 overlap", "nodes 1 and 2"}},
      {"edge-of-three-triangles", {"the edge between nodes 1 and 2 belongs to 3 triangles"}},
      {"double-turn", {"the triangles around node 1 turn 720 degrees", "folded"}},
      {"line-not-an-edge", {"line 2 of 'Gamma_C' (nodes 1, 3) is not an edge of any triangle"}},
      {"line-inside", {"line 2 of 'Gamma_C' (nodes 2, 5) lies inside the domain"}},
      {"line-node-in-no-triangle", {"node 7 of line 11 of 'Gamma_N'", "belongs to no triangle"}},
      {"line-twice",
       {"nodes 2 and 3 is a boundary line twice", "line 2 of 'Gamma_C'", "line 11 of 'Gamma_N'"}},
      {"non-finite-coordinate", {"node 4 has the coordinate nan"}},
      {"out-of-plane", {"node 4 has z = 0.5", "plane z = 0"}},
      {"wrong-header-tags",
       {"Gmsh warned: Min/Max node tags reported in section header are wrong"}},
      // Found by fuzz_msh: Gmsh 4.8.4's reader dies of a segmentation fault on these
      // 114 bytes, and throws std::length_error on a count in the other.
      {"gmsh-segfaults", {"Gmsh crashed (SIGSEGV) while reading it"}},
      {"count-beyond-max-size", {"Gmsh failed while reading it: a count too large"}},
  };
}

class MshDefect : public ::testing::TestWithParam<Defect> {};

TEST_P(MshDefect, IsAMeshErrorNamingIt) {
  const Defect& d = GetParam();
  const std::string path = kDir + d.file + ".msh";
  try {
    read_gmsh_file(path, {"Gamma_D", "Gamma_C", "Gamma_N"}, "Omega_S");
    FAIL() << d.file << " was accepted";
  } catch (const MeshError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    for (const auto& s : d.said)
      EXPECT_NE(m.find(s), std::string::npos) << "'" << s << "' not in: " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

INSTANTIATE_TEST_SUITE_P(Files, MshDefect, ::testing::ValuesIn(defects()),
                         [](const auto& param_info) {
                           std::string name = param_info.param.file;
                           std::replace_if(
                               name.begin(), name.end(), [](char c) { return !std::isalnum(c); },
                               '_');
                           return name;
                         });

// Gmsh runs a file that does not begin with $MeshFormat as a .geo script, whatever
// its extension (measured): not-a-mesh.msh would run `touch` through SystemCall.
TEST(MshFile, AScriptIsNeverRun) {
  const std::string marker = "/tmp/fsicontact-geo-script-was-run";
  std::filesystem::remove(marker);
  EXPECT_THROW(read_gmsh_file(kDir + "not-a-mesh.msh", {"Gamma_D"}, "Omega_S"), MeshError);
  EXPECT_FALSE(std::filesystem::exists(marker));
}

// Gmsh picks some readers by the extension whatever the content (.stl, .step,
// .brep, .png, .py, ...): a valid mesh under another name is refused.
TEST(MshFile, MustHaveTheExtensionMsh) {
  const auto dir = testing::scratch_dir("msh-extension");
  const auto path = dir / "valid-mesh.stl";
  std::filesystem::copy_file(kDir + "valid-4.1.msh", path);
  try {
    read_gmsh_file(path.string(), {"Gamma_D"}, "Omega_S");
    ADD_FAILURE() << "a .stl was read";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("the extension .msh"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(MshFile, AnEmptyFileIsNotAMesh) {
  const auto dir = testing::scratch_dir("msh-empty");
  std::ofstream{dir / "empty.msh"};
  EXPECT_THROW(read_gmsh_file((dir / "empty.msh").string(), {"Gamma_D"}, "Omega_S"), MeshError);
  std::filesystem::remove_all(dir);
}

TEST(MshFile, AMissingGroupIsNamedWithAllRequired) {
  try {
    read_gmsh_file(kDir + "valid-4.1.msh", {"Gamma_D", "Gamma_X"}, "Omega_Y");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_NE(
        std::string(e.what()).find("has no physical group named 'Omega_Y', 'Gamma_X' (required: "
                                   "surface 'Omega_Y'; curves 'Gamma_D', 'Gamma_X')"),
        std::string::npos)
        << e.what();
  }
}

TEST(MshFile, AGroupOfTheWrongDimensionIsNamed) {
  try {
    read_gmsh_file(kDir + "valid-4.1.msh", {"Gamma_D"}, "Gamma_N");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_NE(
        std::string(e.what()).find("'Gamma_N' is a physical curve; it must be a physical surface"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fsi::msh_defects_test
