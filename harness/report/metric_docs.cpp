// The metric registry as Markdown (harness/report/metric_docs.h).
#include "harness/report/metric_docs.h"

#include <fmt/format.h>

#include "harness/measure/metric_registry.h"

namespace aabench {
namespace {

// A table cell: '|' would end it.
std::string cell(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

const char* better_text(Better better) {
    switch (better) {
        case Better::kLower:
            return "lower";
        case Better::kHigher:
            return "higher";
        case Better::kNeither:
            break;
    }
    return "-";
}

std::string gate_text(const MetricDef& def) {
    switch (def.gate) {
        case Gate::kYes:
            return fmt::format("rel {}, abs {}", def.tolerance.rel, def.tolerance.abs);
        case Gate::kOnRequest:
            return "with --time-tolerance";
        case Gate::kNo:
            break;
    }
    return "no";
}

std::string applies_text(unsigned applies) {
    std::string out;
    const auto add = [&](unsigned bit, const char* name) {
        if (applies & bit) out += (out.empty() ? "" : ", ") + std::string(name);
    };
    add(kApplies2d, "2-D");
    add(kApplies3d, "3-D");
    add(kAppliesLines, "lines");
    add(kAppliesSequences, "sequences");
    return out;
}

}  // namespace

std::string metric_registry_markdown() {
    std::string out =
        "| key | header | unit | better | gated (tolerance) | applies to | definition |\n"
        "|---|---|---|---|---|---|---|\n";
    for (const MetricDef& def : metric_registry().all()) {
        out += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", def.key, cell(def.header),
                           def.unit, better_text(def.better), gate_text(def),
                           applies_text(def.applies), cell(def.definition));
    }
    return out;
}

}  // namespace aabench
