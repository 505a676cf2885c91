// The steady and tracked rows of the fast exact engine (methods/scan/exact/fast_coverage.cpp, its
// essay's "Steady rows"): the chains, their order and their dv carried from one row to the
// next, tested on every sub-band as the general path tests its sorted chains.
#include <algorithm>
#include <cmath>

#include "methods/scan/exact/fast_engine_p.h"

namespace aabench::fast_engine {

// A row [top, bottom] of the steady chains (render_row checked that no event lies in it, no
// edge enters and none ends above its bottom, so each chain is its one edge across the row).
// The chains in the order of the row above, tested as sort_chains() and ordered() test them:
// if the order is still chain_before's and the certificate holds, the general path would sort
// the same sequence and its walk would give the same dv, so the row accumulates with those.
// Returns false (having accumulated nothing) when a test fails.
template <class V>
bool FastEngine<V>::steady_row(double top, double bottom) {
    const std::size_t n = s_.steady_edge.size();
    if (n == 0) return true;
    const Edge* edges = s_.edges.data();
    const std::uint32_t* edge = s_.steady_edge.data();
    s_.steady_x_next.resize(n);  // capacity kept (run() reserves it): no allocation once warm
    const double* x = s_.steady_x.data();
    double* x_next = s_.steady_x_next.data();
    // Three passes (x at the bottom, the order test, the pieces) rather than one: each is a
    // short loop the processor overlaps across chains, and the first and last do two chains
    // per SSE2 instruction.
    if (!steady_fields_) {
        s_.steady_x0.resize(n);
        s_.steady_y0.resize(n);
        s_.steady_x1.resize(n);
        s_.steady_y1.resize(n);
        s_.steady_dxdy.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const Edge& e = edges[edge[k]];
            s_.steady_x0[k] = e.x0;
            s_.steady_y0[k] = e.y0;
            s_.steady_x1[k] = e.x1;
            s_.steady_y1[k] = e.y1;
            s_.steady_dxdy[k] = e.dxdy;
        }
        steady_fields_ = true;
    }
    x_at_fields(s_.steady_x0.data(), s_.steady_y0.data(), s_.steady_x1.data(), s_.steady_y1.data(),
                s_.steady_dxdy.data(), n, bottom, x_next);
    switch (steady_order(x, x_next, n)) {
        case Order::kKept:
            break;
        case Order::kChanged:
            return false;
        case Order::kTie:
            if (!steady_order_with_ties(edge, x, x_next, n)) return false;
            break;
    }
    s_.cells.add_segments(x, x_next, bottom - top, s_.steady_dv.data(), n);
    s_.steady_x.swap(s_.steady_x_next);
    return true;
}

// The order test of steady_row, two neighbour pairs per SSE2 instruction: the same comparisons
// as steady_order_with_ties except that of two chains at the same x at the top (a tie, decided
// by x at the bottom and then by edge index), which it leaves to steady_order_with_ties.
template <class V>
typename FastEngine<V>::Order FastEngine<V>::steady_order(const double* x, const double* x_next, std::size_t n) {
    std::size_t k = 1;
#if defined(__SSE2__)
    __m128d changed = _mm_setzero_pd(), tie = _mm_setzero_pd();
    const __m128d slack = _mm_set1_pd(kOrderSlackPx);
    const __m128d all_ones = _mm_castsi128_pd(_mm_set1_epi32(-1));
    for (; k + 2 <= n; k += 2) {
        const __m128d prev_top = _mm_loadu_pd(x + k - 1),
                      prev_bottom = _mm_loadu_pd(x_next + k - 1);
        const __m128d x_top = _mm_loadu_pd(x + k), x_bottom = _mm_loadu_pd(x_next + k);
        changed = _mm_or_pd(changed, _mm_cmplt_pd(x_top, prev_top));
        tie = _mm_or_pd(tie, _mm_cmpeq_pd(x_top, prev_top));
        // std::max(a, b) is maxpd(b, a), std::min(a, b) minpd(b, a) (the same NaN cases).
        const __m128d apart =
            _mm_cmple_pd(_mm_max_pd(prev_bottom, prev_top), _mm_min_pd(x_bottom, x_top));
        const __m128d within_slack =
            _mm_and_pd(_mm_cmple_pd(prev_top, _mm_add_pd(x_top, slack)),
                       _mm_cmple_pd(prev_bottom, _mm_add_pd(x_bottom, slack)));
        changed = _mm_or_pd(changed, _mm_andnot_pd(_mm_or_pd(apart, within_slack), all_ones));
    }
    if (_mm_movemask_pd(changed) != 0) return Order::kChanged;
    if (_mm_movemask_pd(tie) != 0) return Order::kTie;
#endif
    for (; k < n; ++k) {
        if (!(x[k] > x[k - 1]) || !steady_pair_ordered(x[k - 1], x_next[k - 1], x[k], x_next[k])) {
            // Not strictly right of the one before: the exact test decides.
            return steady_order_with_ties(s_.steady_edge.data(), x, x_next, n) ? Order::kKept
                                                                               : Order::kChanged;
        }
    }
    return Order::kKept;
}

