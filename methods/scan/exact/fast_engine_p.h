// The fast exact engine's parts (methods/scan/exact/fast_coverage.cpp says what it computes and why
// it is exact): the chain records and their order, the per-thread scratch and the engine
// class. Only the engine's two files include this: fast_coverage.cpp (edges, events, the
// general path of a row, the double fallback) and fast_tracked.cpp (the steady and tracked
// rows that carry the chains from one row to the next).
//
// The engine is templated on its value type V: double for a grey scene, ChannelValues for a
// colour one (methods/scan/kernel/channel_values.h): the chains, their order, the steady and
// tracked rows and the fallback rows are decided by the geometry alone, and every dv, cell and
// sum is V, so the colour instance gives each plane the grey instance's image of that channel's
// scene bit for bit. Only the fallback's band sweep is per channel (its jumps come from one
// channel's values): a colour fallback row sweeps the three channel scenes in turn.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "methods/scan/exact/fast_coverage.h"
#include "methods/scan/kernel/area_cover_row.h"
#include "methods/scan/kernel/channel_values.h"
#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "methods/scan/reference/visible_boundary.h"

namespace aabench::fast_engine {

// How far a chain may lie left of its left neighbour (at a vertex height) and still pass the
// order certificate. Pieces of a 3-D scene share edges split at different vertices
// (T-junctions), so the same line is evaluated at a vertex of one piece by interpolation on
// the other, and the two x differ by rounding (~1e-13 px at x ~ 1000): without slack such
// rows went to the double sweep. Treating an overlap of at most this width as an order
// misassigns a sliver of at most kOrderSlackPx x (row height 1) x |jump| per pixel: 1e-9 for
// values of order one, 1000 times below the 1e-6 bound.
constexpr double kOrderSlackPx = 1e-9;

#if defined(__SSE2__)
// mask ? a : b, lane by lane (mask lanes all ones or all zeros).
inline __m128d select(__m128d mask, __m128d a, __m128d b) {
    return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
}
#endif

// Edge::x_at, inlined here (it runs a few times per edge per sub-band): x on the edge at
// height y, from the nearer endpoint, clamped to the edge's x-range, exactly x0 at y0 and x1
// at y1 so consecutive edges of a chain meet exactly.
// The choice of endpoint and the clamp without branches (which endpoint is nearer is as good
// as random for the short edges of rings): x_at_fields' lane arithmetic on one lane.
inline double x_at(const Edge& e, double y) {
    if (y <= e.y0) return e.x0;
    if (y >= e.y1) return e.x1;
#if defined(__SSE2__)
    const __m128d yy = _mm_set_sd(y), x0 = _mm_set_sd(e.x0), x1 = _mm_set_sd(e.x1);
    const __m128d dxdy = _mm_set_sd(e.dxdy);
    const __m128d from_top = _mm_sub_sd(yy, _mm_set_sd(e.y0));
    const __m128d from_bottom = _mm_sub_sd(_mm_set_sd(e.y1), yy);
    const __m128d v =
        select(_mm_cmple_sd(from_top, from_bottom), _mm_add_sd(x0, _mm_mul_sd(from_top, dxdy)),
               _mm_sub_sd(x1, _mm_mul_sd(from_bottom, dxdy)));
    return _mm_cvtsd_f64(_mm_max_sd(_mm_min_sd(x1, x0), _mm_min_sd(_mm_max_sd(x1, x0), v)));
#else
    const double x = y - e.y0 <= e.y1 - y ? e.x0 + (y - e.y0) * e.dxdy : e.x1 - (e.y1 - y) * e.dxdy;
    return std::clamp(x, std::min(e.x0, e.x1), std::max(e.x0, e.x1));
#endif
}

// The edges of the chains lie in contour order, so the chains of a row, in x order, are
// scattered over an edge array of megabytes (rings at 1024^2: 123,052 edges, 6.9 MB) and each
// chain's first load missed the caches (a third of the tracked bands' time). Walks over the
// chains ask for the edges of the chain this many places ahead: its edge and the neighbours a
// chain continues into (`below` is the next or the previous edge of the contour).
constexpr std::size_t kPrefetchChains = 8;
inline void prefetch_chain(const Edge* edges, std::uint32_t idx) {
    const char* at = reinterpret_cast<const char*>(edges + idx);
    __builtin_prefetch(at);
    __builtin_prefetch(at + sizeof(Edge));
    __builtin_prefetch(at - sizeof(Edge));
}

// x_at(edge k, y) for k = 0..n-1 into x, from the edges' fields copied out in chain order,
// two edges per SSE2 instruction (two loads per field for two chains, no gather from the
// edge records): the same IEEE operations in each lane, so the same values bit for bit
// (std::clamp(v, lo, hi) is maxpd(lo, minpd(hi, v)) for lo <= hi: v < lo implies v < hi).
inline void x_at_fields(const double* x0s, const double* y0s, const double* x1s, const double* y1s,
                        const double* dxdys, std::size_t n, double y, double* x) {
    std::size_t k = 0;
#if defined(__SSE2__)
    const __m128d yy = _mm_set1_pd(y);
    for (; k + 2 <= n; k += 2) {
        const __m128d x0 = _mm_loadu_pd(x0s + k), y0 = _mm_loadu_pd(y0s + k);
        const __m128d x1 = _mm_loadu_pd(x1s + k), y1 = _mm_loadu_pd(y1s + k);
        const __m128d dxdy = _mm_loadu_pd(dxdys + k);
        const __m128d from_top = _mm_sub_pd(yy, y0), from_bottom = _mm_sub_pd(y1, yy);
        const __m128d near_top = _mm_cmple_pd(from_top, from_bottom);
        const __m128d v = select(near_top, _mm_add_pd(x0, _mm_mul_pd(from_top, dxdy)),
                                 _mm_sub_pd(x1, _mm_mul_pd(from_bottom, dxdy)));
        const __m128d lo = _mm_min_pd(x1, x0), hi = _mm_max_pd(x1, x0);
        __m128d r = _mm_max_pd(lo, _mm_min_pd(hi, v));
        r = select(_mm_cmpge_pd(yy, y1), x1, r);
        r = select(_mm_cmple_pd(yy, y0), x0, r);
        _mm_storeu_pd(x + k, r);
    }
#endif
    for (; k < n; ++k) {
        const Edge e{x0s[k], y0s[k], x1s[k], y1s[k], dxdys[k], 0, 0};
        x[k] = x_at(e, y);
    }
}

struct Chain {
    double x_top, x_bottom, x_min, x_max;
    std::uint32_t head;    // the chain's edge containing the sub-band's top (y0 <= top < y1)
    std::uint32_t pieces;  // edges of the chain inside the sub-band
    std::uint32_t last;    // the chain's edge containing the sub-band's bottom
};

// The one left-to-right order of chains in a sub-band: x at the top, then x at the bottom,
// then edge index (the order of shapes, contours and edges, the same in every band of rows,
// so that a band renders its rows bit for bit as the whole image does).
inline bool chain_before(const Chain& a, const Chain& b) {
    if (a.x_top != b.x_top) return a.x_top < b.x_top;
    if (a.x_bottom != b.x_bottom) return a.x_bottom < b.x_bottom;
    return a.head < b.head;
}

// Chains that arrive without a rank from the sub-band above (new chains, the first sub-band)
// beyond this many: a full sort rather than insertion.
constexpr std::size_t kMaxUnrankedForInsertion = 16;

// Per-thread buffers, reused by every call on the thread (capacity kept: no allocation once
// warm); one set per value type.
template <class V>
struct Scratch {
    std::vector<Edge> edges;
    std::vector<int> contour_index;
    std::vector<std::uint32_t> bucket_start, bucket_edges;
    std::vector<std::uint32_t> edge_rows;  // bucket_edges(): each edge's first row of the call
    std::vector<double> events;
    std::vector<std::uint32_t> active, reorder;
    std::vector<Chain> chains, ranked;
    // rank[edge]: the position, in the sub-band above, of the chain that continues into this
    // edge (-1: none). Only a hint for the sort: the order itself is always checked.
    std::vector<int> rank;
    std::vector<V> chain_dv;  // dv of each sorted chain of the last sub-band walked
    // The steady rows' chains (steady_row), in order: edge, x at the row's top, dv.
    std::vector<std::uint32_t> steady_edge;
    std::vector<double> steady_x;
    std::vector<V> steady_dv;
    std::vector<double> steady_x_next;  // steady_row's x at the row's bottom (swapped in)
    // The steady chains' edges, field by field (steady_row's copy, valid while the steady
    // chains keep their edges: every row of a grating).
    std::vector<double> steady_x0, steady_y0, steady_x1, steady_y1, steady_dxdy;
    std::vector<std::uint32_t> top_edges;  // steady_edge at the top of a tracked row
    std::vector<Chain> starts;             // chains starting at one cut of a tracked row
    AreaCoverRowOf<V> cells;
    CoverWalk cover;         // the visibility rule along a sub-band's walk
    std::vector<V> palette;  // colour: each shape's value (V), the grey engine reads the scene's
};

// The double engine's band sweep, built on first need by a row with a crossing.
struct Fallback {
    explicit Fallback(const Scene& scene) : table(scene), sweep(table, 0, table.height()) {}
    EdgeTable table;
    BandSweep sweep;
};

// A colour scene's: one band sweep per channel scene (its jumps are that channel's).
struct ColourFallback {
    explicit ColourFallback(const Scene& scene) {
        for (int c = 0; c < 3; ++c) {
            const auto k = static_cast<std::size_t>(c);
            scenes[k] = channel_scene(scene, c);
            channels[k] = std::make_unique<Fallback>(scenes[k]);
        }
    }
    std::array<Scene, 3> scenes;
    std::array<std::unique_ptr<Fallback>, 3> channels;  // each refers to its scene
};

// What the engine writes: an image's row (grey) or the three planes' rows (colour).
template <class V>
struct EngineOutput {
    using Out = Image;
    using Row = float*;
    static Row row(Out& out, int j) { return out.row(j); }
    static void fill(Row row, int width, double value) {
        std::fill(row, row + width, static_cast<float>(value));
    }
};
template <>
struct EngineOutput<ChannelValues> {
    using Out = ImagePlanes;
    using Row = PlaneRows;
    static Row row(Out& out, int j) { return {out[0].row(j), out[1].row(j), out[2].row(j)}; }
    static void fill(Row row, int width, const ChannelValues& value) {
        for (std::size_t c = 0; c < 3; ++c) {
            std::fill(row[c], row[c] + width, static_cast<float>(value[c]));
        }
    }
};

template <class V>
class FastEngine {
    static constexpr bool kGrey = std::is_same_v<V, double>;
    using Output = EngineOutput<V>;

public:
    FastEngine(Scratch<V>& s, const Scene& scene, int row_lo, int row_hi)
        : s_(s),
          scene_(scene),
          lo_(row_lo),
          hi_(row_hi),
          width_(scene.width),
          background_(background_of(scene)) {}

