// The tile occlusion structure (occlusion_tiles.h): one pass marks each tile with the nearest
// depth certain over it, a second finds the shapes every one of whose tiles is nearer.
#include "harness/reference/occlusion_tiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "methods/scan/visibility_rule.h"

namespace aabench {
namespace {

// Tiles per shape side: a shape contains whole tiles only when a tile is well below its own
// width (a triangle's inscribed square is under half its smaller side); a sixth of the
// typical shape's smaller side lets a triangle of that size contain several.
constexpr double kTilesPerShapeSide = 6.0;
// The grid's caps: 2048 tiles per axis and 2^22 tiles (32 MiB of depths) whatever the shapes,
// and 64 tiles per shape (the kTilesPerShapeSide^2 = 36 a typical shape spans, with room), so
// that the structure's cost stays linear in the shapes: a few large shapes with many small
// ones (a floor to the horizon under pattern cells) would otherwise spread the small ones'
// tile size over the large ones' extent (2^22 tiles for 2,000 shapes). A coarser grid only
// decides less.
constexpr int kMaxTilesPerAxis = 2048;
constexpr double kMaxTilesTotal = 4194304.0;
constexpr double kMaxTilesPerShape = 64.0;
// The margin between a hiding depth and a hidden one, in depth ties (kDepthTieRelative of
// the planes' term sizes): four ties, so that the shape that hides beats, beyond the tie,
// every shape the hidden one would have beaten (see occlusion_tiles.h).
constexpr double kMarginTies = 4.0;

struct Grid {
    double x0 = 0.0, y0 = 0.0, side_x = 1.0, side_y = 1.0;
    int nx = 1, ny = 1;
    int ix(double x) const {
        const double c = std::floor((x - x0) / side_x);
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(nx - 1)));
    }
    int iy(double y) const {
        const double c = std::floor((y - y0) / side_y);
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(ny - 1)));
    }
    Point corner(int i, int j) const { return {x0 + i * side_x, y0 + j * side_y}; }
};

Grid make_grid(const std::vector<OcclusionInput>& shapes) {
    Bounds all = shapes[0].box;
    std::vector<double> small_sides;
    small_sides.reserve(shapes.size());
    for (const OcclusionInput& s : shapes) {
        all.x0 = std::min(all.x0, s.box.x0);
        all.y0 = std::min(all.y0, s.box.y0);
        all.x1 = std::max(all.x1, s.box.x1);
        all.y1 = std::max(all.y1, s.box.y1);
        small_sides.push_back(std::min(s.box.x1 - s.box.x0, s.box.y1 - s.box.y0));
    }
    const auto mid = small_sides.begin() + static_cast<std::ptrdiff_t>(small_sides.size() / 2);
    std::nth_element(small_sides.begin(), mid, small_sides.end());
    const double w = all.x1 - all.x0, h = all.y1 - all.y0;
    double side = *mid / kTilesPerShapeSide;
    if (!(side > 0.0)) side = std::max(w, h);
    double nx = std::clamp(std::ceil(w / side), 1.0, static_cast<double>(kMaxTilesPerAxis));
    double ny = std::clamp(std::ceil(h / side), 1.0, static_cast<double>(kMaxTilesPerAxis));
    const double max_tiles =
        std::min(kMaxTilesTotal, kMaxTilesPerShape * static_cast<double>(shapes.size()));
    if (nx * ny > max_tiles) {
        const double shrink = std::sqrt(max_tiles / (nx * ny));
        nx = std::max(1.0, std::floor(nx * shrink));
        ny = std::max(1.0, std::floor(ny * shrink));
    }
    Grid g;
    g.x0 = all.x0;
    g.y0 = all.y0;
    g.nx = static_cast<int>(nx);
    g.ny = static_cast<int>(ny);
    g.side_x = w > 0.0 ? w / g.nx : 1.0;
    g.side_y = h > 0.0 ? h / g.ny : 1.0;
    return g;
}

bool inside(const OcclusionInput& s, const Point& p) {
    for (const LinearForm& e : *s.edges) {
        if (!(e.at(p) > s.side_tolerance)) return false;
    }
    return true;
}

// True when the tile [lo, hi] lies wholly outside one of the shape's edge lines (beyond the
// side tolerance), so that no point of the shape is in it.
bool wholly_outside(const OcclusionInput& s, const Point& lo, const Point& hi) {
    for (const LinearForm& e : *s.edges) {
        if (e.at(lo) < -s.side_tolerance && e.at({hi.x, lo.y}) < -s.side_tolerance &&
            e.at({lo.x, hi.y}) < -s.side_tolerance && e.at(hi) < -s.side_tolerance) {
            return true;
        }
    }
    return false;
}

}  // namespace