// steady_row's order test, pair by pair: still sorted by chain_before, and ordered() for
// two chains of one edge each.
template <class V>
bool FastEngine<V>::steady_order_with_ties(const std::uint32_t* edge, const double* x,
                                        const double* x_next, std::size_t n) {
    for (std::size_t k = 1; k < n; ++k) {
        const double prev_top = x[k - 1], prev_bottom = x_next[k - 1];
        const double x_top = x[k], x_bottom = x_next[k];
        // Still sorted: not chain_before(this chain, the one before).
        if (x_top < prev_top ||
            (x_top == prev_top &&
             (x_bottom < prev_bottom || (x_bottom == prev_bottom && edge[k] < edge[k - 1])))) {
            return false;
        }
        if (!steady_pair_ordered(prev_top, prev_bottom, x_top, x_bottom)) return false;
    }
    return true;
}

// A row of the steady chains with events, chains of several edges, chains starting or ending:
// sub-band by sub-band as the general path cuts it, each a pass over the chains in the order
// kept from the band above (tested as the general path tests its sorted chains, so that a
// pass that succeeds accumulates what the general path would), with chains that end removed
// and chains that start inserted at each cut, and the dv walked again when the set changed.
// Returns the sub-bands walked, 0 (having accumulated part of the row) when a test fails.
template <class V>
std::int64_t FastEngine<V>::tracked_row(std::size_t r, double top, double bottom,
                                     std::vector<double>::const_iterator ev,
                                     std::vector<double>::const_iterator ev_end) {
    s_.top_edges.assign(s_.steady_edge.begin(), s_.steady_edge.end());
    steady_fields_ = false;  // the chains move on to other edges here
    const std::span<const std::uint32_t> bucket(s_.bucket_edges.data() + s_.bucket_start[r],
                                                s_.bucket_start[r + 1] - s_.bucket_start[r]);
    std::size_t starts = 0;  // edges of the bucket that start a chain: each must be inserted
    for (const std::uint32_t idx : bucket) starts += s_.edges[idx].above < 0;
    std::int64_t bands = 0;
    double ya = top;
    for (;;) {
        while (ev != ev_end && *ev <= ya) ++ev;  // duplicates
        const double yb = ev != ev_end ? *ev : bottom;
        if (starts > 0) {
            const std::size_t inserted = insert_starts(bucket, ya, yb);
            if (inserted == kNotInserted) return 0;
            starts -= inserted;
            if (inserted > 0) walk_steady();
        }
        const BandResult band = tracked_band(ya, yb);
        if (band == BandResult::kFailed) return 0;
        ++bands;
        if (band == BandResult::kChainsEnded) walk_steady();
        if (yb == bottom) break;
        ya = yb;
    }
    if (starts != 0) return 0;  // a chain started where the row was not cut: not followed
    return bands;  // tracked_band left steady_min_y1_ for the chains after the last cut
}

