// Ctrl-C on `aabench render` leaves no file: not the image, not a temporary. The binary is
// started as a user starts it, interrupted with SIGINT at the two moments that matter — while
// it renders (nothing is on disk yet) and while it writes (the temporary exists) — and must end
// killed by SIGINT with its output directory empty.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include <fmt/format.h>

namespace aabench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// How long a test waits for the moment it interrupts at; far beyond what either takes on a
// loaded machine (the render announces itself in well under a second; the write of a 64 MiB
// EXR takes a few hundred ms), so that only a broken binary runs into it.
constexpr auto kPatience = std::chrono::seconds(120);
// Poll interval while waiting for that moment: short next to the write it has to catch.
constexpr auto kPoll = std::chrono::milliseconds(1);

class RenderInterrupt : public ::testing::Test {
protected:
    void SetUp() override {
        base_ = fs::temp_directory_path() /
                fmt::format("aabench_interrupt_{}_{}", ::getpid(),
                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        out_dir_ = base_ / "out";
        fs::create_directories(out_dir_);
    }
    void TearDown() override {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        fs::remove_all(base_);
    }

    // Starts `aabench ARGS` with stderr into base_/stderr.
    void start(const std::string& args) {
        const std::string err = (base_ / "stderr").string();
        pid_ = ::fork();
        ASSERT_GE(pid_, 0);
        if (pid_ == 0) {
            const std::string cmd = fmt::format("exec {} {} >/dev/null 2>{}", AABENCH_BINARY, args, err);
            ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            std::_Exit(127);
        }
    }
    std::string stderr_text() const {
        std::ifstream in(base_ / "stderr");
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    bool running() {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == 0) return true;
        status_ = status;
        pid_ = -1;
        return false;
    }
    // Sends SIGINT and checks that the process ended by it.
    void interrupt_and_expect_killed_by_sigint() {
        ASSERT_EQ(::kill(pid_, SIGINT), 0);
        int status = 0;
        ASSERT_EQ(::waitpid(pid_, &status, 0), pid_);
        pid_ = -1;
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
            << "status " << status << "; stderr: " << stderr_text();
    }
    std::vector<std::string> files_left() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(out_dir_)) {
            names.push_back(entry.path().filename().string());
        }
        return names;
    }

    fs::path base_, out_dir_;
    pid_t pid_ = -1;
    int status_ = 0;
};

TEST_F(RenderInterrupt, DuringTheRenderNothingIsWritten) {
    // Minutes of work by estimate, so the render announces itself before it starts.
    start(fmt::format("render --pattern star --size 4096x4096 --method ssaa:k=64 --out {}",
                      (out_dir_ / "star.exr").string()));
    const auto deadline = Clock::now() + kPatience;
    while (stderr_text().find("render: ") == std::string::npos) {
        ASSERT_TRUE(running()) << "ended before it was interrupted: " << stderr_text();
        ASSERT_LT(Clock::now(), deadline) << "no estimate line on stderr";
        std::this_thread::sleep_for(kPoll);
    }
    EXPECT_NE(stderr_text().find("ssaa:k=64"), std::string::npos) << stderr_text();
    EXPECT_NE(stderr_text().find("(estimate)"), std::string::npos) << stderr_text();
    interrupt_and_expect_killed_by_sigint();
    EXPECT_TRUE(files_left().empty()) << fmt::format("{}", files_left().front());
}

TEST_F(RenderInterrupt, DuringTheWriteTheTemporaryIsRemoved) {
    // A fast render of a large image: the process spends its time writing the EXR, and the
    // test interrupts it once the temporary file exists.
    start(fmt::format("render --pattern star --size 4096x4096 --method none --out {}",
                      (out_dir_ / "star.exr").string()));
    const auto deadline = Clock::now() + kPatience;
    bool caught = false;
    while (!caught) {
        ASSERT_TRUE(running()) << "finished before its temporary file was seen; stderr: "
                               << stderr_text();
        ASSERT_LT(Clock::now(), deadline) << "no temporary file appeared";
        for (const std::string& name : files_left()) {
            caught = caught || name.find(".tmp-") != std::string::npos;
        }
        if (!caught) std::this_thread::sleep_for(kPoll);
    }
    interrupt_and_expect_killed_by_sigint();
    EXPECT_TRUE(files_left().empty()) << fmt::format("left behind: {}", files_left().front());
}

}  // namespace
}  // namespace aabench
