// blend2d — Blend2D's analytic rasteriser, as an optional peer (built only when CMake is given
// -DAABENCH_BLEND2D_DIR=<install prefix>; docs/peers.md says how to build Blend2D from its
// public source). The fastest analytic rasteriser people use: the benchmark's yardstick for
// `exact`'s speed (docs/benchmarks.md, "`exact` against the peers and Blend2D").
//
// Computes what cairo and agg compute (methods/cairo.cpp): for each fill in order, the
// library's 8-bit coverage of the fill (BLContext::fill_path, nonzero winding, opaque white
// into a BL_FORMAT_A8 image cleared to 0 under the fill's bounding box), read back as
// a = byte / 255 and composited in float over the frame buffer, which starts as the
// background. A fill is a run of consecutive shapes of one value with orientations made
// consistent (methods/scan/kernel/peer_coverage.h, paths=merged): how a user draws the scene.
//
// Library: Blend2D as installed at the prefix (its version in the summary), a synchronous
// single-threaded context (begin() without create info: every call takes effect at once), so
// its time is one thread's, as every other row's. Its cells accumulate exact areas on a
// 1/256 px grid (like AGG's and FreeType's), so vertices are rounded to 1/256 px and coverage
// to a byte. Contours beyond kPeerSafeCoordinate are clipped first, as for the other peers.
// Curved shapes go in as their Bezier outlines (quad_to / cubic_to), as cairo's and agg's do.
//
// Parameters: none.
#include <blend2d/blend2d.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/peer_coverage.h"

namespace aabench {
namespace {

// Per thread and size: the A8 target with its context attached, and the path (BLPath::clear
// keeps its capacity), so a warm render allocates nothing of its own.
struct Blend2dScratch {
    BLImage image;
    BLContext context;
    BLPath path;
    int width = 0, height = 0;

    void ensure(int w, int h) {
        if (width == w && height == h) return;
        context.end();
        if (image.create(w, h, BL_FORMAT_A8) != BL_SUCCESS || context.begin(image) != BL_SUCCESS) {
            width = height = 0;
            throw std::runtime_error(fmt::format("blend2d: cannot make a {}x{} A8 target", w, h));
        }
        width = w;
        height = h;
    }
};

void add_contour(BLPath& path, const Contour& contour, bool reverse) {
    if (contour.empty()) return;
    bool first = true;
    for_each_vertex(contour, reverse, [&](const Point& p) {
        if (first) {
            path.move_to(p.x, p.y);
            first = false;
        } else {
            path.line_to(p.x, p.y);
        }
    });
    path.close();
}

// A contour of Bezier segments as Blend2D's path (quad_to / cubic_to), flattened by Blend2D
// itself: the curves as its users give them.
void add_outline(BLPath& path, const SegmentContour& contour, bool reverse) {
    bool first = true;
    for_each_segment(contour, reverse, [&](const Segment& s) {
        if (first) {
            path.move_to(s.p[0].x, s.p[0].y);
            first = false;
        }
        if (s.degree == 1) {
            path.line_to(s.p[1].x, s.p[1].y);
        } else if (s.degree == 2) {
            path.quad_to(s.p[1].x, s.p[1].y, s.p[2].x, s.p[2].y);
        } else {
            path.cubic_to(s.p[1].x, s.p[1].y, s.p[2].x, s.p[2].y, s.p[3].x, s.p[3].y);
        }
    });
    if (!first) path.close();
}

class Blend2dMethod : public Method {
protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        std::fill(out.row(row_lo), out.row(row_hi), static_cast<float>(scene.background));
        if (scene.width <= 0 || scene.shapes.empty()) return;
        thread_local Blend2dScratch scratch;
        scratch.ensure(scene.width, scene.height);
        BLContext& ctx = scratch.context;
        BLPath& path = scratch.path;
        ctx.restore_clipping();
        // A band is a clip rectangle of whole rows: Blend2D fills its rows only.
        ctx.clip_to_rect(BLRectI(0, row_lo, scene.width, row_hi - row_lo));
        ctx.set_fill_rule(BL_FILL_RULE_NON_ZERO);
        ctx.set_comp_op(BL_COMP_OP_SRC_OVER);
        ctx.set_fill_style(BLRgba32(0xFFFFFFFFu));
        BLImageData data{};
        scratch.image.get_data(&data);
        const auto* pixels = static_cast<const std::uint8_t*>(data.pixel_data);
        const double clip_x0 = -1.0, clip_y0 = -1.0;
        const double clip_x1 = scene.width + 1.0, clip_y1 = scene.height + 1.0;
        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, PeerPaths::kMerged);
            first = run.last;
            PixelBox box = run_pixel_box(scene.shapes, run, scene.width, scene.height);
            box.y0 = std::max(box.y0, row_lo);
            box.y1 = std::min(box.y1, row_hi);
            if (box.empty()) continue;
            ctx.clear_rect(BLRectI(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0));
            path.clear();
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, PeerPaths::kMerged);
                if (draws_outline(shape)) {  // Bezier curves as curves
                    for (const SegmentContour& c : shape.outline) add_outline(path, c, reverse);
                    continue;
                }
                for (const Contour& contour : shape.contours) {
                    if (needs_clipping(contour)) {
                        add_contour(path, clip_contour(contour, clip_x0, clip_y0, clip_x1, clip_y1),
                                    reverse);
                    } else {
                        add_contour(path, contour, reverse);
                    }
                }
            }
            if (ctx.fill_path(path) != BL_SUCCESS) {
                throw std::runtime_error("blend2d: fill_path failed");
            }
            const double value = scene.shapes[run.first].value;
            for (int j = box.y0; j < box.y1; ++j) {
                composite_coverage_row(pixels + static_cast<std::ptrdiff_t>(j) * data.stride + box.x0,
                                       out.row(j) + box.x0, box.x1 - box.x0, value);
            }
        }
    }
};

}  // namespace

// What the harness knows of `blend2d` (methods/method_traits.h).
MethodTraits blend2d_traits() {
    MethodTraits t;
    t.curves = "natively: BLPath quad_to / cubic_to, flattened by Blend2D's own path pipeline";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // An 8-bit coverage plane and the rasteriser's cells, as the other peers.
        return 1.0 * s.width * s.height +
               memory_model::kPeerCellBytes * (s.edge_columns + s.edge_rows);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return cost_model::linear_ms(cost_model::kBlend2d, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px and coverage to 8 bits: steps, not a continuum"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kQuantisedArea,
         "8-bit coverage of cells on a 1/256 px vertex grid"},
    };
    t.hard_cases.figures = [](const ParamValues&) {
        // As AGG's (methods/agg.cpp): a byte of coverage per edge pixel, within two steps, and
        // vertices rounded to 1/256 px.
        return BoundFigures{.coverage_step = 2.0 / 255.0, .vertex_grid_px = 0x1p-8};
    };
    return t;
}

MethodInfo blend2d_method() {
    return {"blend2d",
            fmt::format("Blend2D {}.{}.{} fill_path (nonzero, A8 coverage / 255, synchronous "
                        "single-threaded context), runs of one value as one path, composited "
                        "in float",
                        BL_VERSION >> 16, (BL_VERSION >> 8) & 0xFF, BL_VERSION & 0xFF),
            {},
            [](const ParamValues&) { return std::make_unique<Blend2dMethod>(); }};
}

}  // namespace aabench
