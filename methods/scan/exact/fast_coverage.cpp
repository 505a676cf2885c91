// The fast exact box engine (fast_coverage.h): what it computes, and why it is exact.
//
// Same value as the double engine (box_coverage.cpp, whose essay this builds on): for pixel
// (i, j) the integral over the pixel square of the visible value v, the value of the last
// shape whose nonzero winding number is nonzero there, else the background. In a horizontal
// band in which no two boundaries cross and none starts or ends, v = background + the sum of
// the jumps dv of the boundaries left of the point, so each pixel gets the sum over the
// boundaries of dv times the area of the pixel right of the boundary: the "area and cover"
// accumulation of FreeType's smooth rasteriser, font-rs and Blend2D, one diff array per row
// and a prefix sum along it.
//
// What makes it fast, and the proof obligations each shortcut carries:
//
// - Chains, not edges. Consecutive contour edges that keep running downwards are linked into
//   chains (Edge::below): a polygonal circle of 1000 vertices is two chains per row, however
//   many of its vertices lie in the row. A chain can start or end only at a vertex that is
//   not a strict monotone pass-through (a turning point; a vertex beside a horizontal edge
//   counts as one, conservatively). Those heights are the only places a row is cut into
//   sub-bands when nothing crosses. Heights that are integers need no cut (the half-open rule
//   y0 <= y < y1 picks the chains alive just below a row's top).
// - A certificate instead of a crossing search. In each sub-band the chains are sorted by
//   (x at the top, x at the bottom), and only neighbours in that order are checked: if every
//   neighbour pair keeps x_right - x_left >= 0 at every vertex height of either chain (both
//   are polylines, so their difference is piecewise linear and its sign at the breakpoints
//   decides it), then by transitivity the sorted order is a valid left-to-right order at
//   every height of the sub-band, touching allowed, and one walk (per-shape winding numbers,
//   the topmost nonzero shape) gives every chain its jump dv. Chains whose x-ranges in the
//   sub-band are disjoint pass without looking at their vertices. The test compares computed
//   x values with a slack of kOrderSlackPx = 1e-9 px (shared edges of 3-D pieces, split at
//   different vertices, differ by rounding): an overlap of at most that width treated as an
//   order misassigns at most 1e-9 px^2 x |jump| per pixel, far below the 1e-6 bound the test
//   holds the engine to. The sort itself starts from the order of the sub-band above (rank
//   hints on the edges that continue each chain), so it is an insertion sort in about linear
//   time (sort_chains).
// - The general path. A row whose certificate fails anywhere (two boundaries cross: self-
//   intersecting contours, overlapping shapes) is done again from scratch by the double
//   engine's band sweep (visible_boundary.h), which splits bands at crossings. That path
//   builds an EdgeTable for the whole scene, once per call, and so allocates: only scenes
//   with crossings take it (none of the built-in 2-D patterns from 256^2 up do; strips at
//   96^2 has strips poking into their neighbours; the pieces of the 3-D patterns send 2-14
//   % of their rows; the differential test counts how many rows each path wrote).
// - Steady rows. A row with no event, no edge entering or leaving, and every chain one edge
//   across it, whose chains (in the order of the row above) pass the order test and the
//   certificate, has the same sorted chain sequence as the row above, so the walk would give
//   every chain the same dv: the row reuses the row above's dv and does no chain records,
//   sort, rank hints or walk (steady_row). Rows with cuts, chains of several edges, chains
//   starting or ending carry the same chains through each cut, inserting those that start
//   and removing those that end, and walk the dv again only when the set changed
//   (tracked_row). Both test the order on every sub-band as the general path tests its sorted
//   chains (a failed test sends the row to the general path), so what they accumulate is what
//   the general path accumulates, bit for bit (same x_at calls, same add_segment arguments).
//   Both live in fast_tracked.cpp.
// - Accumulation in double, output in float, sparse resolve: methods/scan/kernel/cells.h. Rows
// no
//   edge reaches are filled with the background.
// - No allocation once warm: every buffer lives in a thread_local Scratch whose vectors keep
//   their capacity between calls (one Method object renders from several TBB threads at once
//   in `compare --jobs`, and bands of one image render on several threads).
// - Huge coordinates. The scene is in its window frame (the prepared frame subtracted the
//   origin once, harness/world/frame.h; scene.cpp says why one subtraction is as good as
//   exact); everything after is the double arithmetic of the reference.
#include "methods/scan/exact/fast_coverage.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "methods/scan/exact/fast_engine_p.h"

