// The union coverage structure (occlusion_tiles.h): shapes inserted front to back into per-tile
// cell masks with two depth layers, each shape tested against what is already there before it
// is inserted.
#include "harness/reference/occlusion_tiles.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "methods/scan/kernel/visibility_rule.h"

namespace aabench {
namespace {

// A tile is kTileCells x kTileCells cells, a row of them the bits of one word, so that a union
// of shapes over a tile is an OR per row and "every cell covered" a comparison per row.
constexpr int kTileCells = 16;
using RowBits = std::uint16_t;
constexpr RowBits kFullRow = 0xFFFF;
constexpr int kTileShift = 4;  // kTileCells = 1 << kTileShift
static_assert(kTileCells == 1 << kTileShift);
static_assert(sizeof(RowBits) * 8 == kTileCells);
// Cells per shape side: the cell side is the typical shape's smaller side over this. A shape
// wholly contains the cells of its interior, and a seam between two hiding shapes leaves
// uncovered only the cells it crosses (a band about one cell wide), which a third shape over
// the seam must close: on the soup of 200,000 random (often thin) triangles 12 cells per side
// find 43,800 shapes hidden, 16 find 55,600, 24 find 67,400, 32 find 73,000, 48 find 78,300
// (a pass of every shape over the finished structure adds 2). The cost per shape grows with
// the cell rows its box spans (each row's cells are found as intervals, not cell by cell) and
// its tiles; with the pairs' separating-axis test, the whole visibility stage of that soup
// counts 10.83, 10.72 and 11.09 G instructions at 16, 24 and 32: past 24 the structure costs
// more than the pairs it saves.
constexpr double kCellsPerShapeSide = 24.0;
// The grid's caps: 2^21 tiles whatever the shapes (2^29 cells, 96 MiB of tile state), and 8
// tiles per shape, so that the structure's cost stays linear in the shapes: a few large
// shapes with many small ones (a floor to the horizon under pattern cells) would otherwise
// spread the small ones' cell size over the large ones' extent. A coarser grid only decides
// less.
constexpr int kMaxTilesPerAxis = 4096;
constexpr double kMaxTilesTotal = 2097152.0;
constexpr double kMaxTilesPerShape = 8.0;
// The margin between a hiding depth and a hidden one, in depth ties (kDepthTieRelative of
// the planes' term sizes), taken on both sides: four ties, so that the shape that hides
// beats, beyond the tie, every shape the hidden one would have beaten (see occlusion_tiles.h).
constexpr double kMarginTies = 4.0;
constexpr double kNone = -std::numeric_limits<double>::infinity();

struct Grid {
    double x0 = 0.0, y0 = 0.0, cell_x = 1.0, cell_y = 1.0;
    int nx = 1, ny = 1;  // tiles per axis
    int cells_x() const { return nx * kTileCells; }
    int cells_y() const { return ny * kTileCells; }
    // Cell corners, the only place coordinates of the grid are made: every test below reads
    // the corners through these, so neighbouring cells share their corners bit for bit and
    // the cells tile the plane exactly. Both are monotone in the index (each rounding is).
    double corner_x(int i) const { return x0 + i * cell_x; }
    double corner_y(int j) const { return y0 + j * cell_y; }
    // The cell holding x, clamped to the grid. Division rounds, so the caller widens the
    // range it takes by one cell on each side (cells beyond a shape's box test as outside).
    int cell_of_x(double x) const {
        const double c = std::floor((x - x0) / cell_x);
        return static_cast<int>(std::clamp(c, 0.0, cells_x() - 1.0));
    }
    int cell_of_y(double y) const {
        const double c = std::floor((y - y0) / cell_y);
        return static_cast<int>(std::clamp(c, 0.0, cells_y() - 1.0));
    }
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
    double tile = *mid / kCellsPerShapeSide * kTileCells;
    if (!(tile > 0.0)) tile = std::max(w, h);
    double nx = std::clamp(std::ceil(w / tile), 1.0, static_cast<double>(kMaxTilesPerAxis));
    double ny = std::clamp(std::ceil(h / tile), 1.0, static_cast<double>(kMaxTilesPerAxis));
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
    g.cell_x = w > 0.0 ? w / g.cells_x() : 1.0;
    g.cell_y = h > 0.0 ? h / g.cells_y() : 1.0;
    // The last corner must not fall short of the extent by a rounding: a shape's part beyond
    // it would lie in no cell and never be tested.
    constexpr double kUp = std::numeric_limits<double>::infinity();
    while (g.corner_x(g.cells_x()) < all.x1) g.cell_x = std::nextafter(g.cell_x, kUp);
    while (g.corner_y(g.cells_y()) < all.y1) g.cell_y = std::nextafter(g.cell_y, kUp);
    return g;
}

// What is certain over one tile: every point of a cell in `mask` lies in some shape whose
// 1/z_v there is at least `near_layer`, every point of any other cell in one whose 1/z_v is
// at least `far_layer` (kNone: nothing known). near_layer > far_layer while mask is not empty.
// The two layers and their update are those of Hasselgren, Andersson and Akenine-Möller's
// masked occlusion culling (2016), in 1/z_v (larger is nearer).
struct Tile {
    std::array<RowBits, kTileCells> mask{};
    double near_layer = kNone;
    double far_layer = kNone;
};

// Cell intervals [lo, hi] (global cell columns) of one cell row; empty when lo > hi.
struct Span {
    int lo = 0, hi = -1;
};

// A shape's cells in one tile: those wholly inside it and those it may reach (not wholly
// outside one of its edge lines).
struct TileCells {
    int tile = 0;
    std::array<RowBits, kTileCells> inside{};
    std::array<RowBits, kTileCells> reached{};
    bool any_inside = false;
    int base_i = 0, base_j = 0;  // the tile's first cell column and row
};

// The rectangle (local cell columns i0..i1, rows j0..j1) of a non-empty mask's cells: the
// near and far bounds are taken over it, only when a test needs them (most tests end at a
// tile that decides without them), so it is found then, not tracked row by row.
std::array<int, 4> mask_rect(const std::array<RowBits, kTileCells>& mask) {
    unsigned columns = 0;
    int j0 = kTileCells, j1 = -1;
    for (int j = 0; j < kTileCells; ++j) {
        columns |= mask[j];
        if (mask[j] != 0) {
            j0 = std::min(j0, j);
            j1 = j;
        }
    }
    return {std::countr_zero(columns), static_cast<int>(std::bit_width(columns)) - 1, j0, j1};
}

// Where an edge's value crosses zero on a row of corners, in cell columns: on the row, the
// value is v(i) = ay + nx (x_i - x0) at corner column i, and the corners with v > tol (inside)
// are those beyond `at` + `slack`, the corners with v < -tol (outside) those short of
// `at` - `slack` (for nx > 0; mirrored for nx < 0). `slack` covers the tolerance and every
// rounding of the computation (of ay, the division, the corner positions: 16 ulps of each
// magnitude involved, each term a few ulps at most), so the sets are those of the real values:
// a corner counted inside lies inside the edge line by more than the tolerance, one counted
// outside beyond it, whatever the rounding. Where the edge is nearly horizontal the slack
// grows with 1/|nx| and so does the distance of the crossing: a row well inside or outside
// stays so, only the rows the edge crosses lose their cells (conservatively) to the slack.
struct Crossing {
    double at = 0.0;
    double slack = 0.0;
    bool finite = false;
};

Crossing crossing(const Grid& g, const LinearForm& e, double ay, double ay_size, double tol) {
    constexpr double kU = 16.0 * std::numeric_limits<double>::epsilon();
    Crossing c;
    const double x_star = e.x0 - ay / e.nx;
    c.at = (x_star - g.x0) / g.cell_x;
    c.slack = (tol + kU * ay_size) / (std::abs(e.nx) * g.cell_x) +
              kU * (std::abs(x_star) + std::abs(e.x0) + std::abs(g.x0)) / g.cell_x +
              kU * std::abs(c.at) + 1e-9;
    c.finite =
        std::isfinite(c.at) && std::isfinite(c.slack) && std::abs(c.at) < 1e15 && c.slack < 1e15;
    return c;
}

// What the passes read of a shape, copied in the front-to-back order with its edge lines in one
// array: read through the inputs (each shape's edges on the heap, in an order unrelated to
// depth) every shape was a cache miss, a fifth of the structure's time on the soup.
struct ShapeView {
    Bounds box;
    AffinePlane inv_depth;
    double side_tolerance = 0.0;
    double near = 0.0, far = 0.0;  // the vertices' largest and smallest 1/z_v, with the margin
    std::size_t edges_begin = 0, edges_end = 0;
    int shape = 0;
};

// The cells a shape's box covers, widened by a cell each side (cell_of_x rounds).
struct CellRange {
    int ci0, ci1, cj0, cj1;
};
CellRange cell_range(const Grid& g, const Bounds& box) {
    return {
        std::max(g.cell_of_x(box.x0) - 1, 0), std::min(g.cell_of_x(box.x1) + 1, g.cells_x() - 1),
        std::max(g.cell_of_y(box.y0) - 1, 0), std::min(g.cell_of_y(box.y1) + 1, g.cells_y() - 1)};
}

// ceil(x) and floor(x) + 1 clamped to [lo, hi], 0 <= lo < hi, exactly as std::ceil and
// std::floor would give them, by comparisons and one truncation of a value already inside the
// range (where truncation is floor): on the default x86-64 target (no SSE4.1) std::floor and
// std::ceil cost a score of instructions each, and they ran for every corner row and edge.
int ceil_clamped(double x, int lo, int hi) {
    if (!(x > lo)) return lo;
    if (x >= hi) return hi;
    const int t = static_cast<int>(x);
    return t + (t < x);
}
int floor_plus_one_clamped(double x, int lo, int hi) {
    if (!(x >= lo)) return lo;
    if (x >= hi - 1) return hi;
    return static_cast<int>(x) + 1;
}

// Scratch of shape_cells, reused from shape to shape.
struct ShapeScratch {
    std::vector<int> in_lo, in_hi;      // per corner row: corners inside every edge, [lo, hi)
    std::vector<Span> inside, reached;  // per cell row
    std::vector<TileCells> tiles;
    std::vector<TileCells> row_of_tiles;  // the tiles of one tile row of the box, being cut
};

// The cells of shape s over its box, tile by tile, into scratch.tiles. A cell is inside when
// its four corners lie inside every edge line beyond the side tolerance (then, the shape
// being convex, so does the cell), and wholly outside when its four corners lie beyond one
// edge line by the tolerance. On a row of corners an edge's passing corners are a half-line
// bounded by its crossing (Crossing: the slack makes the decision that of the real values),
// and a row's cells are intervals: the cost is per row and edge, not per cell.
void shape_cells(const Grid& g, const ShapeView& s, const std::vector<LinearForm>& all_edges,
                 ShapeScratch& sc) {
    sc.tiles.clear();
    // Named copies, not a structured binding: the lambdas below capture them, which C++17
    // rules (clang-14) refuse for a binding.
    const CellRange range = cell_range(g, s.box);
    const int ci0 = range.ci0, ci1 = range.ci1, cj0 = range.cj0, cj1 = range.cj1;
    const int rows = cj1 - cj0 + 1;  // cell rows; corner rows: one more
    const double tol = s.side_tolerance;
    // Corner columns run over [ci0, ci1 + 1]; cells over [ci0, ci1].
    sc.in_lo.assign(rows + 1, ci0);
    sc.in_hi.assign(rows + 1, ci1 + 2);  // exclusive
    sc.reached.assign(rows, Span{ci0, ci1});
    sc.inside.assign(rows, Span{});
    constexpr double kU = 16.0 * std::numeric_limits<double>::epsilon();
    const int end = ci1 + 2;  // one past the last corner column
    for (std::size_t edge = s.edges_begin; edge < s.edges_end; ++edge) {
        const LinearForm& e = all_edges[edge];
        auto row_terms = [&](int r, double& ay, double& ay_size) {
            const double y = g.corner_y(cj0 + r);
            const double dy = e.ny * (y - e.y0);
            ay = e.k + dy;
            // The corner row's own rounding moves ay by ulps of |ny y|: counted here too.
            ay_size =
                std::abs(e.k) + std::abs(dy) + std::abs(e.ny) * (std::abs(y) + std::abs(e.y0));
        };
        // The crossing is affine in y: computed at the first and last corner rows, and
        // interpolated between (its rounding, relative to the magnitudes, added to the slack).
        Crossing first, last;
        double interpolation_slack = 0.0;
        if (e.nx != 0.0) {
            double ay, ay_size;
            row_terms(0, ay, ay_size);
            first = crossing(g, e, ay, ay_size, tol);
            row_terms(rows, ay, ay_size);
            last = crossing(g, e, ay, ay_size, tol);
            const double y0 = g.corner_y(cj0), y1 = g.corner_y(cj0 + rows);
            interpolation_slack =
                kU * (std::abs(first.at) + std::abs(last.at) +
                      std::abs(last.at - first.at) * (std::abs(y0) + std::abs(y1)) / (y1 - y0));
        }
        const bool interpolate = first.finite && last.finite && std::isfinite(interpolation_slack);
        // A product per row, not a quotient (a division per row and edge was a tenth of the
        // structure's time): its rounding, a few ulps of |last.at - first.at|, is inside the
        // interpolation slack's 16 ulps of |first.at| + |last.at|.
        const double step = (last.at - first.at) / rows;
        const double slack = std::max(first.slack, last.slack) + interpolation_slack;
        // Per corner row: the outside corners [o_lo, o_hi) and inside corners [i_lo, i_hi) of
        // this edge, applied to the rows' inside corners and to the reached cells.
        int prev_lo = 0, prev_hi = 0;
        auto apply = [&](int r, int o_lo, int o_hi, int i_lo, int i_hi) {
            sc.in_lo[r] = std::max(sc.in_lo[r], i_lo);
            sc.in_hi[r] = std::min(sc.in_hi[r], i_hi);
            if (r > 0) {
                // Cells of row r - 1 wholly outside this edge: both corners outside on both
                // corner rows, i.e. cells [lo, hi - 2] of the two rows' common outside corners.
                const int lo = std::max(prev_lo, o_lo), hi = std::min(prev_hi, o_hi);
                if (hi - lo >= 2) {
                    Span& reach = sc.reached[r - 1];
                    if (lo <= ci0) reach.lo = std::max(reach.lo, hi - 1);      // a prefix
                    if (hi >= ci1 + 2) reach.hi = std::min(reach.hi, lo - 1);  // a suffix
                }
            }
            prev_lo = o_lo;
            prev_hi = o_hi;
        };
        if (interpolate && e.nx > 0.0) {  // the value grows along the row
            for (int r = 0; r <= rows; ++r) {
                const double at = first.at + step * r;
                apply(r, ci0, ceil_clamped(at - slack, ci0, end),
                      floor_plus_one_clamped(at + slack, ci0, end), end);
            }
        } else if (interpolate) {  // it falls: outside is a suffix, inside a prefix
            for (int r = 0; r <= rows; ++r) {
                const double at = first.at + step * r;
                apply(r, floor_plus_one_clamped(at + slack, ci0, end), end, ci0,
                      ceil_clamped(at - slack, ci0, end));
            }
        } else {
            // Horizontal or nearly so beyond what the crossing resolves: the whole row on one
            // side when the value at both its ends says so (the value is affine in x), else
            // neither inside nor outside.
            for (int r = 0; r <= rows; ++r) {
                double ay, ay_size;
                row_terms(r, ay, ay_size);
                const double xa = g.corner_x(ci0), xb = g.corner_x(ci1 + 1);
                const double v0 = ay + e.nx * (xa - e.x0), v1 = ay + e.nx * (xb - e.x0);
                const double margin =
                    tol + kU * (ay_size +
                                std::abs(e.nx) * (std::abs(xa) + std::abs(xb) + std::abs(e.x0)));
                const bool outside = v0 < -margin && v1 < -margin;
                const bool inside = v0 > margin && v1 > margin;
                apply(r, ci0, outside ? end : ci0, ci0, inside ? end : ci0);
            }
        }
    }
    for (int r = 0; r < rows; ++r) {
        const int lo = std::max(sc.in_lo[r], sc.in_lo[r + 1]);
        const int hi = std::min(sc.in_hi[r], sc.in_hi[r + 1]) - 2;  // cell hi: corner hi - 1
        if (lo <= hi) sc.inside[r] = Span{lo, hi};
    }
    // Tiles: the rows' intervals cut into bits. A row's interval is cut only into the tiles it
    // meets (one or two, mostly), not into every tile of the box: cutting every tile's every
    // row was a third of the structure's time on the soup.
    const int ti0 = ci0 / kTileCells;
    const int tiles_x = ci1 / kTileCells - ti0 + 1;
    for (int tj = cj0 / kTileCells; tj <= cj1 / kTileCells; ++tj) {
        const int base_j = tj * kTileCells;
        sc.row_of_tiles.assign(tiles_x, TileCells{});
        // Sets row j's bits of the span in each tile it meets (cells are >= 0: shifts, not
        // divisions): the first tile from the span's first cell on, the last up to its last.
        auto cut = [&](const Span& sp, int j, bool inside) {
            if (sp.lo > sp.hi) return;
            const int t0 = (sp.lo >> kTileShift) - ti0, t1 = (sp.hi >> kTileShift) - ti0;
            const auto from_lo = static_cast<RowBits>(kFullRow << (sp.lo & (kTileCells - 1)));
            const auto to_hi =
                static_cast<RowBits>(kFullRow >> (kTileCells - 1 - (sp.hi & (kTileCells - 1))));
            for (int t = t0; t <= t1; ++t) {
                RowBits bits = kFullRow;
                if (t == t0) bits &= from_lo;
                if (t == t1) bits &= to_hi;
                TileCells& tc = sc.row_of_tiles[t];
                (inside ? tc.inside : tc.reached)[j] = bits;
                tc.any_inside |= inside;
            }
        };
        bool any_reached = false;
        for (int j = std::max(cj0 - base_j, 0); j <= std::min(cj1 - base_j, kTileCells - 1);
             ++j) {
            const int r = base_j + j - cj0;
            any_reached |= sc.reached[r].lo <= sc.reached[r].hi;
            cut(sc.reached[r], j, false);
            cut(sc.inside[r], j, true);
        }
        if (!any_reached) continue;
        for (int t = 0; t < tiles_x; ++t) {
            TileCells& tc = sc.row_of_tiles[t];
            if (std::all_of(tc.reached.begin(), tc.reached.end(), [](RowBits m) { return m == 0; })) {
                continue;
            }
            tc.tile = tj * g.nx + ti0 + t;
            tc.base_i = (ti0 + t) * kTileCells;
            tc.base_j = base_j;
            sc.tiles.push_back(tc);
        }
    }
}

// The shape's largest (nearest) or smallest 1/z_v over a rectangle of a tile's cells, with
// the margin, capped by its vertices' own bound: an affine function's extremes over a
// rectangle are at its corners.
double rect_bound(const Grid& g, const ShapeView& s, const TileCells& c,
                  const std::array<RowBits, kTileCells>& mask, bool nearest) {
    const std::array<int, 4> rect = mask_rect(mask);
    double best = nearest ? kNone : std::numeric_limits<double>::infinity(), terms = 0.0;
    for (const double x : {g.corner_x(c.base_i + rect[0]), g.corner_x(c.base_i + rect[1] + 1)}) {
        for (const double y :
             {g.corner_y(c.base_j + rect[2]), g.corner_y(c.base_j + rect[3] + 1)}) {
            const double v = s.inv_depth.at(x, y);
            best = nearest ? std::max(best, v) : std::min(best, v);
            terms = std::max(terms, depth_term_size(s.inv_depth, x, y));
        }
    }
    const double margin = kMarginTies * kDepthTieRelative * terms;
    return nearest ? std::min(s.near, best + margin) : std::max(s.far, best - margin);
}

// True when every cell the shape reaches is certainly nearer than the shape there.
bool hidden_in(const Grid& g, const ShapeView& s, const std::vector<Tile>& tiles,
               const std::vector<TileCells>& cells) {
    for (const TileCells& c : cells) {
        const Tile& t = tiles[c.tile];
        if (t.far_layer > s.near) continue;  // the whole tile is nearer than all of the shape
        if (!(std::max(t.far_layer, t.near_layer) > s.far)) return false;  // neither is nearer
        const double near = rect_bound(g, s, c, c.reached, true);
        if (t.far_layer > near) continue;  // the whole tile is nearer
        if (!(t.near_layer > near)) return false;
        for (int j = 0; j < kTileCells; ++j) {
            if (c.reached[j] & ~t.mask[j]) return false;  // a cell only the far layer holds
        }
    }
    return true;
}

// Adds what the shape covers to its tiles (Hasselgren et al.'s update): its cells join the
// near layer, whose depth becomes the farther of the two; a layer that covers the whole tile
// becomes its far layer. A shape no nearer than the far layer adds nothing; one farther behind
// the near layer than that is in front of the far layer starts a new near layer instead of
// dragging the old one back (the old one's cells fall back to the far layer: still true).
void insert(const Grid& g, const ShapeView& s, std::vector<Tile>& tiles,
            const std::vector<TileCells>& cells) {
    for (const TileCells& c : cells) {
        if (!c.any_inside) continue;
        Tile& t = tiles[c.tile];
        const double far = rect_bound(g, s, c, c.inside, false);
        if (!(far > t.far_layer)) continue;
        const bool empty =
            std::all_of(t.mask.begin(), t.mask.end(), [](RowBits m) { return m == 0; });
        if (empty || t.near_layer - far > t.near_layer - t.far_layer) {
            t.mask = c.inside;
            t.near_layer = far;
        } else {
            for (int j = 0; j < kTileCells; ++j) t.mask[j] |= c.inside[j];
            t.near_layer = std::min(t.near_layer, far);
        }
        if (std::all_of(t.mask.begin(), t.mask.end(), [](RowBits m) { return m == kFullRow; })) {
            t.far_layer = t.near_layer;
            t.mask = {};
            t.near_layer = kNone;
        }
    }
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
    std::vector<Tile> tiles(stats.tiles);

    // Each shape's nearest and farthest 1/z_v (its vertices' largest and smallest: the plane
    // is affine) with the margin; the front-to-back order is by the nearest, nearest first.
    std::vector<ShapeView> views(shapes.size());
    std::size_t edge_count = 0;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const OcclusionInput& s = shapes[k];
        double near = kNone, far = std::numeric_limits<double>::infinity(), terms = 0.0;
        for (const Point& v : *s.poly) {
            const double w = s.inv_depth.at(v.x, v.y);
            near = std::max(near, w);
            far = std::min(far, w);
            terms = std::max(terms, depth_term_size(s.inv_depth, v.x, v.y));
        }
        ShapeView& view = views[k];
        view.box = s.box;
        view.inv_depth = s.inv_depth;
        view.side_tolerance = s.side_tolerance;
        view.near = near + kMarginTies * kDepthTieRelative * terms;
        view.far = far - kMarginTies * kDepthTieRelative * terms;
        view.shape = static_cast<int>(k);
        edge_count += s.edges->size();
    }
    // Nearest first, ties in the input's order: keys sorted, then the views moved once (a
    // stable sort of the views themselves moved 100-byte records log n times).
    {
        std::vector<std::pair<double, int>> order(views.size());
        for (std::size_t k = 0; k < views.size(); ++k) {
            order[k] = {-views[k].near, static_cast<int>(k)};
        }
        std::sort(order.begin(), order.end());
        std::vector<ShapeView> sorted(views.size());
        for (std::size_t k = 0; k < views.size(); ++k) sorted[k] = views[order[k].second];
        views = std::move(sorted);
    }
    std::vector<LinearForm> edges;
    edges.reserve(edge_count);
    for (ShapeView& view : views) {
        view.edges_begin = edges.size();
        const std::vector<LinearForm>& own = *shapes[view.shape].edges;
        edges.insert(edges.end(), own.begin(), own.end());
        view.edges_end = edges.size();
    }

