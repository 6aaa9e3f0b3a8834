// Output paths are data (issue 11, class 5): checked as text and against the file
// system before anything is created; the check itself leaves nothing behind.
#include "io/output_path.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "common/errors.hpp"

namespace fsi::output_path_test {
namespace {

namespace fs = std::filesystem;

TEST(OutputPath, TextProblemsAreNamed) {
  EXPECT_EQ(output_path_problem("out/run-1"), "");
  EXPECT_EQ(output_path_problem("C:\\temp"), "");  // a backslash is a character like any other
  EXPECT_NE(output_path_problem("").find("empty"), std::string::npos);
  EXPECT_NE(output_path_problem("C:\temp").find("U+0009"), std::string::npos);
  EXPECT_NE(output_path_problem(std::string("a\0b", 3)).find("U+0000"), std::string::npos);
  EXPECT_NE(output_path_problem("a/" + std::string(256, 'x')).find("256 bytes"), std::string::npos);
  EXPECT_EQ(output_path_problem("a/" + std::string(255, 'x')), "");
}

TEST(OutputPath, TheFileSystemCheckCreatesNothing) {
  const fs::path dir = fs::temp_directory_path() / ("fsicontact-outpath-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  EXPECT_NO_THROW(check_output_dir((dir / "new/deeper").string(), "t"));
  EXPECT_NO_THROW(check_output_dir(dir.string(), "t"));
  EXPECT_THROW(check_output_dir((dir / "file").string(), "t"), InputError);
  EXPECT_THROW(check_output_dir((dir / "file/sub").string(), "t"), InputError);
  fs::create_symlink(dir / "nowhere", dir / "dangling");
  EXPECT_THROW(check_output_dir((dir / "dangling/sub").string(), "t"), InputError);
  EXPECT_THROW(check_output_dir("/proc/fsicontact", "t"), InputError);  // refuses even root
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2) << "the probe left something";
  EXPECT_FALSE(fs::exists(dir / "new"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fsi::output_path_test
