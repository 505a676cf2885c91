// The memory estimate (harness/measure/limits.h, docs/limits.md). Every constant is the size of a data
// structure the code really allocates, rounded up, with the vector growth slack where a vector
// grows by push_back (up to 2x its final size).
#include "harness/measure/limits.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "harness/reference/filter_reference.h"
#include "methods/method.h"
#include "methods/scan/piece_coverage.h"
#include "methods/scan/subscanline.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// A stored vertex: Point (16 bytes) in a Contour.
constexpr double kVertexBytes = 16.0;
// Per contour and per shape: a vector header (24) plus allocator overhead, rounded up.
constexpr double kContourBytes = 64.0;
constexpr double kShapeBytes = 96.0;
// EdgeTable: one Edge (7 doubles/ints, 56 bytes) per edge, in a vector grown by push_back
// (x2), plus the per-contour index (4 bytes per edge), plus one 4-byte bucket entry per
// (edge, row) pair and 4 bytes per row.
constexpr double kEdgeBytes = 2.0 * 56.0 + 4.0;
constexpr double kEdgeRowBytes = 4.0;
constexpr double kRowBytes = 4.0;
// Sub-scanline tracer and band sweep: sorted endpoint heights (16 bytes per edge) and chain
// bookkeeping (about 48 bytes per edge in the worst row).
constexpr double kSweepBytesPerEdge = 64.0;
// box-multiscan's whole-row sums, per chain besides its x and places per line: first and end
// lines and edge (4 each), its change (8), its entry in the list handed to the sweep (24),
// rounded up, and vectors grown by resize (x2).
constexpr double kRowTrackBytes = 2.0 * 48.0;
// The fast exact engine (fast_coverage.cpp, its Scratch), per edge at most: the Edge record
// (56 bytes) grown by push_back (x2), the contour index, bucket entry, active entry and rank
// (4 each), an event height (8, x2), and a Chain (48 bytes) in each of two vectors (x2).
constexpr double kFastEdgeBytes = 2.0 * 56.0 + 4 * 4.0 + 2.0 * 8.0 + 2.0 * 2.0 * 48.0;
// Per pixel, the most `exact` keeps for affine values or curves: the curve compositing's 21
// bytes (value, base, flag, list head) plus, for a run of polygons among curves, its two
// double rasters and the polygon engine's one (24), rounded up: 48.
constexpr double kCurvePixelBytes = 48.0;
// AGG's rasteriser keeps one 16-byte cell per pixel an edge passes through (grown in blocks);
// Cairo's tor converter keeps per-edge records and a cell per crossed pixel, about the same.
constexpr double kPeerCellBytes = 32.0;

struct Working {
    double bytes = 0.0;  // working memory while the task runs
    double kept = 0.0;   // what stays: the output image or raster
};

double edge_table_bytes(const SceneSize& s) {
    return kEdgeBytes * s.vertices + kEdgeRowBytes * s.edge_rows + kRowBytes * (s.height + 1);
}

