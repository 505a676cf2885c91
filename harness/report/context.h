// The context every result file carries: what built the binary, where it ran, when, and the
// command that reproduces it.
#pragma once

#include <string>

namespace aabench {

struct RunContext {
    std::string tool = "aabench";
    std::string git_revision;
    std::string build_type;
    std::string compiler;
    std::string flags;
    std::string cpu;
    int hardware_threads = 0;
    std::string date_utc;  // ISO 8601
    std::string command;   // argv joined, shell-quoted where needed
};

RunContext capture_context(int argc, char** argv);

}  // namespace aabench
