// freetype — FreeType's smooth rasterizer (ftgrays: the one behind every Linux and Android
// glyph, and forked by Qt, ThorVG and plutovg), as a peer to the sources' methods.
//
// Computes: for each fill in order, FreeType's 8-bit coverage of the fill, read back as
// a = coverage / 255 and composited in float over the frame buffer, which starts as the
// background (out = out + a (value - out), as agg and cairo do: methods/agg.cpp says why).
//
// How the fill reaches FreeType, as its users give it: an FT_Outline built with FT_Outline_New,
// its points rounded to 26.6 fixed point (FreeType takes 1/64 px, so a point moves by up to
// 1/128 px in x and in y: what every FreeType user gets), curves as FreeType's own tags
// (a quadratic's control FT_CURVE_TAG_CONIC, a cubic's two FT_CURVE_TAG_CUBIC), nonzero fill
// (no FT_OUTLINE_EVEN_ODD_FILL), rendered by FT_Outline_Render with FT_RASTER_FLAG_AA |
// FT_RASTER_FLAG_DIRECT | FT_RASTER_FLAG_CLIP: gray spans handed to a callback, clipped to the
// band's rows. The scene's y-down frame goes in as it is: the rasterizer's rows are the
// image's rows (a flip would mirror nothing but the winding's sign, which nonzero ignores).
//
// What FreeType's coverage is (ftgrays.c): exact area coverage of the outline on the 1/64 px
// grid (cells of cover and area, 8 bits of the area kept: coverage = min(|area| / 2^9, 255)
// after FreeType's own rounding), curves split by FreeType until they lie within its own
// tolerance of their chords (quadratics and cubics: a fixed subdivision bound in 26.6 units),
// then drawn as lines. So on curves its error is its flattening plus the 1/64 px grid.
//
// Discs and rings are drawn as circles of cubic arcs, as FreeType's users draw them (the scene's
// polygonisation of a circle has more points than an outline holds).
//
// Limits of FreeType's outline: FT_Outline counts points and contours in 16 bits (at most
// 32767 of each). A run of shapes that needs more is drawn in parts of whole contours, each
// part's coverage added to the run's and capped at 255 (exact where the parts do not
// overlap); a single contour of more than 32767 points cannot be drawn: not_applicable says so.
// Coordinates beyond kFreeTypeSafeCoordinate (2^17 px, below) are clipped first
// (methods/scan/kernel/peer_coverage.h).
//
// Library: FreeType as packaged by Debian 12 (libfreetype6 2.12.1); the version `list`
// prints is the linked library's (FT_Library_Version).
//
// Parameters:
//   paths  merged|per-shape, default merged: what one fill is (peer_coverage.h), as for agg.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/kernel/peer_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/text.h"

