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
// How a run reaches FreeType: as its users hand it glyphs, one connected group of contours at a
// time (a glyph with its counters; shapes that overlap or abut stay together), all into one
// coverage plane. The groups touch disjoint pixels, so this is the coverage of the run as one
// outline to the bit (outline_parts, below, says why it is also far faster on a page of text).
// Limits of FreeType's outline: FT_Outline counts points and contours in 16 bits (at most
// 32767 of each). A polygon group that needs more is drawn in tiles, each contour clipped to
// the tile (render_tiles); a group with curves that needs more is drawn in parts of whole
// contours, each part's coverage added and capped at 255 (exact where the parts do not
// overlap); a single contour of more than 32767 points cannot be drawn: not_applicable says so.
// Coordinates beyond kFreeTypeSafeCoordinate (2^17 px, below) are clipped first
// (methods/scan/kernel/peer_coverage.h).
//
// Library: FreeType as packaged by Debian 12 (libfreetype6 2.12.1); the version `list`
// prints is the linked library's (FT_Library_Version).
//
// Parameters:
//   paths  merged|per-shape, default merged: what one fill is (peer_coverage.h), as for agg.
//   blend  linear|srgb, default linear: composited in linear light, or in sRGB codes as a text
//          stack that blends glyph coverage into an sRGB frame buffer without linearising
//          (peer_coverage.h, PeerBlend; the gamma question of docs/text.md).
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
// The most points of a tile (render_tiles): ftgrays decomposes a whole outline again for every
// band of rows it renders, so small tiles of a large group cost far less than full outlines
// (rings at 1024²: 2.2 s in tiles of up to 32767 points).
constexpr std::size_t kTilePoints = 4096;

// FT_Span's x is a short: a wider image would wrap.
constexpr int kMaxWidth = SHRT_MAX;
// The widest clip box handed to FreeType at once (render_part).
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

struct OutlinePart {
    std::size_t first = 0, count = 0;  // its contours: s.group_contours[first, first + count)
    PixelBox box;
    bool cut = false;
    bool tiles = false;  // a polygon group beyond one outline: drawn in tiles (render_tiles)
};

// One thread's FreeType library (an FT_Library is not to be used from two threads at once)
// and the outline being built: points, tags, contour ends.
struct FreeTypeScratch {
    FT_Library library = nullptr;
    // The run's outline as it is built: points, tags and each contour's end (one past its
    // last point), in size_t, so that a run of any size can be staged before it is split.
    std::vector<FT_Vector> points;
    std::vector<char> tags;
    std::vector<std::size_t> ends;
    // One FT_Outline handed to FreeType: a part of the run (short contour ends).
    std::vector<FT_Vector> part_points;
    std::vector<char> part_tags;
    std::vector<short> part_ends;
    std::vector<std::uint8_t> coverage;  // the run's, width x height
    std::vector<std::uint8_t> part;      // one part's, added into `coverage`
    // outline_parts' buffers: each contour's pixel box, the union-find, the sweep, the groups.
    std::vector<PixelBox> boxes;
    std::vector<std::size_t> parent, by_x, active, group_of, group_contours;
    std::vector<OutlinePart> groups, parts;
    int width = 0;
    FT_Error error = 0;  // the last error FT_Outline_Render returned for the run
    FreeTypeScratch() {
        if (FT_Init_FreeType(&library) != 0) throw std::runtime_error("FreeType did not start");
    }
    ~FreeTypeScratch() { FT_Done_FreeType(library); }
    void clear() {
        points.clear();
        tags.clear();
        ends.clear();
    }
};

// The pixel box of contour k's points (26.6, control points included: they bound the curve).
PixelBox contour_box(const FreeTypeScratch& s, std::size_t k) {
    const std::size_t begin = k == 0 ? 0 : s.ends[k - 1];
    FT_Pos x0 = s.points[begin].x, x1 = x0, y0 = s.points[begin].y, y1 = y0;
    for (std::size_t i = begin + 1; i < s.ends[k]; ++i) {
        x0 = std::min(x0, s.points[i].x);
        x1 = std::max(x1, s.points[i].x);
        y0 = std::min(y0, s.points[i].y);
        y1 = std::max(y1, s.points[i].y);
    }
    // Whole pixels around it: floor of the low side, one past the high side's floor.
    return {static_cast<int>(x0 >> 6), static_cast<int>(y0 >> 6), static_cast<int>(x1 >> 6) + 1,
            static_cast<int>(y1 >> 6) + 1};
}

