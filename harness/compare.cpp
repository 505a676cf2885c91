#include "harness/compare.h"

#include <map>

#include "harness/box_reference.h"
#include "harness/filter_reference.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {

std::vector<std::string> split_spec_list(const std::string& text) {
    std::vector<std::string> specs;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const bool continues = item.find('=') != std::string::npos &&
                               item.find(':') == std::string::npos && !specs.empty();
        if (continues) {
            specs.back() += "," + item;
        } else if (!item.empty()) {
            specs.push_back(item);
        } else {
            throw InputError("empty item in the list '" + text + "'");
        }
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return specs;
}

std::vector<ResultRow> run_comparison(const CompareOptions& options,
                                      const ProgressFn& progress) {
    check_image_size(options.width, options.height, "--size");
    if (options.runs < 1 || options.runs > 1000) {
        throw InputError("--runs: " + std::to_string(options.runs) + " is out of range 1..1000");
    }
    std::vector<std::string> pattern_specs = options.pattern_specs;
    if (pattern_specs.empty()) {
        for (const PatternInfo& info : pattern_registry()) pattern_specs.push_back(info.id);
    }
    std::vector<std::string> method_specs = options.method_specs;
    if (method_specs.empty()) {
        for (const MethodInfo& info : method_registry()) method_specs.push_back(info.id);
    }
    // Check every spec before any work, so a typo fails at once and not after an hour.
    std::vector<PatternInstance> patterns;
    for (const auto& spec : pattern_specs) patterns.push_back(resolve_pattern(spec));
    std::vector<MethodInstance> methods;
    for (const auto& spec : method_specs) methods.push_back(make_method(spec));

    const std::size_t total = patterns.size() * methods.size();
    std::size_t done = 0;
    std::vector<ResultRow> rows;
    for (const PatternInstance& pattern : patterns) {
        const Scene scene =
            pattern.info->generate(pattern.params, options.width, options.height);
        // One reference per distinct filter, computed on first use.
        std::map<std::string, Coverage> references;
        references.emplace("box", box_reference(scene));
        auto reference_for = [&](const std::string& spec) -> const Coverage& {
            auto it = references.find(spec);
            if (it == references.end()) it = references.emplace(spec, exact_reference(scene, spec)).first;
            return it->second;
        };
        Image out(scene.width, scene.height);
        for (const MethodInstance& method : methods) {
            ResultRow row;
            row.pattern = pattern.spec;
            row.pattern_id = pattern.info->id;
            row.method = method.spec;
            row.method_id = method.id;
            row.width = scene.width;
            row.height = scene.height;
            row.edges = static_cast<long long>(scene.edge_count());
            row.time = time_render(*method.method, scene, out, options.runs);
            row.box = compare_to_reference(out, references.at("box"));
            row.reference_filter = canonical_reference_spec(method.method->reference_filter());
            row.own = row.reference_filter == "box"
                          ? row.box
                          : compare_to_reference(out, reference_for(row.reference_filter));
            const double seconds = row.time.median_ns * 1e-9;
            if (seconds > 0.0) {
                row.mpixel_per_s = static_cast<double>(scene.width) * scene.height / seconds / 1e6;
                row.medges_per_s = static_cast<double>(row.edges) / seconds / 1e6;
            }
            rows.push_back(row);
            if (progress) progress(++done, total, pattern.info->id + " / " + method.spec);
        }
    }
    return rows;
}

}  // namespace aabench