namespace aabench {
namespace {

// FT_Outline's n_points and n_contours are shorts.
constexpr std::size_t kMaxOutlinePoints = SHRT_MAX;
// FT_Span's x is a short: a wider image would wrap.
constexpr int kMaxWidth = SHRT_MAX;
// The widest clip box handed to FreeType at once (render()).
constexpr int kTileWidth = 256;

// FT_Outline_Render refuses an outline whose control box reaches beyond +-2^24 in 26.6 units
// (2^18 px; ftgrays' gray_raster_render, Invalid_Outline): contours reaching beyond 2^17 px
// are clipped near the image first, curves and circles beyond it drawn as their clipped
// polygonisation (a circle's arcs reach 1.04 r from its centre: within 2^18).
constexpr double kFreeTypeSafeCoordinate = 131072.0;

// A point in FreeType's 26.6 fixed point: rounded to 1/64 px.
FT_Vector to_26_6(const Point& p) {
    return {static_cast<FT_Pos>(std::lround(p.x * 64.0)),
            static_cast<FT_Pos>(std::lround(p.y * 64.0))};
}

// One thread's FreeType library (an FT_Library is not to be used from two threads at once)
// and the outline being built: points, tags, contour ends.
struct FreeTypeScratch {
    FT_Library library = nullptr;
    std::vector<FT_Vector> points;
    std::vector<char> tags;
    std::vector<short> contours;
    std::vector<std::uint8_t> coverage;  // the run's, width x height
    int width = 0;
    FT_Error error = 0;       // the last error FT_Outline_Render returned for the run
    bool drawn_part = false;  // a part of the run has been drawn into `coverage`
    FreeTypeScratch() {
        if (FT_Init_FreeType(&library) != 0) throw std::runtime_error("FreeType did not start");
    }
    ~FreeTypeScratch() { FT_Done_FreeType(library); }
    void clear() {
        points.clear();
        tags.clear();
        contours.clear();
    }
};

struct SpanTarget {
    std::uint8_t* coverage;
    int width;
};

// FreeType's gray-spans callback: adds each span's coverage to the run's (capped at 255).
void add_spans(int y, int count, const FT_Span* spans, void* user) {
    const SpanTarget& target = *static_cast<const SpanTarget*>(user);
    std::uint8_t* row = target.coverage + static_cast<std::size_t>(y) * target.width;
    for (int k = 0; k < count; ++k) {
        std::uint8_t* p = row + spans[k].x;
        const int c = spans[k].coverage;
        for (int n = 0; n < spans[k].len; ++n)
            p[n] = static_cast<std::uint8_t>(std::min(255, p[n] + c));
    }
}

// The points a contour of the shape takes in an FT_Outline.
std::size_t outline_points(const SegmentContour& c) {
    std::size_t n = 0;
    for (const Segment& s : c) n += static_cast<std::size_t>(s.degree);
    return n;
}

class FreeTypeMethod : public Method {
public:
    explicit FreeTypeMethod(PeerPaths paths) : paths_(paths) {}

    std::string not_applicable(const Scene& scene) const override {
        if (scene.width > kMaxWidth) {
            return fmt::format("FreeType's spans hold x in 16 bits: images up to {} px wide",
                               kMaxWidth);
        }
        for (const Shape& shape : scene.shapes) {
            if (shape.circle && draws_circle_as_arcs(*shape.circle, kFreeTypeSafeCoordinate)) {
                continue;  // cubic arcs
            }
            if (draws_outline(shape, kFreeTypeSafeCoordinate)) {
                for (const SegmentContour& c : shape.outline) {
                    if (outline_points(c) > kMaxOutlinePoints) {
                        return "a contour of more than 32767 points: FreeType's outline counts "
                               "points in 16 bits";
                    }
                }
                continue;
            }
            for (const Contour& c : shape.contours) {
                if (c.size() > kMaxOutlinePoints) {
                    return "a contour of more than 32767 points: FreeType's outline counts "
                           "points in 16 bits";
                }
            }
        }
        return Method::not_applicable(scene);
    }

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        std::fill(out.row(row_lo), out.row(row_hi), static_cast<float>(scene.background));
        if (scene.width <= 0 || scene.shapes.empty()) return;
        const int width = scene.width, height = scene.height;
        thread_local FreeTypeScratch scratch;
        scratch.coverage.resize(static_cast<std::size_t>(width) * height);
        scratch.width = width;
        for (std::size_t first = 0; first < scene.shapes.size();) {
            const ShapeRun run = next_shape_run(scene.shapes, first, paths_);
            first = run.last;
            PixelBox box = run_pixel_box(scene.shapes, run, width, height);
            box.y0 = std::max(box.y0, row_lo);
            box.y1 = std::min(box.y1, row_hi);
            if (box.empty()) continue;
            for (int j = box.y0; j < box.y1; ++j) {
                std::memset(scratch.coverage.data() + static_cast<std::size_t>(j) * width + box.x0,
                            0, static_cast<std::size_t>(box.x1 - box.x0));
            }
            scratch.clear();
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, paths_);
                if (draws_outline(shape, kFreeTypeSafeCoordinate)) {
                    for (const SegmentContour& c : shape.outline) {
                        make_room(scratch, outline_points(c), box);
                        add_outline_contour(scratch, c, reverse);
                    }
                    continue;
                }
                if (shape.circle && draws_circle_as_arcs(*shape.circle, kFreeTypeSafeCoordinate)) {
                    // As FreeType's users draw a circle: cubic arcs (its polygonisation is
                    // finer than an outline holds).
                    for (const SegmentContour& c : circle_arc_contours(*shape.circle)) {
                        make_room(scratch, outline_points(c), box);
                        add_outline_contour(scratch, c, reverse);
                    }
                    continue;
                }
                for (const Contour& original : shape.contours) {
                    const bool clip = needs_clipping(original, kFreeTypeSafeCoordinate);
                    const Contour clipped =
                        clip ? clip_contour(original, -1.0, -1.0, width + 1.0, height + 1.0)
                             : Contour{};
                    const Contour& contour = clip ? clipped : original;
                    if (contour.size() < 2) continue;
                    make_room(scratch, contour.size(), box);
                    for_each_vertex(contour, reverse, [&](const Point& p) {
                        scratch.points.push_back(to_26_6(p));
                        scratch.tags.push_back(FT_CURVE_TAG_ON);
                    });
                    scratch.contours.push_back(static_cast<short>(scratch.points.size() - 1));
                }
            }
            render(scratch, box);
            const double value = scene.shapes[run.first].value;
            for (int j = box.y0; j < box.y1; ++j) {
                float* row = out.row(j) + box.x0;
                if (scratch.error != 0) {
                    // FreeType refused the fill: its pixels say so (the nonfinite figure).
                    std::fill(row, row + (box.x1 - box.x0),
                              std::numeric_limits<float>::quiet_NaN());
                    continue;
                }
                composite_coverage_row(
                    scratch.coverage.data() + static_cast<std::size_t>(j) * width + box.x0, row,
                    box.x1 - box.x0, value);
            }
            scratch.error = 0;
            scratch.drawn_part = false;
        }
    }