bool boxes_overlap(const PixelBox& a, const PixelBox& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// A run's contours in the groups FreeType is handed one at a time, as its users hand it glyphs:
// contours whose pixel boxes overlap, directly or through others, form one group (a glyph's
// counters with its bowls, shapes that overlap or abut). Two groups touch no pixel in common, so
// drawing them one by one into one plane gives the coverage of the whole run drawn as one outline
// to the bit (a pixel's coverage comes from its row's cells, and a closed contour's cover sums to
// zero outside it), without FreeType decomposing a page-long outline again for every band of
// rows (ftgrays does: 41 ms instead of 465 ms for a 1024-px page of 12-px text). Groups are found
// by a sweep over the boxes in x (union-find) and kept in the order of their first contour. A
// group that alone exceeds FT_Outline's 16-bit counts (the nested rings of `rings` at 1024²:
// 123,052 points in one group) is drawn in tiles when it is a polygon: each contour clipped to
// the tile (Sutherland–Hodgman, which keeps the winding number of every point inside it), so each
// tile's coverage is the group's there (render_tiles). A group with curves
// that exceeds an outline is cut in contour order into parts marked `cut`, whose coverages add
// where they overlap (over-covered there, capped at 255).
// Fills s.parts (and the buffers behind it, all in the scratch: a warm render allocates
// nothing).
void outline_parts(FreeTypeScratch& s) {
    const std::size_t n = s.ends.size();
    s.boxes.resize(n);
    s.parent.resize(n);
    s.by_x.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        s.boxes[k] = contour_box(s, k);
        s.parent[k] = k;
        s.by_x[k] = k;
    }
    auto find = [&s](std::size_t k) {
        while (s.parent[k] != k) k = s.parent[k] = s.parent[s.parent[k]];
        return k;
    };
    std::sort(s.by_x.begin(), s.by_x.end(),
              [&s](std::size_t a, std::size_t b) { return s.boxes[a].x0 < s.boxes[b].x0; });
    s.active.clear();  // boxes whose x range may still meet the sweep's
    for (const std::size_t k : s.by_x) {
        std::erase_if(s.active, [&](std::size_t a) { return s.boxes[a].x1 <= s.boxes[k].x0; });
        for (const std::size_t a : s.active) {
            if (boxes_overlap(s.boxes[a], s.boxes[k])) s.parent[find(a)] = find(k);
        }
        s.active.push_back(k);
    }
    // Groups numbered in the order of their first contour; their contours laid out one group
    // after another (a counting sort), each in contour order.
    s.group_of.assign(n, SIZE_MAX);
    s.groups.clear();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t root = find(k);
        if (s.group_of[root] == SIZE_MAX) {
            s.group_of[root] = s.groups.size();
            s.groups.push_back({0, 0, s.boxes[k], false, false});
        }
        OutlinePart& g = s.groups[s.group_of[root]];
        ++g.count;
        g.box = {std::min(g.box.x0, s.boxes[k].x0), std::min(g.box.y0, s.boxes[k].y0),
                 std::max(g.box.x1, s.boxes[k].x1), std::max(g.box.y1, s.boxes[k].y1)};
    }
    std::size_t offset = 0;
    for (OutlinePart& g : s.groups) {
        g.first = offset;
        offset += g.count;
        g.count = 0;
    }
    s.group_contours.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        OutlinePart& g = s.groups[s.group_of[find(k)]];
        s.group_contours[g.first + g.count++] = k;
    }
    auto points_of = [&s](std::size_t k) { return s.ends[k] - (k == 0 ? 0 : s.ends[k - 1]); };
    s.parts.clear();
    for (OutlinePart g : s.groups) {
        const std::size_t* contours = s.group_contours.data() + g.first;
        std::size_t points = 0;
        for (std::size_t q = 0; q < g.count; ++q) points += points_of(contours[q]);
        if (points <= kMaxOutlinePoints && g.count <= static_cast<std::size_t>(SHRT_MAX)) {
            s.parts.push_back(g);
            continue;
        }
        bool polygon = true;
        for (std::size_t q = 0; q < g.count && polygon; ++q) {
            const std::size_t k = contours[q];
            const std::size_t begin = k == 0 ? 0 : s.ends[k - 1];
            polygon = std::all_of(s.tags.begin() + begin, s.tags.begin() + s.ends[k],
                                  [](char t) { return t == FT_CURVE_TAG_ON; });
        }
        if (polygon) {  // drawn in tiles, each contour clipped to the tile
            g.tiles = true;
            s.parts.push_back(g);
            continue;
        }
        OutlinePart piece{g.first, 0, g.box, true, false};
        std::size_t piece_points = 0;
        for (std::size_t q = 0; q < g.count; ++q) {
            const std::size_t m = points_of(contours[q]);
            if (piece.count > 0 && (piece_points + m > kMaxOutlinePoints ||
                                    piece.count + 1 > static_cast<std::size_t>(SHRT_MAX))) {
                s.parts.push_back(piece);
                piece = {g.first + q, 0, g.box, true, false};
                piece_points = 0;
            }
            ++piece.count;
            piece_points += m;
        }
        s.parts.push_back(piece);
    }
}

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
    FreeTypeMethod(PeerPaths paths, PeerBlend blend) : paths_(paths), blend_(blend) {}

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
            scratch.error = 0;
            for (std::size_t k = run.first; k < run.last; ++k) {
                const Shape& shape = scene.shapes[k];
                const bool reverse = reverse_for_run(shape, paths_);
                if (draws_outline(shape, kFreeTypeSafeCoordinate)) {
                    for (const SegmentContour& c : shape.outline) {
                        add_outline_contour(scratch, c, reverse);
                    }
                    continue;
                }
                if (shape.circle && draws_circle_as_arcs(*shape.circle, kFreeTypeSafeCoordinate)) {
                    // As FreeType's users draw a circle: cubic arcs (its polygonisation is
                    // finer than an outline holds).
                    for (const SegmentContour& c : circle_arc_contours(*shape.circle)) {
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
                    for_each_vertex(contour, reverse, [&](const Point& p) {
                        scratch.points.push_back(to_26_6(p));
                        scratch.tags.push_back(FT_CURVE_TAG_ON);
                    });
                    scratch.ends.push_back(scratch.points.size());
                }
            }
            render_run(scratch, box);
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
                    box.x1 - box.x0, value, blend_);
            }
        }
    }

