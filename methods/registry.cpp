// The one registry table: every method of the suite is one row here and one file beside it.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "methods/method.h"

namespace aabench {

const std::vector<MethodInfo>& method_registry() {
    static const std::vector<MethodInfo> registry = {
        none_method(),
        exact_method(),
        box_multiscan_method(),
        gauss_multiscan_method(),
        ssaa_method(),
        nishita_d_method(),
        fast_edge_method(),
        cairo_method(),
        agg_method(),
        exact_8bit_method(),
        aa_circle_method(),
        wu_circle_method(),
        midpoint_circle_method(),
    };
    return registry;
}

MethodInstance make_method(const std::string& spec_text) {
    const SpecString spec = parse_spec_string(spec_text);
    for (const MethodInfo& info : method_registry()) {
        if (info.id != spec.id) continue;
        MethodInstance instance;
        instance.id = info.id;
        instance.params =
            resolve_params(fmt::format("method '{}'", info.id), info.params, spec.assignments);
        const std::string params = instance.params.to_string();
        instance.spec = params.empty() ? info.id : info.id + ":" + params;
        instance.method = info.factory(instance.params);
        return instance;
    }
    std::vector<std::string> ids;
    for (const MethodInfo& info : method_registry()) ids.push_back(info.id);
    throw InputError(
        fmt::format("unknown method '{}' (valid: {})", spec.id, fmt::join(ids, ", ")));
}

Image render_scene(const Method& method, const Scene& scene) {
    Image out(scene.width, scene.height);
    method.render(scene, out);
    return out;
}

}  // namespace aabench
