// A test fixture for pipeline tests that read journals: a scratch directory
// per test process (removed afterwards), the built-in schemes, and
// journal(body) writing <cooperage version="1">body</cooperage> there and
// reading it back.
#pragma once

#include "framework/io/journal_reader.h"
#include "schemes/builtin_schemes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace cooperage::pipeline::testing {

class JournalFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("cooperage-" + std::string(info->test_suite_name()) + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    register_builtin_schemes(registry_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  io::Job journal(const std::string& body) {
    const std::filesystem::path file = dir_ / "job.xml";
    std::ofstream(file) << "<cooperage version=\"1\">\n" << body << "</cooperage>\n";
    return io::read_journal(file.string());
  }

  std::filesystem::path dir_;
  scheme::Registry registry_;
};

}  // namespace cooperage::pipeline::testing
