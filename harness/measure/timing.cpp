#include "harness/measure/timing.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include <fmt/format.h>

namespace aabench {

TimingStats time_render(const Method& method, const Scene& scene, Image& out, int runs,
                        int threads) {
    render_in_bands(method, scene, out, threads);  // warm-up: caches, page faults, tables
    std::vector<double> ns;
    ns.reserve(runs);
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        render_in_bands(method, scene, out, threads);
        const auto stop = std::chrono::steady_clock::now();
        ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
    }
    std::sort(ns.begin(), ns.end());
    TimingStats stats;
    stats.runs = runs;
    stats.threads = threads;
    if (ns.empty()) return stats;
    stats.min_ns = ns.front();
    stats.max_ns = ns.back();
    const std::size_t mid = ns.size() / 2;
    stats.median_ns = ns.size() % 2 ? ns[mid] : 0.5 * (ns[mid - 1] + ns[mid]);
    return stats;
}

nlohmann::json parse_benchmark_json(const std::string& text, const std::string& source) {
    // Bare NaN / Infinity / -Infinity / -nan tokens outside strings become null.
    std::string clean;
    clean.reserve(text.size());
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (in_string) {
            clean += c;
            if (c == '\\' && k + 1 < text.size()) {
                clean += text[++k];
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') in_string = true;
        std::size_t skip = 0;
        for (const char* token : {"-Infinity", "Infinity", "-NaN", "NaN", "-nan", "nan"}) {
            const std::string t(token);
            if (text.compare(k, t.size(), t) == 0) {
                skip = t.size();
                break;
            }
        }
        if (skip > 0) {
            clean += "null";
            k += skip - 1;
        } else {
            clean += c;
        }
    }
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(clean);
    } catch (const nlohmann::json::parse_error& e) {
        // The offset is in the text with the bare tokens read as null: near, not at, the byte.
        throw InputError(fmt::format("{}: invalid JSON near byte {}", source, e.byte));
    }
    if (!doc.is_object() || !doc.contains("benchmarks") || !doc["benchmarks"].is_array()) {
        throw InputError(source + ": not Google Benchmark JSON output (no \"benchmarks\" array)");
    }
    return doc;
}

double benchmark_number(const nlohmann::json& entry, const char* key, double fallback) {
    const auto it = entry.find(key);
    return it != entry.end() && it->is_number() ? it->get<double>() : fallback;
}

}  // namespace aabench