// One sub-band [ya, yb] of the steady chains: chain records as sub_band() builds them, each
// tested against the one before as sort_chains() and ordered() test them. Each chain is
// accumulated as it is walked, piece by piece with the arguments accumulate_chain() gives
// add_segment (a failed test leaves a row the caller clears). Then moves each chain on as
// move_on(yb) does, in the same pass (each chain's edges are in the caches there): at its
// edge holding yb (handed to the one below when it ends at yb) and its x there, removed when
// it ends at yb; and sets steady_min_y1_ for the chains left.
template <class V>
typename FastEngine<V>::BandResult FastEngine<V>::tracked_band(double ya, double yb) {
    const Edge* edges = s_.edges.data();
    const std::size_t n = s_.steady_edge.size();
    std::uint32_t* steady_edge = s_.steady_edge.data();
    double* steady_x = s_.steady_x.data();
    V* steady_dv = s_.steady_dv.data();
    std::size_t kept = 0;
    double min_y1 = HUGE_VAL;
    // The chain before, as scalars (kept in registers; records are built only for ordered()'s
    // vertex walk): records on the stack, stored and re-read per chain, stalled on store
    // forwarding, and a record whose address goes to ordered() stays on the stack.
    double prev_top = 0.0, prev_bottom = 0.0, prev_min = 0.0, prev_max = 0.0;
    std::uint32_t prev_head = 0, prev_pieces = 0, prev_last = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (k + kPrefetchChains < n) prefetch_chain(edges, steady_edge[k + kPrefetchChains]);
        const std::uint32_t idx = steady_edge[k];
        const V dv = steady_dv[k];
        const double x_top = steady_x[k];
        double x_min = x_top, x_max = x_top;
        double x_from = x_top, y_from = ya;  // the start of the piece being walked
        std::uint32_t cur = idx, pieces = 1;
        while (edges[cur].y1 < yb) {
            const Edge& e = edges[cur];
            x_min = std::min(x_min, e.x1);
            x_max = std::max(x_max, e.x1);
            if (!is_zero(dv)) queue_segment(x_from, e.x1, e.y1 - y_from, dv);
            x_from = e.x1;
            y_from = e.y1;
            if (e.below < 0) return BandResult::kFailed;  // a chain ends inside: events cut there
            cur = static_cast<std::uint32_t>(e.below);
            ++pieces;
        }
        const double x_bottom = x_at(edges[cur], yb);
        if (!is_zero(dv)) queue_segment(x_from, x_bottom, yb - y_from, dv);
        x_min = std::min(x_min, x_bottom);
        x_max = std::max(x_max, x_bottom);
        // chain_before(this, prev), and ordered()'s two quick cases inline (apart in x; one
        // edge each), its vertex walk called only for chains of several pieces that overlap.
        if (k > 0) {
            const bool before =
                x_top != prev_top
                    ? x_top < prev_top
                    : (x_bottom != prev_bottom ? x_bottom < prev_bottom : idx < prev_head);
            if (before) return BandResult::kFailed;
            if (!(prev_max <= x_min)) {
                const bool kept_order =
                    prev_pieces == 1 && pieces == 1
                        ? prev_top <= x_top + kOrderSlackPx &&
                              prev_bottom <= x_bottom + kOrderSlackPx
                        : ordered(Chain{prev_top, prev_bottom, prev_min, prev_max, prev_head,
                                        prev_pieces, prev_last},
                                  Chain{x_top, x_bottom, x_min, x_max, idx, pieces, cur}, ya, yb);
                if (!kept_order) return BandResult::kFailed;
            }
        }
        prev_top = x_top;
        prev_bottom = x_bottom;
        prev_max = x_max;
        prev_min = x_min;
        prev_head = idx;
        prev_pieces = pieces;
        prev_last = cur;
        if (edges[cur].y1 <= yb) {
            if (edges[cur].below < 0) continue;  // the chain ends at yb
            cur = static_cast<std::uint32_t>(edges[cur].below);
        }
        // kept <= k: the slots written are those already read.
        steady_edge[kept] = cur;
        steady_x[kept] = x_bottom;
        steady_dv[kept] = dv;
        ++kept;
        min_y1 = std::min(min_y1, edges[cur].y1);
    }
    steady_min_y1_ = min_y1;
    if (kept == n) return BandResult::kKept;
    s_.steady_edge.resize(kept);
    s_.steady_x.resize(kept);
    s_.steady_dv.resize(kept);
    return BandResult::kChainsEnded;
}

// The chains moved on to the edges holding y (an edge ending at y hands over to the one
// below), those that end at y removed. Returns whether any was removed.
template <class V>
bool FastEngine<V>::move_on(double y) {
    const Edge* edges = s_.edges.data();
    const std::size_t n = s_.steady_edge.size();
    std::size_t m = 0;
    for (std::size_t k = 0; k < n; ++k) {
        std::uint32_t idx = s_.steady_edge[k];
        if (edges[idx].y1 <= y) {
            if (edges[idx].below < 0) continue;
            idx = static_cast<std::uint32_t>(edges[idx].below);
        }
        s_.steady_edge[m] = idx;
        s_.steady_x[m] = s_.steady_x[k];
        s_.steady_dv[m] = s_.steady_dv[k];
        ++m;
    }
    s_.steady_edge.resize(m);
    s_.steady_x.resize(m);
    s_.steady_dv.resize(m);
    return m != n;
}

