// The comparison run's task list and task estimates (harness/measure/compare_tasks.h).
#include "harness/measure/compare_tasks.h"

#include "harness/measure/limits.h"
#include "patterns/scene/params.h"

namespace aabench {
namespace {

// The spec with one parameter set to `value` (added if absent).
std::string with_param(const std::string& spec_text, const std::string& key,
                       const std::string& value) {
    SpecString spec = parse_spec_string(spec_text);
    bool found = false;
    for (auto& [k, v] : spec.assignments) {
        if (k == key) {
            v = value;
            found = true;
        }
    }
    if (!found) spec.assignments.emplace_back(key, value);
    std::string out = spec.id;
    for (std::size_t i = 0; i < spec.assignments.size(); ++i) {
        out += (i == 0 ? ":" : ",") + spec.assignments[i].first + "=" + spec.assignments[i].second;
    }
    return out;
}

const MethodInfo& method_info(const std::string& id) {
    for (const MethodInfo& info : method_registry()) {
        if (info.id == id) return info;
    }
    throw std::logic_error("no method " + id);
}

}  // namespace

std::vector<Task> make_all_tasks(const std::vector<bool>& curved,
                                 const std::vector<MethodInstance>& methods,
                                 const CompareOptions& options) {
    std::vector<Task> tasks;
    long long index = 0;
    for (std::size_t p = 0; p < curved.size(); ++p) {
        for (const MethodInstance& method : methods) {
            const MethodInfo& info = method_info(method.id);
            auto add = [&](MethodInstance instance, bool sweep_point) {
                Task task{p, std::move(instance), sweep_point, info.cost_param, 0.0, index++};
                if (!info.cost_param.empty()) {
                    task.cost_value = task.method.params.get_real(info.cost_param);
                }
                tasks.push_back(std::move(task));
            };
            add(make_method(method.spec), false);
            if (!options.sweep || info.cost_param.empty()) continue;
            if (info.sweep_on_curves_only && !curved[p]) continue;
            const double own = method.params.get_real(info.cost_param);
            for (double v : info.sweep_values) {
                if (v == own) continue;  // the method as asked for is already a row
                MethodInstance point;
                try {
                    point = make_method(with_param(method.spec, info.cost_param, format_real(v)));
                } catch (const InputError&) {
                    continue;  // a value this variant refuses (ssaa:pattern=msaa: k = 2, 4, 8, 16)
                }
                add(std::move(point), true);
            }
            check_task_count(index, "compare");  // a sweep of sweeps stops before any work
        }
    }
    return tasks;
}

int renders_per_task(bool sweep_point, const CompareOptions& options) {
    const int scored = 1, timed = options.runs + 1;  // time_render: one warm-up, then the runs
    const int motion = options.symptoms && !sweep_point ? options.motion_frames : 0;
    return scored + timed + motion;
}

double estimate_task_ms(const Task& task, const SceneSize& drawn, const CompareOptions& options) {
    return estimate_render_ms(task.method, drawn) * renders_per_task(task.sweep_point, options);
}

}  // namespace aabench