    void run(typename Output::Out& out, FastCoverageStats& stats);

private:
    void extract_edges();
    void add_contour(const Contour& contour, int shape);
    void bucket_edges();
    void render_row(int j, typename Output::Row out, FastCoverageStats& stats);
    bool sub_band(double ya, double yb);
    void keep_chain_order(double ya);
    void sort_chains();
    void set_rank_hints();
    bool ordered(const Chain& a, const Chain& b, double ya, double yb) const;
    // The visible value after crossing one chain of `shape` (the rule of visibility_rule.h).
    V cross(int shape, int winding) {
        s_.cover.cross(shape, winding);
        const int top = s_.cover.top();
        value_ = top < 0 ? background_ : shape_value(top);
        return value_;
    }
    // Shape k's value: the scene's (grey), or its three channels' (colour, made by run()).
    V shape_value(int k) const {
        if constexpr (kGrey) {
            return scene_.shapes[k].value;
        } else {
            return s_.palette[static_cast<std::size_t>(k)];
        }
    }
    static V background_of(const Scene& scene) {
        if constexpr (kGrey) {
            return scene.background;
        } else {
            return {channel_background(scene, 0), channel_background(scene, 1),
                    channel_background(scene, 2)};
        }
    }
    void accumulate_chain(const Chain& c, double ya, double yb, const V& dv);
    void add_segment(double xa, double xb, double height, const V& weight) {
        s_.cells.add_segment(xa, xb, height, weight);
    }
    // The same, deferred (AreaCoverRow::queue_segment): the steady and tracked rows' pieces.
    void queue_segment(double xa, double xb, double height, const V& weight) {
        s_.cells.queue_segment(xa, xb, height, weight);
    }
    void begin_steady(double bottom);
    bool steady_row(double top, double bottom);
    enum class Order { kKept, kChanged, kTie };
    Order steady_order(const double* x, const double* x_next, std::size_t n);
    bool steady_order_with_ties(const std::uint32_t* edge, const double* x, const double* x_next,
                                std::size_t n);
    // ordered() for two chains of one edge each, from their x at the top and the bottom.
    static bool steady_pair_ordered(double prev_top, double prev_bottom, double x_top,
                                    double x_bottom) {
        return std::max(prev_top, prev_bottom) <= std::min(x_top, x_bottom) ||
               (prev_top <= x_top + kOrderSlackPx && prev_bottom <= x_bottom + kOrderSlackPx);
    }
    std::int64_t tracked_row(std::size_t r, double top, double bottom,
                             std::vector<double>::const_iterator ev,
                             std::vector<double>::const_iterator ev_end);
    enum class BandResult { kFailed, kKept, kChainsEnded };
    BandResult tracked_band(double ya, double yb);
    bool move_on(double y);
    static constexpr std::size_t kNotInserted = ~std::size_t{0};
    std::size_t insert_starts(std::span<const std::uint32_t> bucket, double y, double yb);
    void walk_steady();
    void fallback_row(int j);
    // One band sweep's pieces of row j, each segment's jump made a weight by weight_of.
    template <class Weight>
    void fallback_sweep(Fallback& fallback, int j, Weight weight_of);

    Scratch<V>& s_;
    const Scene& scene_;
    int lo_, hi_, width_;
    V background_;
    V value_{};
    // The steady chains (Scratch::steady_*) hold the state after the row above, and none of
    // their edges ends above steady_min_y1_.
    bool steady_ = false;
    bool steady_fields_ = false;  // Scratch::steady_x0 ... hold the steady chains' edges
    double steady_min_y1_ = 0.0;
    std::unique_ptr<std::conditional_t<kGrey, Fallback, ColourFallback>> fallback_;
};

}  // namespace aabench::fast_engine
