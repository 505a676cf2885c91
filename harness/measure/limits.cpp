// The memory estimate (harness/measure/limits.h, docs/limits.md). Every constant is the size of a
// data structure the code really allocates, rounded up, with the vector growth slack where a vector
// grows by push_back (up to 2x its final size); the methods' own are their rows'
// (methods/memory_model.h).
#include "harness/measure/limits.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "harness/reference/filter_reference.h"
#include "harness/reference/visibility.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/reference/piece_coverage.h"  // has_affine_values
#include "patterns/scene/curves.h"

namespace aabench {

// Exact visibility refuses a scene over the same budget as a job (docs/limits.md).
static_assert(VisibilityOptions{}.memory_budget_bytes == kDefaultMemoryBudgetBytes);

namespace {

// A stored vertex: Point (16 bytes) in a Contour.
constexpr double kVertexBytes = 16.0;
// Per contour and per shape: a vector header (24) plus allocator overhead, rounded up.
constexpr double kContourBytes = 64.0;
constexpr double kShapeBytes = 96.0;

struct Working {
    double bytes = 0.0;  // working memory while the task runs
    double kept = 0.0;   // what stays: the output image or raster
};

// The row's estimate (MethodTraits::working_bytes, methods/memory_model.h) and the float32
// output.
Working method_working(const MethodInstance& m, const SceneSize& s) {
    return {m.method->traits().working_bytes(m.params, s), 4.0 * s.pixels()};
}

Working reference_working(const std::string& spec, const SceneSize& s) {
    const double pixels = static_cast<double>(s.width) * s.height;
    Working w;
    w.kept = 8.0 * pixels;
    using namespace memory_model;
    const Filter filter = Filter::parse(spec);  // checks the spec
    if (filter.is_box()) {
        w.bytes = edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices;
    } else {
        // The radial references add a difference raster (double, W + 1 per row) and sweep the
        // rows within the filter's radius beyond the image too (at most 8 px each side).
        const double margin_rows = 2.0 * (std::ceil(filter.radius_px()) + 2.0);
        w.bytes = edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices +
                  8.0 * (s.width + 1.0) * s.height + kEdgeRowBytes * s.vertices * margin_rows;
    }
    return w;
}

}  // namespace

SceneSize measure_scene(const Scene& scene) {
    require_window_frame(scene, "measure_scene");
    SceneSize s;
    s.width = scene.width;
    s.height = scene.height;
    s.shapes = static_cast<long long>(scene.shapes.size());
    s.exact_raster = has_affine_values(scene) || has_curves(scene);
    s.channels = scene.channels;
    for (const Shape& shape : scene.shapes) {
        s.contours += static_cast<long long>(shape.contours.size());
        for (const Contour& c : shape.contours) {
            s.vertices += static_cast<long long>(c.size());
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a = c[k], b = c[(k + 1) % c.size()];
                // Rows and columns overlapped, clipped in double (coordinates may be huge).
                const double r0 = std::max(0.0, std::floor(std::min(a.y, b.y)));
                const double r1 = std::min<double>(scene.height, std::ceil(std::max(a.y, b.y)));
                if (a.y != b.y && r1 > r0) s.edge_rows += static_cast<long long>(r1 - r0);
                const double c0 = std::max(0.0, std::floor(std::min(a.x, b.x)));
                const double c1 = std::min<double>(scene.width, std::ceil(std::max(a.x, b.x)));
                if (c1 > c0) s.edge_columns += static_cast<long long>(c1 - c0);
            }
        }
    }
    return s;
}

std::size_t estimate_job_bytes(const SceneSize& scene, const std::vector<std::string>& method_specs,
                               const std::vector<std::string>& reference_specs,
                               int concurrent) {
    double peak_working = 0.0, kept = 0.0;
    for (const std::string& spec : method_specs) {
        const Working w = method_working(make_method(spec), scene);
        peak_working = std::max(peak_working, w.bytes);
        kept += w.kept;
    }
    for (const std::string& spec : reference_specs) {
        const Working w = reference_working(spec, scene);
        peak_working = std::max(peak_working, w.bytes);
        kept += w.kept;
        // Beside the box reference, its half of the ꟻLIP map (flip::FlipReference): 3 doubles
        // of CIELAB and 2 of features per pixel.
        if (spec == "box") kept += 40.0 * static_cast<double>(scene.width) * scene.height;
    }
    const double scene_bytes = kVertexBytes * scene.vertices + kContourBytes * scene.contours +
                               kShapeBytes * scene.shapes;
    const double total = scene_bytes + kept + std::max(1, concurrent) * peak_working;
    // Saturate rather than wrap: an absurd job must still read as absurd.
    constexpr double kMax = static_cast<double>(static_cast<std::size_t>(-1) / 2);
    return static_cast<std::size_t>(std::min(total, kMax));
}

double estimate_render_ms(const MethodInstance& method, const SceneSize& scene) {
    return method.method->traits().time_ms(method.params, scene);
}

std::string format_bytes(std::size_t bytes) {
    const double b = static_cast<double>(bytes);
    if (b >= 1024.0 * 1024.0 * 1024.0) return fmt::format("{:.1f} GiB", b / (1u << 30));
    if (b >= 1024.0 * 1024.0) return fmt::format("{:.0f} MiB", b / (1u << 20));
    if (b >= 1024.0) return fmt::format("{:.1f} KiB", b / 1024.0);
    return fmt::format("{} bytes", bytes);
}

void check_job_memory(std::size_t bytes, std::size_t budget, const std::string& what) {
    if (bytes <= budget) return;
    throw InputError(fmt::format(
        "{}: needs about {} by estimate, more than the memory budget of {} (docs/limits.md)",
        what, format_bytes(bytes), format_bytes(budget)));
}

void check_task_count(long long tasks, const std::string& where) {
    if (tasks <= kMaxCompareTasks) return;
    throw InputError(fmt::format("{}: {} tasks, more than the limit of {} (docs/limits.md)",
                                 where, tasks, kMaxCompareTasks));
}

}  // namespace aabench