    // Front to back: a shape hidden by what is in already is not inserted (where it is, the
    // structure holds nearer depths than any of its own). A shape whose every tile is wholly
    // covered nearer than its nearest point is hidden without looking at its cells.
    ShapeScratch scratch;
    auto tile_range = [&](const ShapeView& view) {
        const CellRange r = cell_range(g, view.box);
        return std::array<int, 4>{r.ci0 / kTileCells, r.ci1 / kTileCells, r.cj0 / kTileCells,
                                  r.cj1 / kTileCells};
    };
    for (std::size_t q = 0; q < views.size(); ++q) {
        const ShapeView& view = views[q];
        if (q + 1 < views.size()) {  // the next shape's tiles are far from this one's in memory
            const auto [ti0, ti1, tj0, tj1] = tile_range(views[q + 1]);
            for (int tj = tj0; tj <= tj1; ++tj) {
                for (int ti = ti0; ti <= ti1; ++ti) __builtin_prefetch(&tiles[tj * g.nx + ti]);
            }
        }
        const auto [ti0, ti1, tj0, tj1] = tile_range(view);
        bool saturated = true;
        for (int tj = tj0; saturated && tj <= tj1; ++tj) {
            for (int ti = ti0; ti <= ti1; ++ti) {
                if (!(tiles[tj * g.nx + ti].far_layer > view.near)) {
                    saturated = false;
                    break;
                }
            }
        }
        if (saturated) {
            hidden[view.shape] = 1;
            continue;
        }
        shape_cells(g, view, edges, scratch);
        if (hidden_in(g, view, tiles, scratch.tiles)) {
            hidden[view.shape] = 1;
        } else {
            insert(g, view, tiles, scratch.tiles);
        }
    }
    for (const Tile& t : tiles) stats.covered_tiles += t.far_layer != kNone;
    for (const char h : hidden) stats.hidden += h;
    if (stats_out) *stats_out = stats;
    return hidden;
}

}  // namespace aabench