private:
    // Renders what the outline holds when `more` points would not fit in it.
    static void make_room(FreeTypeScratch& s, std::size_t more, const PixelBox& box) {
        if (s.points.size() + more > kMaxOutlinePoints ||
            s.contours.size() + 1 > static_cast<std::size_t>(SHRT_MAX)) {
            render(s, box);
            s.clear();
        }
    }

    // A contour of segments as FreeType's tagged points: the start on the curve, then each
    // segment's controls and end, the last end (the start again) left for FreeType to close.
    static void add_outline_contour(FreeTypeScratch& s, const SegmentContour& c, bool reverse) {
        bool first = true;
        std::size_t k = 0;
        const std::size_t n = c.size();
        for_each_segment(c, reverse, [&](const Segment& seg) {
            if (first) {
                s.points.push_back(to_26_6(seg.p[0]));
                s.tags.push_back(FT_CURVE_TAG_ON);
                first = false;
            }
            const char control = seg.degree == 2 ? FT_CURVE_TAG_CONIC : FT_CURVE_TAG_CUBIC;
            for (int i = 1; i < seg.degree; ++i) {
                s.points.push_back(to_26_6(seg.p[i]));
                s.tags.push_back(control);
            }
            if (++k < n) {
                s.points.push_back(to_26_6(seg.p[seg.degree]));
                s.tags.push_back(FT_CURVE_TAG_ON);
            }
        });
        s.contours.push_back(static_cast<short>(s.points.size() - 1));
    }

    static void render(FreeTypeScratch& s, const PixelBox& box) {
        if (s.contours.empty()) return;
        FT_Outline outline{};
        outline.n_points = static_cast<short>(s.points.size());
        outline.n_contours = static_cast<short>(s.contours.size());
        outline.points = s.points.data();
        outline.tags = s.tags.data();
        outline.contours = s.contours.data();
        outline.flags = FT_OUTLINE_NONE;
        SpanTarget target{s.coverage.data(), s.width};
        FT_Raster_Params params{};
        params.flags = FT_RASTER_FLAG_AA | FT_RASTER_FLAG_DIRECT | FT_RASTER_FLAG_CLIP;
        params.gray_spans = add_spans;
        params.user = &target;
        // FreeType's cell pool holds a band of rows at a time and splits a band that
        // overflows it down to one row; a row crossing more cells than the pool holds (a fill
        // thousands of pixels wide) fails with Raster_Overflow, after the bands above it have
        // been drawn. The fill is drawn whole first, as FreeType's users draw it; when that
        // fails, its box is cleared and drawn again in tiles of kTileWidth columns, each a clip
        // box of its own (cells left of a clip box keep their cover in ftgrays, so a tile's
        // coverage is the whole fill's), whose rows fit: 1024 columns overflowed on the hard
        // case image-16384x16 (a 16,377 px slanted edge), 256 do not. A part of a run drawn
        // after another (more than 32767 points) goes straight to tiles: its box already holds
        // coverage that a clear would lose. A fill FreeType still refuses is drawn as NaN.
        if (!s.drawn_part) {
            params.clip_box = {box.x0, box.y0, box.x1, box.y1};  // whole pixels
            const FT_Error error = FT_Outline_Render(s.library, &outline, &params);
            s.drawn_part = true;
            if (error != FT_Err_Raster_Overflow) {
                if (error != 0) s.error = error;
                return;
            }
            for (int j = box.y0; j < box.y1; ++j) {
                std::memset(s.coverage.data() + static_cast<std::size_t>(j) * s.width + box.x0, 0,
                            static_cast<std::size_t>(box.x1 - box.x0));
            }
        }
        for (int x0 = box.x0; x0 < box.x1; x0 += kTileWidth) {
            params.clip_box = {x0, box.y0, std::min(box.x1, x0 + kTileWidth), box.y1};
            const FT_Error error = FT_Outline_Render(s.library, &outline, &params);
            if (error != 0) s.error = error;
        }
    }

    PeerPaths paths_;
};

}  // namespace

