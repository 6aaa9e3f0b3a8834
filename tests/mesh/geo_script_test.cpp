// A user's Gmsh .geo script (structure.shape = "geo"): the commands that reach outside
// the geometry are refused with the line they are on, wherever they hide but in comments
// and strings; the child that runs the script can neither write a file nor start a
// process; the script's own errors come back in its words; the mesh has the groups asked
// for and is at most h fine where the script says nothing.
#include "mesh/geo_script.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "mesh/gmsh_child.hpp"
#include "mesh/gmsh_io.hpp"
#include "support/cli.hpp"

namespace fsi::geo_script_test {
namespace {

std::string refusal(const std::string& text) {
  try {
    check_geo_script(text, "s.geo");
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

TEST(GeoScript, CommandsThatReachOutsideAreRefusedWithTheirLine) {
  for (const char* command : {"System \"rm -rf /tmp/x\";", "SystemCall \"ls\";", "Save \"out.msh\";",
                              "Include \"other.geo\";", "Merge \"x.step\";", "Sleep 100;", "Exit;",
                              "Print \"a.png\";", "OnelabRun(\"x\", \"y\");", "Plugin(Crack).Run;"}) {
    const std::string m = refusal(std::string("Point(1) = {0, 0, 0};\n\n") + command + "\n");
    EXPECT_EQ(m.rfind("s.geo:3: the command '", 0), 0u) << command << ": " << m;
    EXPECT_NE(m.find("allowed: geometry"), std::string::npos) << m;
  }
  EXPECT_NE(refusal("Printf(\"%g\", 1) > \"/tmp/leak.txt\";").find("'Printf'"), std::string::npos);
  EXPECT_NE(refusal("Printf(\"%g\", 1) >> \"log\";").find("'Printf'"), std::string::npos);
}

TEST(GeoScript, CommentsStringsAndOptionNamesAreNotCommands) {
  EXPECT_EQ(refusal("// System \"rm\"; Save\n/* Include \"x\"; Exit; */\n"
                    "Physical Curve(\"Save this Include\") = {1};\n"
                    "Print.Format = 1; Mesh.SaveAll = 0;\nPrintf(\"x = %g\", x > 1);\n"
                    "Saved = 3; Exits = 1;\n"),
            "");
  EXPECT_NE(refusal(std::string("x = 1;\n", 7) + std::string(1, '\0')).find("NUL"), std::string::npos);
}

TEST(GeoScript, FilesAreCheckedBeforeAnythingRuns) {
  const auto dir = testing::scratch_dir("geo-files");
  auto message = [](const std::string& path) {
    try {
      read_geo_script(path);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message((dir / "none.geo").string()).find("no such script file"), std::string::npos);
  std::ofstream(dir / "a.txt") << "Point(1) = {0,0,0};\n";
  EXPECT_NE(message((dir / "a.txt").string()).find("extension .geo"), std::string::npos);
  std::ofstream(dir / "big.geo") << std::string(kMaxGeoScriptBytes + 1, ' ');
  EXPECT_NE(message((dir / "big.geo").string()).find("at most"), std::string::npos);
  std::filesystem::create_directory(dir / "d.geo");
  EXPECT_NE(message((dir / "d.geo").string()).find("a directory, not a script file"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// The second fence: whatever the script does, the child cannot grow a file or fork.
TEST(GeoScript, TheScriptsChildCanWriteNoFileAndStartNoProcess) {
  const auto dir = testing::scratch_dir("geo-fence");
  const std::string file = (dir / "leak.txt").string();
  const std::vector<char> reply = run_in_child(
      [&] {
        forbid_side_effects();
        std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG instead of killing
        std::FILE* f = std::fopen(file.c_str(), "w");
        const bool wrote = f && std::fputs("secret", f) >= 0 && std::fflush(f) == 0;
        if (f) std::fclose(f);
        const pid_t pid = ::fork();
        if (pid == 0) ::_exit(0);
        const bool forked = pid > 0;
        return std::vector<char>{wrote ? 'w' : '-', forked ? 'f' : '-'};
      },
      {"testing the fence", ""}, {});
  ASSERT_EQ(reply.size(), 2u);
  EXPECT_EQ(reply[0], '-');
  EXPECT_EQ(std::filesystem::exists(file) ? std::filesystem::file_size(file) : 0u, 0u);
  if (::geteuid() != 0) {
    EXPECT_EQ(reply[1], '-');  // RLIMIT_NPROC does not bind root
  }
  std::filesystem::remove_all(dir);
}

Mesh mesh_text(const std::filesystem::path& dir, const std::string& text, double h, double limit = 1e5) {
  std::ofstream(dir / "s.geo") << text;
  return mesh_geo_script((dir / "s.geo").string(), h, limit, {"Gamma_D", "Gamma_N"}, {"Gamma_C"}, "Omega_S");
}

std::string mesh_failure(const std::filesystem::path& dir, const std::string& text, double h, double limit = 1e5) {
  try {
    mesh_text(dir, text, h, limit);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

const std::string kSquare = R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("Omega_S") = {1}; Physical Curve("Gamma_D") = {4}; Physical Curve("Gamma_N") = {1, 2, 3};
)";

// Where the script sets no size Gmsh takes a tenth of the bounding box's diagonal
// (0.14 here); h caps every size. A script sized by h follows h at any size.
TEST(GeoScript, TheScriptSeesHAndHCapsTheSize) {
  const auto dir = testing::scratch_dir("geo-mesh");
  const Mesh coarse = mesh_text(dir, kSquare, 0.1), fine = mesh_text(dir, kSquare, 0.05);
  EXPECT_GT(fine.num_triangles(), 3 * coarse.num_triangles());
  EXPECT_EQ(coarse.vertices_on(coarse.label("Gamma_D")).size(), 11u);  // 1/0.1 segments
  EXPECT_TRUE(coarse.has_label("Gamma_C"));  // optional: an empty label
  EXPECT_TRUE(coarse.edges_on(coarse.label("Gamma_C")).empty());
  EXPECT_EQ(mesh_text(dir, kSquare, 0.5).num_triangles(), mesh_text(dir, kSquare, 0.25).num_triangles());
  // h is defined before the first line: a script may size itself by it.
  const std::string sized = "lc = h / 2;\n" + kSquare + "MeshSize{1, 2, 3, 4} = lc;\n";
  const Mesh half = mesh_text(dir, sized, 0.5), quarter = mesh_text(dir, sized, 0.25);
  EXPECT_EQ(half.vertices_on(half.label("Gamma_D")).size(), 5u);
  EXPECT_EQ(quarter.vertices_on(quarter.label("Gamma_D")).size(), 9u);
  std::filesystem::remove_all(dir);
}

TEST(GeoScript, TheScriptsErrorsComeBackInItsWords) {
  const auto dir = testing::scratch_dir("geo-errors");
  const std::string syntax = mesh_failure(dir, "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0 0};\n", 0.1);
  EXPECT_NE(syntax.find("'" + (dir / "s.geo").string() + "', line 2: syntax error"), std::string::npos)
      << syntax;  // the user's file and line, not the memory file's
  EXPECT_EQ(syntax.find("/proc/self"), std::string::npos) << syntax;
  EXPECT_NE(mesh_failure(dir, "Point(1) = {0, 0, 0};\n", 0.1).find("defines no surface"), std::string::npos);
  EXPECT_NE(mesh_failure(dir, kSquare, 1e-4, 1e5).find("above the limit"), std::string::npos);
  const std::string missing = mesh_failure(dir, "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
                                                "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
                                                "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"
                                                "Physical Surface(\"Omega_S\") = {1};\n", 0.2);
  EXPECT_NE(missing.find("Gamma_D"), std::string::npos) << missing;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fsi::geo_script_test
