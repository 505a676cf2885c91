// The one registry table: every method of the suite is one row here and one file beside it.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

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

void Method::render_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const {
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi) return;
    if (has_origin(scene)) {
        draw_rows(in_window_frame(scene), out, row_lo, row_hi);
        return;
    }
    draw_rows(scene, out, row_lo, row_hi);
}

void render_in_bands(const Method& method, const Scene& scene, Image& out, int threads) {
    if (threads <= 1 || scene.height < 2) {
        method.render(scene, out);
        return;
    }
    // The origin out once for all bands (render_rows would copy the scene per band).
    if (has_origin(scene)) {
        render_in_bands(method, in_window_frame(scene), out, threads);
        return;
    }
    const int bands = std::min(threads, scene.height);
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(0, bands, [&](int b) {
            const int lo = static_cast<int>(static_cast<long long>(scene.height) * b / bands);
            const int hi = static_cast<int>(static_cast<long long>(scene.height) * (b + 1) / bands);
            method.render_rows(scene, out, lo, hi);
        });
    });
}

}  // namespace aabench