private:
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
        s.ends.push_back(s.points.size());
    }

    // The staged run into s.coverage (cleared over `box` by the caller), group by group
    // (outline_parts). A run of one group is drawn straight into s.coverage. Otherwise each part
    // is drawn into s.part over its box and added (capped at 255): a part's box may hold another
    // group's pixels, and a retry in tiles (render_part) clears the box it draws in.
    static void render_run(FreeTypeScratch& s, const PixelBox& box) {
        if (s.ends.empty()) return;
        outline_parts(s);
        for (const OutlinePart& part : s.parts) {
            const PixelBox pbox{std::max(part.box.x0, box.x0), std::max(part.box.y0, box.y0),
                                std::min(part.box.x1, box.x1), std::min(part.box.y1, box.y1)};
            if (pbox.empty()) continue;
            if (part.tiles) {
                render_tiles(s, part, pbox);
                continue;
            }
            load_part(s, s.group_contours.data() + part.first, part.count);
            if (s.parts.size() == 1) {
                render_part(s, s.coverage.data(), pbox);
                continue;
            }
            s.part.resize(s.coverage.size());
            clear_part(s, pbox);
            render_part(s, s.part.data(), pbox);
            add_part(s, pbox);
        }
    }

    // s.part zeroed over `box`.
    static void clear_part(FreeTypeScratch& s, const PixelBox& box) {
        for (int j = box.y0; j < box.y1; ++j) {
            std::memset(s.part.data() + static_cast<std::size_t>(j) * s.width + box.x0, 0,
                        static_cast<std::size_t>(box.x1 - box.x0));
        }
    }

    // s.part over `box` added into s.coverage, capped at 255.
    static void add_part(FreeTypeScratch& s, const PixelBox& box) {
        for (int j = box.y0; j < box.y1; ++j) {
            const std::size_t at = static_cast<std::size_t>(j) * s.width;
            for (int i = box.x0; i < box.x1; ++i) {
                s.coverage[at + i] =
                    static_cast<std::uint8_t>(std::min(255, s.coverage[at + i] + s.part[at + i]));
            }
        }
    }

    // A polygon group too large for one outline, over `box`: the box is halved across its longer
    // side until the group's contours clipped to a tile (one pixel beyond it on every side, so
    // that the clip's own edges lie outside the pixels drawn) fit kTilePoints; each tile is drawn
    // with itself as the clip box. Sutherland–Hodgman keeps the winding number of every point
    // inside the clip rectangle, and ftgrays keeps the cover of cells left of a clip box, so a
    // tile's coverage is the group's there. Each half clips the contours already clipped to its
    // parent (the work is the points times the depth, not the points times the tiles). A single
    // pixel that still does not fit one outline is drawn in parts of its clipped contours
    // (coverage added, as for `cut`). This path allocates: only groups beyond one outline.
    static void render_tiles(FreeTypeScratch& s, const OutlinePart& group, const PixelBox& box) {
        s.part.resize(s.coverage.size());
        std::vector<Contour> polygons;
        polygons.reserve(group.count);
        for (std::size_t q = 0; q < group.count; ++q) {
            const std::size_t k = s.group_contours[group.first + q];
            const std::size_t begin = k == 0 ? 0 : s.ends[k - 1];
            Contour& polygon = polygons.emplace_back();
            for (std::size_t i = begin; i < s.ends[k]; ++i) {
                polygon.push_back({s.points[i].x / 64.0, s.points[i].y / 64.0});
            }
        }
        std::vector<const Contour*> all;
        all.reserve(polygons.size());
        for (const Contour& polygon : polygons) all.push_back(&polygon);
        render_tile(s, all, box);
    }

    // `polygons` clipped to `tile` (with its margin): a polygon wholly outside is left out, one
    // wholly inside passed on as it is, the others clipped into `owned` (reserved first, so
    // the pointers into it stay valid for the halves).
    static void render_tile(FreeTypeScratch& s, const std::vector<const Contour*>& polygons,
                            const PixelBox& tile) {
        const double x0 = tile.x0 - 1.0, y0 = tile.y0 - 1.0, x1 = tile.x1 + 1.0, y1 = tile.y1 + 1.0;
        std::vector<Contour> owned;
        owned.reserve(polygons.size() + 64);  // the clipped contours and the winding rectangles
        int winding = 0;
        std::vector<const Contour*> clipped;
        clipped.reserve(polygons.size());
        std::size_t points = 0;
        for (const Contour* polygon : polygons) {
            double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
            for (const Point& p : *polygon) {
                bx0 = std::min(bx0, p.x);
                bx1 = std::max(bx1, p.x);
                by0 = std::min(by0, p.y);
                by1 = std::max(by1, p.y);
            }
            if (bx1 <= x0 || bx0 >= x1 || by1 <= y0 || by0 >= y1) continue;  // no point inside
            if (bx0 >= x0 && bx1 <= x1 && by0 >= y0 && by1 <= y1) {
                clipped.push_back(polygon);
                points += polygon->size();
                continue;
            }
            // A contour with no edge through the rectangle adds one winding number to all of it
            // (a ring round the tile): summed into `winding`, drawn as rectangles below, not
            // clipped into a rectangle each (a thousand nested rings would never fit a tile).
            if (!crosses_rectangle(*polygon, x0, y0, x1, y1)) {
                winding += winding_number(*polygon, 0.5 * (x0 + x1), 0.5 * (y0 + y1));
                continue;
            }
            Contour c = clip_contour(*polygon, x0, y0, x1, y1);
            if (c.size() < 3) continue;
            points += c.size();
            owned.push_back(std::move(c));
            clipped.push_back(&owned.back());
        }
        if (winding != 0) {
            // The rectangle itself, once per unit of winding, turned to carry its sign.
            Contour rectangle = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            if ((winding_number(rectangle, 0.5 * (x0 + x1), 0.5 * (y0 + y1)) > 0) != (winding > 0)) {
                std::reverse(rectangle.begin(), rectangle.end());
            }
            for (int k = 0; k < std::abs(winding); ++k) {
                owned.push_back(rectangle);
                clipped.push_back(&owned.back());
                points += rectangle.size();
            }
        }
        const int w = tile.x1 - tile.x0, h = tile.y1 - tile.y0;
        if (points > kTilePoints && (w > 1 || h > 1)) {
            PixelBox a = tile, b = tile;
            if (w >= h) {
                a.x1 = b.x0 = tile.x0 + w / 2;
            } else {
                a.y1 = b.y0 = tile.y0 + h / 2;
            }
            render_tile(s, clipped, a);
            render_tile(s, clipped, b);
            return;
        }
        clear_part(s, tile);
        // One outline per kMaxOutlinePoints of the clipped contours (one, but for a single pixel
        // crossed by more edges than an outline holds).
        for (std::size_t first = 0; first < clipped.size();) {
            s.part_points.clear();
            s.part_tags.clear();
            s.part_ends.clear();
            for (; first < clipped.size(); ++first) {
                const Contour& c = *clipped[first];
                if (!s.part_ends.empty() &&
                    (s.part_points.size() + c.size() > kMaxOutlinePoints ||
                     s.part_ends.size() + 1 > static_cast<std::size_t>(SHRT_MAX))) {
                    break;
                }
                for (const Point& p : c) {
                    s.part_points.push_back(to_26_6(p));
                    s.part_tags.push_back(FT_CURVE_TAG_ON);
                }
                s.part_ends.push_back(static_cast<short>(s.part_points.size() - 1));
            }
            render_part(s, s.part.data(), tile);
        }
        add_part(s, tile);
    }

    // Copies the staged contours part[0, count) into the outline handed over.
    static void load_part(FreeTypeScratch& s, const std::size_t* part, std::size_t count) {
        s.part_points.clear();
        s.part_tags.clear();
        s.part_ends.clear();
        for (std::size_t q = 0; q < count; ++q) {
            const std::size_t k = part[q];
            const std::size_t begin = k == 0 ? 0 : s.ends[k - 1];
            s.part_points.insert(s.part_points.end(), s.points.begin() + begin,
                                 s.points.begin() + s.ends[k]);
            s.part_tags.insert(s.part_tags.end(), s.tags.begin() + begin, s.tags.begin() + s.ends[k]);
            s.part_ends.push_back(static_cast<short>(s.part_points.size() - 1));
        }
    }

    // The loaded outline into `plane` (zero over `box`), clipped to `box`.
    static void render_part(FreeTypeScratch& s, std::uint8_t* plane, const PixelBox& box) {
        FT_Outline outline{};
        outline.n_points = static_cast<short>(s.part_points.size());
        outline.n_contours = static_cast<short>(s.part_ends.size());
        outline.points = s.part_points.data();
        outline.tags = s.part_tags.data();
        outline.contours = s.part_ends.data();
        outline.flags = FT_OUTLINE_NONE;
        SpanTarget target{plane, s.width};
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
        // case image-16384x16 (a 16,377 px slanted edge), 256 do not. A fill FreeType still
        // refuses is drawn as NaN.
        params.clip_box = {box.x0, box.y0, box.x1, box.y1};  // whole pixels
        FT_Error error = FT_Outline_Render(s.library, &outline, &params);
        if (error != FT_Err_Raster_Overflow) {
            if (error != 0) s.error = error;
            return;
        }
        for (int j = box.y0; j < box.y1; ++j) {
            std::memset(plane + static_cast<std::size_t>(j) * s.width + box.x0, 0,
                        static_cast<std::size_t>(box.x1 - box.x0));
        }
        for (int x0 = box.x0; x0 < box.x1; x0 += kTileWidth) {
            params.clip_box = {x0, box.y0, std::min(box.x1, x0 + kTileWidth), box.y1};
            error = FT_Outline_Render(s.library, &outline, &params);
            if (error != 0) s.error = error;
        }
    }

    PeerPaths paths_;
    PeerBlend blend_;
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
        // Fitted as every row (methods/cost_model.h); dense scenes are under-predicted.
        return cost_model::linear_ms(cost_model::kFreeType, s.pixels(), s.vertices);
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
          "per shape, composited where shapes meet"},
         {"blend",
          ParamKind::kChoice,
          0,
          0,
          0,
          {"linear", "srgb"},
          "linear: coverage blended in linear light; srgb: in sRGB codes, as a text stack "
          "blending into an sRGB frame buffer without linearising (white on black thinner, "
          "black on white bolder)"}},
        [](const ParamValues& p) {
            return std::make_unique<FreeTypeMethod>(peer_paths_from_name(p.get_choice("paths")),
                                                    peer_blend_from_name(p.get_choice("blend")));
        }};
}

}  // namespace aabench