namespace aabench {
namespace fast_engine {

thread_local Scratch<double> t_scratch;
thread_local Scratch<ChannelValues> t_colour_scratch;

template <class V>
void FastEngine<V>::run(typename Output::Out& out, FastCoverageStats& stats) {
    s_.cells.reset(width_);
    s_.cover.reset(static_cast<int>(scene_.shapes.size()));
    if constexpr (!kGrey) {
        s_.palette.resize(scene_.shapes.size());
        for (std::size_t k = 0; k < scene_.shapes.size(); ++k) {
            const Shape& shape = scene_.shapes[k];
            s_.palette[k] = {channel_value(shape, 0), channel_value(shape, 1),
                             channel_value(shape, 2)};
        }
    }
    extract_edges();
    bucket_edges();
    s_.rank.assign(s_.edges.size(), -1);
    s_.active.clear();
    for (int j = lo_; j < hi_; ++j) render_row(j, Output::row(out, j), stats);
    // sort_chains() swaps `chains` and `ranked`, so which buffer is which after a render
    // depends on how many sorts it did (steady and tracked rows do none): both kept as large
    // as the larger, so that the next render of the scene finds either big enough.
    const std::size_t capacity = std::max(s_.chains.capacity(), s_.ranked.capacity());
    s_.chains.reserve(capacity);
    s_.ranked.reserve(capacity);
    // The same for steady_row's swap of steady_x and steady_x_next.
    const std::size_t x_capacity = std::max(s_.steady_x.capacity(), s_.steady_x_next.capacity());
    s_.steady_x.reserve(x_capacity);
    s_.steady_x_next.reserve(x_capacity);
}

template <class V>
void FastEngine<V>::extract_edges() {
    s_.edges.clear();
    s_.events.clear();
    for (int shape = 0; shape < static_cast<int>(scene_.shapes.size()); ++shape) {
        for (const Contour& contour : scene_.shapes[shape].contours) add_contour(contour, shape);
    }
    std::sort(s_.events.begin(), s_.events.end());
}

template <class V>
void FastEngine<V>::add_contour(const Contour& contour, int shape) {
    const std::size_t n = contour.size();
    if (n == 0) return;
    const double lo = lo_, hi = hi_;
    // Only the edges with a part in the rows of this call.
    append_contour_edges(contour, shape, s_.edges, s_.contour_index, lo, hi);
    for (std::size_t k = 0; k < n; ++k) {
        // Turning points (anything but a strict monotone pass-through) cut sub-bands.
        const double y = contour[k].y;
        const double yp = contour[k == 0 ? n - 1 : k - 1].y;  // no `% n`: see edge_table
        const double yn = contour[k + 1 == n ? 0 : k + 1].y;
        const bool monotone = (yp < y && y < yn) || (yp > y && y > yn);
        if (!monotone && y > lo && y < hi && y != std::floor(y)) s_.events.push_back(y);
    }
}

// Counting sort of the edges by the first row of this call they reach.
template <class V>
void FastEngine<V>::bucket_edges() {
    const std::size_t rows = static_cast<std::size_t>(hi_ - lo_);
    s_.bucket_start.assign(rows + 1, 0);
    auto first_row = [&](const Edge& e) {
        // Clamped in double first: y0 may be -1e300. floor(max(lo, y0)) is max(lo, floor(y0))
        // for an integer lo, and truncation is floor for max(lo, y0) >= lo >= 0: one
        // conversion instead of std::floor's masked sequence (baseline x86-64 has no roundsd).
        const double y = std::max<double>(lo_, e.y0);
        return static_cast<std::size_t>(static_cast<std::int64_t>(y)) -
               static_cast<std::size_t>(lo_);
    };
    // Each edge's row kept from the counting pass: the fill then reads 4 bytes an edge
    // instead of the edge records (56 bytes apart) again.
    const std::size_t n = s_.edges.size();
    s_.edge_rows.resize(n);
    std::uint32_t* edge_row = s_.edge_rows.data();
    std::uint32_t* count = s_.bucket_start.data() + 1;
    for (std::size_t idx = 0; idx < n; ++idx) {
        const auto row = static_cast<std::uint32_t>(first_row(s_.edges[idx]));
        edge_row[idx] = row;
        ++count[row];
    }
    for (std::size_t r = 0; r < rows; ++r) s_.bucket_start[r + 1] += s_.bucket_start[r];
    s_.bucket_edges.resize(n);
    // Fill from the back of each bucket so the start array can serve as the cursor.
    for (std::uint32_t idx = static_cast<std::uint32_t>(n); idx-- > 0;) {
        s_.bucket_edges[--count[edge_row[idx]]] = idx;
    }
    // bucket_start[r + 1] now holds the start of bucket r; shift back.
    for (std::size_t r = 0; r < rows; ++r) s_.bucket_start[r] = s_.bucket_start[r + 1];
    s_.bucket_start[rows] = static_cast<std::uint32_t>(s_.edges.size());
}

template <class V>
void FastEngine<V>::render_row(int j, typename Output::Row out, FastCoverageStats& stats) {
    const std::size_t r = static_cast<std::size_t>(j - lo_);
    const double top = j, bottom = j + 1.0;
    ++stats.rows;
    // Events of this row (sorted); a call's events all lie in its rows.
    auto ev = std::lower_bound(s_.events.begin(), s_.events.end(), top);
    const auto ev_end = std::lower_bound(ev, s_.events.end(), bottom);
    if (steady_) {
        const bool entering = s_.bucket_start[r] != s_.bucket_start[r + 1];
        const bool one_edge = !entering && ev == ev_end && steady_min_y1_ >= bottom;
        // The edges the chains had at the row's top: steady_row keeps them, tracked_row
        // copies them first.
        const std::vector<std::uint32_t>& top_edges = one_edge ? s_.steady_edge : s_.top_edges;
        const std::int64_t bands =
            one_edge ? (steady_row(top, bottom) ? 1 : 0) : tracked_row(r, top, bottom, ev, ev_end);
        if (bands > 0) {
            stats.sub_bands += bands;
            s_.cells.resolve(background_, out);
            return;
        }
        // An order changed, or something the tracked path does not follow: the general path
        // does the row from scratch, from the active edges it would have had.
        s_.cells.clear();
        steady_ = false;
        s_.active.clear();
        for (const std::uint32_t idx : top_edges) {
            if (s_.edges[idx].y0 < top) s_.active.push_back(idx);  // the others enter below
        }
    }
    for (std::uint32_t k = s_.bucket_start[r]; k < s_.bucket_start[r + 1]; ++k) {
        s_.active.push_back(s_.bucket_edges[k]);
    }
    std::erase_if(s_.active, [&](std::uint32_t idx) { return s_.edges[idx].y1 <= top; });
    if (s_.active.empty()) {
        Output::fill(out, width_, background_);
        ++stats.empty_rows;
        return;
    }
    bool ok = true;
    double ya = top;
    for (; ok && ev != ev_end; ++ev) {
        if (*ev <= ya) continue;  // duplicates
        ok = sub_band(ya, *ev);
        ++stats.sub_bands;
        ya = *ev;
    }
    if (ok) {
        ok = sub_band(ya, bottom);
        ++stats.sub_bands;
        if (ok) {
            keep_chain_order(ya);
            begin_steady(bottom);
        }
    }
    if (!ok) {
        s_.cells.clear();
        fallback_row(j);
        ++stats.fallback_rows;
    }
    s_.cells.resolve(background_, out);
}

// After a row done by the general path: its last sub-band's chains, in their order with their
// dv, moved on to the edges that hold the next row's top, are where the next rows continue.
template <class V>
void FastEngine<V>::begin_steady(double bottom) {
    const auto& chains = s_.chains;
    const std::size_t n = chains.size();
    s_.steady_edge.resize(n);
    s_.steady_x.resize(n);
    s_.steady_dv.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        s_.steady_edge[k] = chains[k].last;
        s_.steady_x[k] = chains[k].x_bottom;
        s_.steady_dv[k] = s_.chain_dv[k];
    }
    if (move_on(bottom)) walk_steady();
    steady_fields_ = false;
    double min_y1 = HUGE_VAL;
    for (const std::uint32_t idx : s_.steady_edge) min_y1 = std::min(min_y1, s_.edges[idx].y1);
    steady_min_y1_ = min_y1;
    steady_ = true;
}

// After the row's last sub-band (top ya): the active edges that headed its chains first, in
// the chains' left-to-right order, then the others as they were. The next row builds its
// chains in this order, so where nothing crossed or entered they come out sorted and
// sort_chains() only checks it (a grating's edges arrive right edge before left edge, and
// were sorted anew on every row). Only the order of the list changes, not the sorted chains,
// so the image is the same bit for bit.
template <class V>
void FastEngine<V>::keep_chain_order(double ya) {
    const auto& edges = s_.edges;
    s_.reorder.clear();
    for (const Chain& c : s_.chains) s_.reorder.push_back(c.head);
    for (const std::uint32_t idx : s_.active) {
        if (!(edges[idx].y0 <= ya && ya < edges[idx].y1)) s_.reorder.push_back(idx);
    }
    // Copied back, not swapped: the two buffers keep their own capacities (no allocation
    // once warm).
    s_.active.assign(s_.reorder.begin(), s_.reorder.end());
}

// One crossing-free candidate sub-band [ya, yb]: chains, sort, certificate, walk. Returns
// false, having accumulated nothing, when the certificate fails.
template <class V>
bool FastEngine<V>::sub_band(double ya, double yb) {
    const auto& edges = s_.edges;
    // Written in place (no push_back of a temporary: building the record on the stack and
    // copying it stalled on store forwarding, a quarter of the time on gratings).
    s_.chains.resize(s_.active.size());
    Chain* chain = s_.chains.data();
    for (const std::uint32_t idx : s_.active) {
        const Edge& head = edges[idx];
        if (!(head.y0 <= ya && ya < head.y1)) continue;
        const double x_top = x_at(head, ya);
        double x_min = x_top, x_max = x_top;
        std::uint32_t cur = idx, pieces = 1;
        while (edges[cur].y1 < yb) {
            const double x = edges[cur].x1;
            x_min = std::min(x_min, x);
            x_max = std::max(x_max, x);
            const int next = edges[cur].below;
            if (next < 0) return false;  // a chain ends inside: cannot happen (events cut there)
            cur = static_cast<std::uint32_t>(next);
            ++pieces;
        }
        const double x_bottom = x_at(edges[cur], yb);
        chain->x_top = x_top;
        chain->x_bottom = x_bottom;
        chain->x_min = std::min(x_min, x_bottom);
        chain->x_max = std::max(x_max, x_bottom);
        chain->head = idx;
        chain->pieces = pieces;
        chain->last = cur;
        ++chain;
    }
    s_.chains.resize(static_cast<std::size_t>(chain - s_.chains.data()));
    if (s_.chains.empty()) return true;
    sort_chains();
    for (std::size_t k = 1; k < s_.chains.size(); ++k) {
        if (!ordered(s_.chains[k - 1], s_.chains[k], ya, yb)) return false;
    }
    value_ = background_;
    s_.chain_dv.resize(s_.chains.size());
    for (std::size_t k = 0; k < s_.chains.size(); ++k) {
        const Chain& c = s_.chains[k];
        const Edge& e = edges[c.head];
        const V before = value_;
        const V dv = cross(e.shape, e.winding) - before;
        s_.chain_dv[k] = dv;
        if (!is_zero(dv)) accumulate_chain(c, ya, yb, dv);
    }
    // Every closed contour crosses a full line with net winding 0, so all counts are back to
    // 0; reset anyway so that no state can leak into the next sub-band.
    s_.cover.clear();
    return true;
}

// Sorts s_.chains by chain_before. Boundaries keep their order from one sub-band to the next
// except where they cross or start, so the chains are first put in the order of the sub-band
// above (rank hints left on the edges that continue them), new ones after, and insertion sort
// finishes in about linear time; with many new chains, a full sort.
template <class V>
void FastEngine<V>::sort_chains() {
    auto& chains = s_.chains;
    auto& ranked = s_.ranked;
    if (std::is_sorted(chains.begin(), chains.end(), chain_before)) {
        set_rank_hints();  // already in order (active edges often are): nothing to move
        return;
    }
    ranked.assign(chains.size(), Chain{});
    std::size_t unranked = 0;
    // Slots by rank; collisions and unranked chains go to the back, after the ranked ones.
    std::vector<Chain>& tail = chains;  // reused in place: unranked chains compacted to its front
    for (const Chain& c : chains) {
        const int r = s_.rank[c.head];
        if (r >= 0 && static_cast<std::size_t>(r) < ranked.size() && ranked[r].pieces == 0) {
            ranked[r] = c;
        } else {
            tail[unranked++] = c;
        }
    }
    std::size_t n = 0;
    for (const Chain& c : ranked) {
        if (c.pieces != 0) ranked[n++] = c;
    }
    std::copy(tail.begin(), tail.begin() + static_cast<std::ptrdiff_t>(unranked),
              ranked.begin() + static_cast<std::ptrdiff_t>(n));
    chains.swap(ranked);
    if (unranked > kMaxUnrankedForInsertion) {
        std::sort(chains.begin(), chains.end(), chain_before);
    } else {
        for (std::size_t k = 1; k < chains.size(); ++k) {
            if (!chain_before(chains[k], chains[k - 1])) continue;
            const Chain c = chains[k];
            std::size_t m = k;
            for (; m > 0 && chain_before(c, chains[m - 1]); --m) chains[m] = chains[m - 1];
            chains[m] = c;
        }
    }
    set_rank_hints();
}

// Hints for the sub-band below: the edge that will hold its top, on each chain.
template <class V>
void FastEngine<V>::set_rank_hints() {
    const auto& chains = s_.chains;
    for (std::size_t k = 0; k < chains.size(); ++k) {
        const Edge& last = s_.edges[chains[k].last];
        s_.rank[chains[k].last] = static_cast<int>(k);
        if (last.below >= 0) s_.rank[last.below] = static_cast<int>(k);
    }
}

// True when b lies right of (or on) a at every height of [ya, yb].
template <class V>
bool FastEngine<V>::ordered(const Chain& a, const Chain& b, double ya, double yb) const {
    if (a.x_max <= b.x_min) return true;
    if (a.pieces == 1 && b.pieces == 1) {
        return a.x_top <= b.x_top + kOrderSlackPx && a.x_bottom <= b.x_bottom + kOrderSlackPx;
    }
    const auto& edges = s_.edges;
    std::uint32_t ia = a.head, ib = b.head;
    double y = ya;
    for (;;) {
        if (x_at(edges[ib], y) < x_at(edges[ia], y) - kOrderSlackPx) return false;
        if (y >= yb) return true;
        const double next = std::min({edges[ia].y1, edges[ib].y1, yb});
        // At `next` the edge ending there and the one starting there give the same x (a
        // shared vertex), so moving on before the check is the same as checking first.
        if (next < yb && edges[ia].y1 <= next) ia = static_cast<std::uint32_t>(edges[ia].below);
        if (next < yb && edges[ib].y1 <= next) ib = static_cast<std::uint32_t>(edges[ib].below);
        y = next;
    }
}

template <class V>
void FastEngine<V>::accumulate_chain(const Chain& c, double ya, double yb, const V& dv) {
    if (c.pieces == 1) {  // one edge across the sub-band: its ends are the chain's x_top, x_bottom
        add_segment(c.x_top, c.x_bottom, yb - ya, dv);
        return;
    }
    const auto& edges = s_.edges;
    for (int idx = static_cast<int>(c.head); idx >= 0 && edges[idx].y0 < yb;
         idx = edges[idx].below) {
        const Edge& e = edges[idx];
        const double a = std::max(e.y0, ya), b = std::min(e.y1, yb);
        if (b > a) add_segment(x_at(e, a), x_at(e, b), b - a, dv);
    }
}

template <class V>
void FastEngine<V>::fallback_row(int j) {
    if constexpr (kGrey) {
        if (!fallback_) fallback_ = std::make_unique<Fallback>(scene_);
        fallback_sweep(*fallback_, j, [](double jump) { return jump; });
    } else {
        // Channel by channel, each jump on its own component: component c receives the grey
        // fallback's pieces of channel c in their order, the others +0 (channel_values.h).
        if (!fallback_) fallback_ = std::make_unique<ColourFallback>(scene_);
        for (std::size_t c = 0; c < 3; ++c) {
            fallback_sweep(*fallback_->channels[c], j, [c](double jump) {
                ChannelValues weight;
                weight.set(c, jump);
                return weight;
            });
        }
    }
}

template <class V>
template <class Weight>
void FastEngine<V>::fallback_sweep(Fallback& fallback, int j, Weight weight_of) {
    const EdgeTable& table = fallback.table;
    fallback.sweep.sweep_row(j, [&](const Band& band) {
        for (const BandSegment& seg : band.segments) {
            if (seg.jump == 0.0) continue;
            const V weight = weight_of(seg.jump);
            for_each_piece(table, band, seg, [&](double xa, double ya, double xb, double yb) {
                add_segment(xa, xb, yb - ya, weight);
            });
        }
    });
}

template class FastEngine<double>;
template class FastEngine<ChannelValues>;

// Rows [row_lo, row_hi) (clamped) of `scene` into `out` by the engine of value type V.
template <class V>
void run_engine(Scratch<V>& scratch, const Scene& scene, typename EngineOutput<V>::Out& out,
                int row_lo, int row_hi, FastCoverageStats* stats) {
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi || scene.width <= 0) return;
    FastCoverageStats local;
    FastEngine<V>(scratch, scene, row_lo, row_hi).run(out, stats ? *stats : local);
}

}  // namespace fast_engine

void fast_coverage_rows(const Scene& scene, Image& out, int row_lo, int row_hi,
                        FastCoverageStats* stats) {
    fast_engine::run_engine(fast_engine::t_scratch, scene, out, row_lo, row_hi, stats);
}

void fast_colour_coverage_rows(const Scene& scene, ImagePlanes& out, int row_lo, int row_hi,
                               FastCoverageStats* stats) {
    fast_engine::run_engine(fast_engine::t_colour_scratch, scene, out, row_lo, row_hi, stats);
}

}  // namespace aabench
