// The crossings of horizontal lines taken top to bottom, without sorting each line's crossings
// from scratch: the active edge list of classic scan conversion, kept sorted by x from one
// line to the next. Shared by the point sampler (none, ssaa, nishita-d, fast-edge) and the
// sub-scanline tracer (box-multiscan, gauss-multiscan).
//
// Why: EdgeTable::crossings_at gathers a row's edges and sorts their crossings on every line,
// O(c log c) for c crossings, and on a scene of many long edges (grating: 2,000 crossings on
// every line of a 1024² image) that sort was most of the render. Between two lines the order
// of the crossings changes only where edges cross each other, where a contour's chain of
// edges starts (a local minimum of y, a new pair of crossings) or ends: so the list is
// carried over, each entry moved to its edge's x on the new line, and re-sorted by insertion
// (O(c) when nothing crossed, O(c + swaps) otherwise; past a budget of swaps, a full sort).
// Entries follow the edge chains of EdgeTable (Edge::below): when an edge ends, the next edge
// of its y-monotone chain takes its place at the same x (they share the vertex), so a
// polygonised circle of thousands of edges costs two entries per line, not a re-sort.
//
// Bit for bit: x on each line is Edge::x_at(y) of the edge the line meets, the very value
// crossings_at computes, not an incremental x += dxdy (which would drift by an ulp per line
// and change images). The set of crossings is crossings_at's (y0 <= y < y1); their order is
// crossings_at's wherever the x differ. Among crossings of equal x the order is not defined
// (std::sort is not stable either): ties() says when the last line had any, for callers
// whose result depends on that order (the sub-scanline tracer, which notices ties while it
// walks, then gathers and sorts the row as before, to stay bit-identical with what it always
// computed).
//
// Lines must come in ascending y to be incremental. The first line is reached from the top,
// entering every chain that starts above it (each edge is passed once), so a sweep that only
// goes down never needs the table's row buckets. A line above the previous one (the rotated
// sample grids sample a row's lines out of order) seeks: it rebuilds the list from the line's
// EdgeTable row and sorts it, what crossings_at costs.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "methods/scan/kernel/edge_table.h"

namespace aabench {

class EdgeSweep {
public:
    EdgeSweep() = default;
    explicit EdgeSweep(EdgeTable& table) { reset(table); }
    // Sweeps `table` from now on, from the top, reusing the memory held: no allocation once it
    // has swept a table at least as large. The table may come without row buckets
    // (RowBuckets::kOnDemand): the sweep builds them the first time it has to seek.
    void reset(EdgeTable& table);

    // The crossings of the line at height y, 0 <= y < height, sorted by x (the same crossings
    // as table.crossings_at(y), see above for their order). Valid until the next call.
    std::span<const Crossing> crossings(double y);

    // Whether two crossings of the last line have equal x (their order is then arbitrary).
    bool ties() const;
    // Whether some edge starts or ends exactly on the last line (y0 == y or y1 == y): the
    // sub-scanline tracer's "the two limits differ" test, found while the list is carried
    // over instead of by a search over every endpoint. Exact except after a seek to y == 0,
    // where an edge lying wholly above the image may end on the line unseen.
    bool endpoint_on_line() const { return endpoint_on_line_; }

    // The edges whose chain ends exactly on the last line (y1 == y, no edge below), in no
    // particular order, when known: after crossings() carried the list over (not after a
    // seek, adopt() or move_straight()). With last_crossings() and the chain links, the edges
    // the line's limit from above meets (y0 < y <= y1), without the table's row buckets.
    bool ended_known() const { return ended_known_; }
    std::span<const std::uint32_t> ended_on_line() const { return ended_; }

    // The last line swept (-infinity before the first) and its crossings, as crossings()
    // returned them.
    double last_line() const { return y_; }
    std::span<const Crossing> last_crossings() const { return active_; }
    // The smallest y0 among the chains that have not entered the list yet (+infinity: none).
    // With last_crossings(), what a caller needs to prove that no edge starts between the
    // last line and a lower one.
    double next_entry() const;
    // The heads of the chains that have not entered yet and start above y (y0 < y), in
    // ascending y0 (ties by edge index).
    std::span<const std::uint32_t> entering_before(double y) const;

    // A caller that has itself followed every chain down to the line y > last_line() (the
    // sub-scanline tracer's whole rows) hands the result over instead of advance() doing it
    // again. The caller's proof: no edge of the chains met starts or ends exactly on y, and
    // `list` is then the line's crossings in ascending x, each with the edge it meets, x as
    // Edge::x_at(y), the chains that entered since the last line among them, which are the
    // `entered` next heads. Refused (false, nothing changed) when a chain not listed starts
    // at or above y. move_straight(): the same when every entry keeps its edge, x given.
    bool adopt(double y, std::span<const Crossing> list, std::size_t entered);
    bool move_straight(double y, const double* x);

    // Lines served by seeking and by carrying the list over, since reset() (for tests).
    long seeks() const { return seeks_; }
    long advances() const { return advances_; }

private:
    // adopt() and move_straight(): whether the line y can be taken over (below the last line,
    // inside the image, no chain but the `entered` next heads starting at or above it), and
    // the bookkeeping of having taken it.
    bool can_take(double y, std::size_t entered) const;
    void took(double y, std::size_t entered);
    void seek(double y);
    void advance(double y);
    // The edge of the chain from `edge` downwards that the line y meets (y0 <= y < y1), or -1
    // when the chain ends at or above y; notes every endpoint lying on y on the way. The
    // caller knows edge.y0 <= y.
    int follow(std::uint32_t edge, double y);
    Crossing entry(std::uint32_t edge, double y) const;
    void sort_active();
    void merge_pending();

    EdgeTable* table_ = nullptr;
    std::vector<std::uint32_t> heads_;  // chain heads (Edge::above == -1), ascending y0
    // reset()'s sort keys: (y0, index) side by side, so the sort reads memory in order rather
    // than looking each head's edge up (a third of the time on 400,000 chains).
    std::vector<std::pair<double, std::uint32_t>> head_keys_;
    std::size_t next_head_ = 0;         // heads_[next_head_..] start below the last line
    std::vector<Crossing> active_;      // the last line's crossings, ascending x
    std::vector<Crossing> pending_;     // chains entering on this line
    std::vector<std::uint32_t> ended_;  // see ended_on_line()
    double y_ = -std::numeric_limits<double>::infinity();  // the last line
    bool endpoint_on_line_ = false;
    bool ended_known_ = false;
    long seeks_ = 0, advances_ = 0;
};

}  // namespace aabench