// The chains of `bucket` that start at height y, inserted among the steady chains where their x
// at y puts them (ties among them by chain_before at yb, the next cut). Returns how many, or
// kNotInserted when one starts exactly at a steady chain's x (the order there is not decided
// at y) or ends above yb.
template <class V>
std::size_t FastEngine<V>::insert_starts(std::span<const std::uint32_t> bucket, double y, double yb) {
    const Edge* edges = s_.edges.data();
    auto& starts = s_.starts;
    starts.clear();
    for (const std::uint32_t idx : bucket) {
        const Edge& e = edges[idx];
        if (e.above >= 0 || e.y0 != y) continue;
        std::uint32_t cur = idx;
        while (edges[cur].y1 < yb) {
            if (edges[cur].below < 0) return kNotInserted;
            cur = static_cast<std::uint32_t>(edges[cur].below);
        }
        Chain c{};
        c.x_top = e.x0;
        c.x_bottom = x_at(edges[cur], yb);
        c.head = idx;
        starts.push_back(c);
    }
    std::sort(starts.begin(), starts.end(), chain_before);
    // Positions among the steady chains first (Chain::pieces holds it), then inserted from the
    // last: a chain inserted never moves the place of one still to insert, and starts at one
    // place (the two sides of a turning point) keep their order.
    const auto& xs = s_.steady_x;
    for (Chain& c : starts) {
        const auto at = std::upper_bound(xs.begin(), xs.end(), c.x_top);
        if (at != xs.begin() && *(at - 1) == c.x_top) return kNotInserted;
        c.pieces = static_cast<std::uint32_t>(at - xs.begin());
    }
    for (auto c = starts.rbegin(); c != starts.rend(); ++c) {
        const std::ptrdiff_t pos = c->pieces;
        s_.steady_x.insert(s_.steady_x.begin() + pos, c->x_top);
        s_.steady_edge.insert(s_.steady_edge.begin() + pos, c->head);
        s_.steady_dv.insert(s_.steady_dv.begin() + pos, V{});
    }
    return starts.size();
}

// The dv of every steady chain: the walk of sub_band() over them in their order.
template <class V>
void FastEngine<V>::walk_steady() {
    const Edge* edges = s_.edges.data();
    const std::uint32_t* edge = s_.steady_edge.data();
    V* dvs = s_.steady_dv.data();
    const std::size_t n = s_.steady_edge.size();
    if (scene_.shapes.size() == 1) {
        // One shape (gratings, rings): cross()'s rule (visibility_rule.h) in registers, the
        // same values and subtractions.
        OneShapeWalk<V> one(shape_value(0), background_);
        V value = background_;
        for (std::size_t k = 0; k < n; ++k) {
            if (k + kPrefetchChains < n) __builtin_prefetch(edges + edge[k + kPrefetchChains]);
            const V before = value;
            value = one.cross(edges[edge[k]].winding);
            dvs[k] = value - before;
        }
        value_ = value;
        return;
    }
    value_ = background_;
    for (std::size_t k = 0; k < n; ++k) {
        const Edge& e = edges[edge[k]];
        const V before = value_;
        dvs[k] = cross(e.shape, e.winding) - before;
    }
    s_.cover.clear();
}

// This file's members of both instances (fast_coverage.cpp instantiates the class).
#define AABENCH_TRACKED_MEMBERS(V)                                                             \
    template bool FastEngine<V>::steady_row(double, double);                                   \
    template FastEngine<V>::Order FastEngine<V>::steady_order(const double*, const double*,    \
                                                              std::size_t);                    \
    template bool FastEngine<V>::steady_order_with_ties(const std::uint32_t*, const double*,   \
                                                        const double*, std::size_t);           \
    template std::int64_t FastEngine<V>::tracked_row(std::size_t, double, double,              \
                                                     std::vector<double>::const_iterator,      \
                                                     std::vector<double>::const_iterator);     \
    template FastEngine<V>::BandResult FastEngine<V>::tracked_band(double, double);            \
    template bool FastEngine<V>::move_on(double);                                              \
    template std::size_t FastEngine<V>::insert_starts(std::span<const std::uint32_t>, double,  \
                                                      double);                                 \
    template void FastEngine<V>::walk_steady();
AABENCH_TRACKED_MEMBERS(double)
AABENCH_TRACKED_MEMBERS(ChannelValues)
#undef AABENCH_TRACKED_MEMBERS

}  // namespace aabench::fast_engine
