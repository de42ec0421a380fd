// Config input through the command line: YAML files that are refused (alias bombs,
// duplicate keys, a second document), values that would break the one-line message, and
// parameter combinations refused before anything runs. Each refusal is one line on stderr
// with exit code 2 and leaves no file.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;

class ConfigInputCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tactip_cfg_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliResult Run(const std::string& args) { return testing::RunTactip(args, dir_); }
  std::string P(const std::string& name) const { return (dir_ / name).string(); }

  // `generate` with these arguments must be refused on one line naming `fragment`,
  // with exit code 2 and no dataset.
  void ExpectRefused(const std::string& args, const std::string& fragment) {
    const CliResult r = Run("generate " + args + " --runs 1 --out " + P("x.h5"));
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << args << ": not one line\n" << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(P("x.h5"))) << args;
  }

  fs::path dir_;
};

TEST_F(ConfigInputCliTest, YamlAliasBombDuplicateKeysAndASecondDocumentAreRefused) {
  std::string bomb = "sim: &l0 {a: x, b: x, c: x, d: x, e: x, f: x, g: x, h: x, i: x, j: x}\n";
  for (int level = 1; level <= 8; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    bomb += "x" + std::to_string(level) + ": &l" + std::to_string(level) + " {";
    for (char k = 'a'; k <= 'j'; ++k) bomb += std::string(k == 'a' ? "" : ", ") + k + ": " + prev;
    bomb += "}\n";
  }
  std::ofstream(P("bomb.yaml")) << bomb;
  std::ofstream(P("dup.yaml")) << "sim:\n  iterations: 50\n  iterations: 60\n";
  std::ofstream(P("two.yaml")) << "sim:\n  iterations: 50\n---\nsim:\n  iterations: 60\n";
  ExpectRefused("rail --config " + P("bomb.yaml"), "bomb.yaml: expands to more than 10000 YAML nodes");
  ExpectRefused("rail --config " + P("dup.yaml"), "dup.yaml: key 'sim.iterations' appears twice (line 3)");
  ExpectRefused("rail --config " + P("two.yaml"), "two.yaml: holds 2 YAML documents");
}

TEST_F(ConfigInputCliTest, LineBreakInASetValueIsRefusedOnOneLine) {
  // /bin/sh has no $'...': printf makes the line break.
  ExpectRefused("rail --set \"$(printf 'sim.iterations=5\\nx')\"", "--set 'sim.iterations=5\\nx': holds a line break");
}

}  // namespace
}  // namespace tactip
