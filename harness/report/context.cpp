#include "harness/report/context.h"

#include <chrono>
#include <fstream>
#include <thread>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "build_info.h"

namespace aabench {
namespace {

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
        }
    }
    return "unknown";
}

std::string shell_quote(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t\n'\"\\$`*?;&|<>()[]{}") == std::string::npos) {
        return arg;
    }
    std::string out = "'";
    for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

RunContext capture_context(int argc, char** argv) {
    RunContext ctx;
    ctx.git_revision = build_info::kGitRevision;
    ctx.build_type = build_info::kBuildType;
    ctx.compiler = build_info::kCompilerId;
    ctx.flags = build_info::kCxxFlags;
    ctx.cpu = cpu_model();
    ctx.hardware_threads = static_cast<int>(std::thread::hardware_concurrency());
    ctx.date_utc = fmt::format("{:%Y-%m-%dT%H:%M:%SZ}",
                               fmt::gmtime(std::chrono::system_clock::to_time_t(
                                   std::chrono::system_clock::now())));
    for (int k = 0; k < argc; ++k) {
        if (k) ctx.command += ' ';
        ctx.command += shell_quote(argv[k]);
    }
    return ctx;
}

}  // namespace aabench
