// A test fixture that runs the aabench binary in a fresh temporary directory per test and
// returns its exit code, stdout and stderr (for the command-line tests).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>

namespace aabench {

struct CliOutput {
    int exit_code;
    std::string out;
    std::string err;
};

class CliRunner : public ::testing::Test {
protected:
    // `prefix` names the suite in the directory name: /tmp/aabench_<prefix>_<pid>_<test>.
    explicit CliRunner(std::string prefix) : prefix_(std::move(prefix)) {}
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               fmt::format("aabench_{}_{}_{}", prefix_, ::getpid(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    CliOutput run(const std::string& args) const {
        const std::string cmd =
            fmt::format("{} {} >{} 2>{}", AABENCH_BINARY, args, path("stdout"), path("stderr"));
        const int status = std::system(cmd.c_str());
        auto slurp = [](const std::string& p) {
            std::ifstream in(p);
            return std::string((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        };
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(path("stdout")),
                slurp(path("stderr"))};
    }
    std::filesystem::path dir_;

private:
    std::string prefix_;
};

}  // namespace aabench