Working method_working(const MethodInstance& m, const SceneSize& s) {
    const double pixels = static_cast<double>(s.width) * s.height;
    const double table = edge_table_bytes(s);
    Working w;
    w.kept = 4.0 * pixels;  // the float32 output
    if (m.id == "exact" || m.id == "exact-8bit") {
        // The fast engine (fast_coverage.cpp): its own edge records, chains and events, one
        // row of double accumulators; rows where boundaries cross also build the edge table
        // and the band sweep. Per-pixel state only for affine values and curves: affine values
        // take one double raster (piece_coverage.h); curves (curve_coverage.cpp) keep value
        // and base (doubles), a flag and a list head per pixel (21 bytes) over the curves'
        // boxes, and each run of polygons among them two double rasters plus the polygon
        // engine's own: kCurvePixelBytes covers the lot.
        w.bytes = kFastEdgeBytes * s.vertices + 8.0 * (s.width + 32) + kRowBytes * (s.height + 1) +
                  table + kSweepBytesPerEdge * s.vertices +
                  (s.exact_raster ? kCurvePixelBytes * pixels : 0.0);
    } else if (m.id == "box-multiscan" || m.id == "gauss-multiscan") {
        // Two rows of per-pixel sums (double, with one pixel of margin each side).
        w.bytes = table + kSweepBytesPerEdge * s.vertices + 4.0 * 8.0 * (s.width + 2);
        const int n = m.params.get_int("n");
        if (m.id == "box-multiscan" && n <= SubscanlineTracer::kMaxRowIntervals) {
            // The whole-row sums (subscanline_rows.cpp): per chain met, its x on the n + 1
            // lines (double) and its place among them per line (int), plus a few fields and
            // its entry in the list handed to the sweep, vectors grown by resize (x2); a row
            // meets at most every vertex.
            w.bytes += (2.0 * 12.0 * (n + 1) + kRowTrackBytes) * s.vertices;
        }
    } else if (m.id == "ssaa") {
        const double k = m.params.get_int("k");
        // Sample positions and values of one sample row (double, k per pixel, two pixels of
        // margin for the Gaussian), and for the Gaussian a double accumulator per pixel.
        w.bytes = table + 2.0 * 8.0 * k * (s.width + 2);
        if (m.params.get_choice("filter") == "gaussian") w.bytes += 8.0 * pixels;
    } else if (m.id == "nishita-d") {
        // Five lattice rows of 2 W + 3 doubles, and the positions.
        w.bytes = table + 6.0 * 8.0 * (2.0 * s.width + 3.0);
    } else if (m.id == "fast-edge") {
        w.bytes = table + 4.0 * pixels;  // the z-buffer of shape indices
    } else if (m.id == "cairo" || m.id == "agg") {
        // An 8-bit coverage plane (Cairo pads rows to 4 bytes) and the rasteriser's cells.
        w.bytes = 1.0 * (s.width + 3) * s.height + kPeerCellBytes * (s.edge_columns + s.edge_rows);
    } else {
        // none, and any method this table does not know yet: the edge table and a row.
        w.bytes = table + 3.0 * 8.0 * s.width;
    }
    return w;
}

Working reference_working(const std::string& spec, const SceneSize& s) {
    const double pixels = static_cast<double>(s.width) * s.height;
    Working w;
    w.kept = 8.0 * pixels;
    const std::string canonical = canonical_reference_spec(spec);  // checks the spec
    if (canonical == "box") {
        w.bytes = edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices;
    } else {
        // The radial references add a difference raster (double, W + 1 per row) and sweep the
        // rows within the filter's radius beyond the image too (at most 8 px each side).
        const RadialFilter f = parse_radial_filter(spec);
        const double margin_rows = 2.0 * (std::ceil(f.radius_px) + 2.0);
        w.bytes = edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices +
                  8.0 * (s.width + 1.0) * s.height + kEdgeRowBytes * s.vertices * margin_rows;
    }
    return w;
}

}  // namespace

SceneSize measure_scene(const Scene& scene) {
    SceneSize s;
    s.width = scene.width;
    s.height = scene.height;
    s.shapes = static_cast<long long>(scene.shapes.size());
    s.exact_raster = has_affine_values(scene) || has_curves(scene);
    const Scene* window = &scene;
    Scene shifted;
    if (has_origin(scene)) {
        // Only the window frame says which rows an edge overlaps; the copy is of the scene the
        // methods will copy anyway.
        shifted = in_window_frame(scene);
        window = &shifted;
    }
    for (const Shape& shape : window->shapes) {
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
    }
    const double scene_bytes = kVertexBytes * scene.vertices + kContourBytes * scene.contours +
                               kShapeBytes * scene.shapes;
    const double total = scene_bytes + kept + std::max(1, concurrent) * peak_working;
    // Saturate rather than wrap: an absurd job must still read as absurd.
    constexpr double kMax = static_cast<double>(static_cast<std::size_t>(-1) / 2);
    return static_cast<std::size_t>(std::min(total, kMax));
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