// What the harness knows of `freetype` (methods/method_traits.h).
MethodTraits freetype_traits() {
    MethodTraits t;
    t.curves = "natively: FT_Outline conic / cubic tags, flattened by FreeType's own subdivision";
    t.working_bytes = [](const ParamValues&, const SceneSize& s) {
        // An 8-bit coverage plane, the outline's points and FreeType's cell pool.
        return 1.0 * s.width * s.height + 24.0 * s.vertices +
               memory_model::kPeerCellBytes * (s.edge_columns + s.edge_rows);
    };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        // Not fitted yet: AGG's coefficients (the same cell accumulator, ftgrays' ancestor).
        return cost_model::linear_ms(cost_model::kAgg, s.pixels(), s.vertices);
    };
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kLocalChanges,
         "points rounded to 1/64 px and coverage to 8 bits: steps, not a continuum"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kQuantisedArea,
         "8-bit coverage on a 1/64 px point grid"},
    };
    t.hard_cases.figures = [](const ParamValues&) {
        // 8-bit coverage within 2/255 of c per edge pixel; points rounded to 1/64 px move an
        // edge by at most 2^-7 px in x and y (the area by at most its length x 2^-7 x sqrt 2,
        // below length x 2^-6).
        return BoundFigures{.coverage_step = 2.0 / 255.0, .vertex_grid_px = 0x1p-6};
    };
    return t;
}

MethodInfo freetype_method() {
    return {
        "freetype",
        fmt::format("FreeType {} smooth rasterizer (FT_Outline_Render, gray spans, 26.6 points, "
                    "nonzero), composited in float",
                    freetype_version()),
        {{"paths",
          ParamKind::kChoice,
          0,
          0,
          0,
          {"merged", "per-shape"},
          "merged: each run of consecutive shapes of one value is one outline (orientations "
          "made consistent), as a user drawing the scene as one path; per-shape: one outline "
          "per shape, composited where shapes meet"}},
        [](const ParamValues& p) {
            return std::make_unique<FreeTypeMethod>(peer_paths_from_name(p.get_choice("paths")));
        }};
}

}  // namespace aabench
