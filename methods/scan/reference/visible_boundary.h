// The boundary of the visible value, shared by the exact references.
//
// The visible value v(x, y) of a scene (the value of the last shape whose nonzero winding
// number is nonzero there, else the background) is piecewise constant. Two views of where it
// jumps:
//
// - BandSweep: row by row, each row cut into horizontal bands inside which no two edges cross
//   and no edge starts or ends. It reports every band with its edges in left-to-right order
//   and the jump of v across each (the box reference accumulates exactly these).
// - The jump set: every segment across which v is discontinuous, with the jump as a weight.
//   Its non-horizontal pieces are the band segments with a nonzero jump; its horizontal
//   pieces lie on band borders, where v just above differs from v just below (horizontal
//   scene edges, edges starting or ending, crossings that change which shape is on top). The
//   box reference never needs those (they enclose no height); radial filters in polar form
//   about a point do (they subtend an angle). See docs/references.md.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "methods/scan/kernel/edge_table.h"
#include "patterns/scene/scene.h"

namespace aabench {

// One boundary inside one crossing-free band: a chain of contour edges running downwards
// (Edge::below links), y-monotone, spanning the band. x_top and x_bottom are its x at the
// band's top and bottom (Edge::x_at, so a later band of the same chain starts exactly where
// this one ends); its straight pieces inside the band are given by for_each_piece().
struct BandSegment {
    double x_top;
    double x_bottom;
    double jump;         // v right of the segment minus v left of it
    double value_right;  // v right of the segment (left of the next one in the band)
    std::uint32_t edge;  // the chain's first edge inside the band (index into EdgeTable::edges())
};

// A crossing-free band [y_top, y_bottom] and its edges in left-to-right order (the order at
// mid-height, which is the order everywhere inside the band). Left of the first segment v is
// the background.
struct Band {
    double y_top;
    double y_bottom;
    std::span<const BandSegment> segments;
};

using BandCallback = std::function<void(const Band&)>;

// Calls fn(x_a, y_a, x_b, y_b) for each straight piece of a band segment's chain inside the
// band, top to bottom (y_a < y_b).
template <class Fn>
void for_each_piece(const EdgeTable& table, const Band& band, const BandSegment& segment, Fn&& fn) {
    const auto& edges = table.edges();
    for (int idx = static_cast<int>(segment.edge); idx >= 0 && edges[idx].y0 < band.y_bottom;
         idx = edges[idx].below) {
        const Edge& e = edges[idx];
        const double ya = std::max(e.y0, band.y_top), yb = std::min(e.y1, band.y_bottom);
        if (yb > ya) fn(e.x_at(ya), ya, e.x_at(yb), yb);
    }
}

class BandSweep {
public:
    // Rows [row_lo, row_hi) may extend beyond the image rows [0, table.height()): a filter
    // whose support reaches outside the image needs the scene there too.
    BandSweep(const EdgeTable& table, int row_lo, int row_hi);

    // Calls on_band for each band of row r (row_lo <= r < row_hi) that holds at least one
    // edge, top to bottom. Bands without edges (v is the background there) are skipped.
    void sweep_row(int r, const BandCallback& on_band);

private:
    // A chain of edges inside the current row: chain_edges_[first, first + count).
    struct Chain {
        std::uint32_t first;
        std::uint32_t count;
        double y_start;
        double y_end;
    };
    // A chain inside one band as an explicit polyline: points_[first, first + count) of
    // (y, x), from the band's top to its bottom.
    struct Active {
        std::uint32_t chain;
        std::uint32_t first;
        std::uint32_t count;
        double x_mid;
    };
    struct YX {
        double y;
        double x;
    };

    std::span<const std::uint32_t> row_edges(int r) const;
    void sweep_band(double ya, double yb, int depth, const BandCallback& on_band);
    void collect_active(double ya, double yb);
    void gap_crossings(const Active& left, const Active& right, double ya, double yb);
    void walk_band(double ya, double yb, const BandCallback& on_band);

    const EdgeTable& table_;
    VisibilityWalker walker_;
    int row_lo_;
    // Edge lists for the rows outside [0, height) (EdgeTable buckets only the image rows).
    std::vector<std::vector<std::uint32_t>> margin_rows_;
    std::vector<double> breaks_;
    std::vector<Chain> chains_;
    std::vector<std::uint32_t> chain_edges_;
    std::vector<Active> active_;
    std::vector<YX> points_;
    std::vector<double> crossings_;
    std::vector<BandSegment> segments_;
};

// One piece of the jump set. `weight` is v on the side where cross(b - a, q - a) > 0 minus v
// on the other side (x right, y down: the right-hand side walking from a to b, so the left of
// a downward segment and the underside of a rightward one). Non-horizontal pieces run
// downwards (a.y < b.y), horizontal ones rightwards (a.y == b.y, a.x < b.x).
struct JumpSegment {
    Point a;
    Point b;
    double weight;
};

// Calls on_segment for every piece of the jump set of the scene's visible value between
// y = row_lo and y = row_hi, top to bottom. Non-horizontal pieces are reported over the whole
// width (a point value needs every edge to its left); horizontal pieces are clipped to
// [x_lo, x_hi]. The window's own top and bottom (where the sweep starts and stops) are
// reported as jumps from and to the background: callers keep them out of reach.
void for_each_jump_segment(const Scene& scene, int row_lo, int row_hi, double x_lo, double x_hi,
                           const std::function<void(const JumpSegment&)>& on_segment);

// The same, collected.
std::vector<JumpSegment> visible_jump_set(const Scene& scene, int row_lo, int row_hi, double x_lo,
                                          double x_hi);

}  // namespace aabench
