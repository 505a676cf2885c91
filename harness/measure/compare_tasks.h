// The comparison run's task list (harness/measure/compare.h) and each task's estimated cost,
// shared by the run itself and by its shard plan. Internal to harness/measure.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "methods/method.h"
#include "methods/method_traits.h"

namespace aabench {

struct Task {
    std::size_t pattern;  // index into the run's patterns
    MethodInstance method;
    bool sweep_point = false;
    std::string cost_param;
    double cost_value = 0.0;
    long long index = 0;  // in the unsharded order
};

// Every task of the unsharded run, in the one order every shard agrees on: pattern, then
// method, then the method's sweep values in ascending cost (with options.sweep). Refuses a run
// of more than kMaxCompareTasks tasks before any work.
// `curved[p]`: pattern p has Bezier curves (the sweeps of sweep_on_curves_only methods run
// there only); its size is the run's pattern count.
std::vector<Task> make_all_tasks(const std::vector<bool>& curved,
                                 const std::vector<MethodInstance>& methods,
                                 const CompareOptions& options);

// Renders the run makes for one task: the scored render, the timing's warm-up and runs, and
// for a default row with options.symptoms the motion frames (the crawl and popping figures).
// The rest (mass windows, metrics) is small beside them; the references are the pattern's,
// shared by its tasks.
int renders_per_task(bool sweep_point, const CompareOptions& options);

// The task's estimated time in ms on the cost model's machine: its method's estimate
// (MethodTraits::time_ms) on the scene it draws, times renders_per_task.
double estimate_task_ms(const Task& task, const SceneSize& drawn, const CompareOptions& options);

}  // namespace aabench
