// Test support: a fresh scratch folder under the system's temp directory for one test,
// removed with everything in it when the test ends.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

namespace tactip::testing {

/// temp/tactip_<label>_<pid>_<test name>, created empty (any leftover of an earlier process
/// with the same pid removed) and removed when the object goes. The pid keeps tests that ctest
/// runs in parallel processes apart, the test's name the tests of one process.
class TestTempDir {
 public:
  explicit TestTempDir(const std::string& label)
      : path_(std::filesystem::temp_directory_path() /
              ("tactip_" + label + "_" + std::to_string(::getpid()) + "_" + CurrentTestName())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TestTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TestTempDir(const TestTempDir&) = delete;
  TestTempDir& operator=(const TestTempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The path of `name` inside the folder, as a string.
  std::string File(const std::string& name) const { return (path_ / name).string(); }

 private:
  static std::string CurrentTestName() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // A parameterised test's name holds '/' (NAME/PARAM): one folder, not two.
    std::string name = info != nullptr ? info->name() : "suite";
    for (char& ch : name) {
      if (ch == '/') ch = '_';
    }
    return name;
  }
  std::filesystem::path path_;
};

}  // namespace tactip::testing
