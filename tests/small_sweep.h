// The small sweep the comparison and shard tests run: three methods (one with a cost parameter)
// on two patterns at 40x32, one timing run.
#pragma once

#include "harness/measure/compare.h"

namespace aabench::test {

inline CompareOptions small_sweep() {
    CompareOptions options;
    options.method_specs = {"none", "box-multiscan", "ssaa:k=2"};
    options.pattern_specs = {"star", "strips"};
    options.width = 40;
    options.height = 32;
    options.runs = 1;
    options.sweep = true;
    return options;
}

}  // namespace aabench::test
