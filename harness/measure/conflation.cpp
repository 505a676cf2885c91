#include "harness/measure/conflation.h"

#include <cmath>

namespace aabench {

std::optional<std::string> conflation_twin_spec(const MethodInstance& method) {
    std::string spec = method.id;
    char separator = ':';
    bool has_paths = false;
    for (auto [key, value] : method.params.items()) {
        if (key == "paths") {
            has_paths = true;
            value = value == "merged" ? "per-shape" : "merged";
        }
        spec += separator + key + "=" + value;
        separator = ',';
    }
    if (!has_paths) return std::nullopt;
    return spec;
}

std::optional<double> conflation_rmse(const MethodInstance& method, const SceneInput& scene,
                                      const Image& out) {
    const std::optional<std::string> twin = conflation_twin_spec(method);
    if (!twin) return std::nullopt;
    const Image other = render_scene(*make_method(*twin).method, scene);
    double sum = 0.0;
    for (std::size_t k = 0; k < out.data.size(); ++k) {
        const double d = static_cast<double>(out.data[k]) - other.data[k];
        sum += d * d;
    }
    return out.data.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(out.data.size()));
}

}  // namespace aabench
