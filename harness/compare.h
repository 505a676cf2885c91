// The comparison run: every method on every pattern, each scored against the exact box
// reference and timed. Pure computation: the report stage writes the files.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/metrics.h"
#include "harness/timing.h"

namespace aabench {

struct CompareOptions {
    std::vector<std::string> method_specs;   // empty: every registered method, defaults
    std::vector<std::string> pattern_specs;  // empty: every built-in pattern, defaults
    int width = 256;
    int height = 256;
    int runs = 7;  // timed runs after one warm-up; the median is reported
};

struct ResultRow {
    std::string pattern;  // canonical pattern spec (every parameter)
    std::string pattern_id;
    std::string method;  // canonical method spec (every parameter)
    std::string method_id;
    int width = 0;
    int height = 0;
    long long edges = 0;
    ErrorStats box;                // against the exact box reference
    std::string reference_filter;  // the method's own filter (canonical spec)
    ErrorStats own;                // against the exact reference of that filter
    TimingStats time;
    double mpixel_per_s = 0.0;
    double medges_per_s = 0.0;
};

// Called after each method x pattern task: (tasks done, tasks in all, what was just done).
using ProgressFn = std::function<void(std::size_t, std::size_t, const std::string&)>;

// Checks every spec first (InputError before any work), then runs. Rows come in pattern
// order, then method order.
std::vector<ResultRow> run_comparison(const CompareOptions& options,
                                      const ProgressFn& progress = {});

// Splits a comma-separated list of specs whose own parameters are also comma-separated:
// an item with '=' but no ':' continues the previous spec ("ssaa:k=3,filter=box,none" is
// two specs).
std::vector<std::string> split_spec_list(const std::string& text);

}  // namespace aabench
