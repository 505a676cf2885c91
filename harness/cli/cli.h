// The command-line interface: the only place that parses arguments. Returns the exit code:
// 0 success, 1 a failed gate or internal error, 2 bad input (one line on stderr, no output
// file written).
#pragma once

namespace aabench {

int run_cli(int argc, char** argv);

}  // namespace aabench