std::vector<char> wholly_hidden(const std::vector<OcclusionInput>& shapes,
                                OcclusionStats* stats_out) {
    std::vector<char> hidden(shapes.size(), 0);
    OcclusionStats stats;
    if (shapes.size() < 2) {
        if (stats_out) *stats_out = stats;
        return hidden;
    }
    const Grid g = make_grid(shapes);
    stats.tiles = static_cast<std::size_t>(g.nx) * g.ny;
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    std::vector<double> certain(stats.tiles, kNone);

    // Pass 1: every tile wholly inside a shape gets the shape's far depth on it (its corners'
    // smallest 1/z_v, less the margin), the nearest such over the shapes.
    for (const OcclusionInput& s : shapes) {
        // Tiles whose corners all lie within the box: first corner index >= box.x0, last <= x1.
        const int i0 = static_cast<int>(std::ceil((s.box.x0 - g.x0) / g.side_x));
        const int i1 = static_cast<int>(std::floor((s.box.x1 - g.x0) / g.side_x)) - 1;
        const int j0 = static_cast<int>(std::ceil((s.box.y0 - g.y0) / g.side_y));
        const int j1 = static_cast<int>(std::floor((s.box.y1 - g.y0) / g.side_y)) - 1;
        for (int j = std::max(j0, 0); j <= std::min(j1, g.ny - 1); ++j) {
            for (int i = std::max(i0, 0); i <= std::min(i1, g.nx - 1); ++i) {
                double far = std::numeric_limits<double>::infinity(), terms = 0.0;
                bool all_in = true;
                for (const Point& c : {g.corner(i, j), g.corner(i + 1, j), g.corner(i, j + 1),
                                       g.corner(i + 1, j + 1)}) {
                    if (!inside(s, c)) {
                        all_in = false;
                        break;
                    }
                    far = std::min(far, s.inv_depth.at(c.x, c.y));
                    terms = std::max(terms, depth_term_size(s.inv_depth, c.x, c.y));
                }
                if (!all_in) continue;
                double& t = certain[static_cast<std::size_t>(j) * g.nx + i];
                t = std::max(t, far - kMarginTies * kDepthTieRelative * terms);
            }
        }
    }
    for (const double t : certain) stats.covered_tiles += t != kNone;

    // Pass 2: a shape is hidden when each tile its box touches is certainly nearer than the
    // shape's nearest point there (its vertices' largest 1/z_v, or its plane's at the tile's
    // corners, whichever is smaller: both bound it on the shape's part of the tile).
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const OcclusionInput& s = shapes[k];
        double near_all = -std::numeric_limits<double>::infinity(), terms_all = 0.0;
        for (const Point& v : *s.poly) {
            near_all = std::max(near_all, s.inv_depth.at(v.x, v.y));
            terms_all = std::max(terms_all, depth_term_size(s.inv_depth, v.x, v.y));
        }
        const double bound_all = near_all + kMarginTies * kDepthTieRelative * terms_all;
        bool is_hidden = true;
        for (int j = g.iy(s.box.y0); is_hidden && j <= g.iy(s.box.y1); ++j) {
            for (int i = g.ix(s.box.x0); i <= g.ix(s.box.x1); ++i) {
                const double t = certain[static_cast<std::size_t>(j) * g.nx + i];
                if (t == kNone || !(t > bound_all)) {
                    // A tile of the box that the shape does not reach needs no cover: most of
                    // a small triangle's box is outside it.
                    if (wholly_outside(s, g.corner(i, j), g.corner(i + 1, j + 1))) continue;
                    // The tile's own bound may still be nearer than the shape there.
                    double near = -std::numeric_limits<double>::infinity(), terms = 0.0;
                    for (const Point& c : {g.corner(i, j), g.corner(i + 1, j),
                                           g.corner(i, j + 1), g.corner(i + 1, j + 1)}) {
                        near = std::max(near, s.inv_depth.at(c.x, c.y));
                        terms = std::max(terms, depth_term_size(s.inv_depth, c.x, c.y));
                    }
                    if (t == kNone || !(t > near + kMarginTies * kDepthTieRelative * terms)) {
                        is_hidden = false;
                        break;
                    }
                }
            }
        }
        hidden[k] = is_hidden;
        stats.hidden += is_hidden;
    }
    if (stats_out) *stats_out = stats;
    return hidden;
}

}  // namespace aabench
