// One pixel row of "area and cover" cells for the fast exact engine (fast_coverage.cpp): how an
// edge's pieces are added to the cells of a CellRow (methods/scan/kernel/cells.h, which says
// what a cell holds and how the prefix sum rounds). Inline, so that the engine's per-edge loops
// compile into one body.
//
// Accumulation in double, output in float: a row of rings crosses 400 boundaries, and a float
// prefix sum over 400 jumps of size 1 carries about 400 * 2^-24 = 2.4e-5 of rounding, 24
// times the 1e-6 budget; in double it is 1e-13. The array is one row (W + 16 doubles,
// L1-resident), so double costs no bandwidth; the output is float32, rounded once.
//
// Batches. The steady and tracked rows (fast_tracked.cpp) hand their pieces over in arrays
// (queue_segment, add_segments), and the one-or-two-pixel case, nearly every piece of a
// grating or a ring, is computed two pieces per SSE2 instruction. Each lane does the IEEE
// operations of add_segment in the same order, and the pieces are added to the cells in the
// order they were given, so the sums are the same bit for bit. (The build targets baseline
// x86-64: SSE2, no SSE4.1 roundsd, hence the truncations instead of std::floor below.)
//
// Sparse resolve: the cells are flagged in blocks of 16 (kernel/cells.h); the prefix sum, four
// cells at a time (Prefix::kFourWide), runs only through flagged blocks.
//
// Colour. AreaCoverRowOf<ChannelValues> is the same row with a weight of three components
// (kernel/channel_values.h): the scalar arithmetic of add_segment on each, no queue and no
// batches (the SSE2 lanes are the scalar operations, so the grey sums are the same either way),
// and a resolve into three planes. Component c of its cells is the grey row of channel c's
// weights bit for bit.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/kernel/channel_values.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__SSE2__) && defined(__x86_64__)
#include <immintrin.h>  // AVX2 for AreaCoverRow::batch_math_avx2 only, chosen at run time
#endif

namespace aabench {

// max(v, 0) without a branch. GCC compiles std::max of two doubles to a compare and a jump
// here, and whether an edge's piece of a row reaches into the next pixel is as good as random
// on rings and strips: the mispredicted jump was a fifth of add_segment's time (perf, rings at
// 1024^2). maxsd(0, v) is 0 > v ? 0 : v, what std::max(v, 0.0) returns for every v (-0 and
// NaN included).
inline double max0(double v) {
#if defined(__SSE2__)
    return _mm_cvtsd_f64(_mm_max_sd(_mm_setzero_pd(), _mm_set_sd(v)));
#else
    return std::max(v, 0.0);
#endif
}

#if defined(__SSE2__)
// mask ? a : b, lane by lane (mask lanes all ones or all zeros).
inline __m128d select_pd(__m128d mask, __m128d a, __m128d b) {
    return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
}
#endif

#if defined(__SSE2__)
// acc[0], acc[1] by two 8-byte loads.
inline __m128d load_cells(const double* acc) { return _mm_loadh_pd(_mm_load_sd(acc), acc + 1); }
#endif

// max(v, DBL_MIN) without a branch, as max0.
inline double max_min_normal(double v) {
#if defined(__SSE2__)
    return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(DBL_MIN), _mm_set_sd(v)));
#else
    return std::max(v, DBL_MIN);
#endif
}

// std::floor without SSE4.1's roundsd (the build targets baseline x86-64, where std::floor is
// a call or a masked sequence): truncation, less one where truncation rounded up. |v| >= 2^52
// is whole already (and NaN passes). It differs from std::floor only for v = -0 (+0, not -0),
// which the cell code below only compares or adds 1 to: the same cells and sums.
inline double floor_fast(double v) {
    if (!(std::abs(v) < 0x1p52)) return v;
    const double t = static_cast<double>(static_cast<std::int64_t>(v));
    return t > v ? t - 1.0 : t;
}

// The area cells of one row: 16 to a flag (a piece reaches three cells; add_batch's pairs four).
template <class V>
using AreaCellsOf = CellRow<V, 16>;
using AreaCells = AreaCellsOf<double>;

// weight * (area right of the piece [xl, xr] of one column c = floor((xl + xr) / 2), or at its
// right border) into the cells of a row `width` pixels wide; w = weight * piece height. The
// area right of a piece inside column c is w (c + 1 - mean x) (a trapezoid: the mean of a
// linear function is its midpoint value), and every column > c gets the whole w. Shared by the
// exact engine and the box reference (methods/scan/reference/box_coverage.cpp).
template <class Writer, class V>
inline void add_area_piece(Writer cells, double xl, double xr, V w, int width) {
    const double mid = 0.5 * (xl + xr);
    const double c = floor_fast(mid);
    if (c < 0.0) {
        cells.add(0, w);
        return;
    }
    if (c >= width) return;
    const auto col = static_cast<std::size_t>(c);
    const double right_area = c + 1.0 - mid;  // in [0, 1]
    V* acc = cells.cells();
    acc[col] += w * right_area;
    acc[col + 1] += w * (1.0 - right_area);
    cells.flag(col);
    cells.flag(col + 1);
}

template <class V>
class AreaCoverRowOf {
    static constexpr bool kGrey = std::is_same_v<V, double>;
    using Cells = AreaCellsOf<V>;

public:
    // A row of `width` pixels, every cell zero (capacity kept: no allocation once warm).
    // Indices 0..width + 1: col + 1 may be width, and add_batch adds 0 to col + 3 (so those
    // cells stay zero, never flagged).
    void reset(int width) {
        width_ = width;
        cells_.reset(width);
    }

    // weight * (area right of the segment (xa, .)-(xb, .) of the given height within each
    // pixel of the row), as in box_coverage.cpp.
    // Inlined into the engine's loops (the long case is not), so that the pieces of successive
    // edges overlap in the pipeline.
    // Pieces queued by queue_segment are added first, so that every cell sees its pieces in
    // the order they were given (the sums, and so the image, do not depend on the batching).
    [[gnu::always_inline]] void add_segment(double xa, double xb, double height, V weight) {
        if (queued_ != 0) flush();
        add_segment_now(xa, xb, height, weight);
    }

    // add_segment, deferred: the piece is queued and the queue added by flush(), two pieces
    // at a time (the arithmetic of add_segment's one-or-two-pixel case in SSE2, which has
    // the same IEEE operations in each lane, so the same sums bit for bit). resolve() and
    // add_segment() flush first; clear() drops the queue with the row.
    void queue_segment(double xa, double xb, double height, V weight) {
        if constexpr (kGrey) {
            if (queued_ == kQueueLength) flush();
            queue_xa_[queued_] = xa;
            queue_xb_[queued_] = xb;
            queue_height_[queued_] = height;
            queue_weight_[queued_] = weight;
            ++queued_;
        } else {  // colour: added at once (no lanes to fill)
            add_segment_now(xa, xb, height, weight);
        }
    }

    void flush();

    // add_segment(xa[k], xb[k], height, weight[k]) for k = 0..n-1 in order, pieces of weight
    // 0 skipped, two at a time as flush() does (the steady rows' pieces: one height).
    void add_segments(const double* xa, const double* xb, double height, const V* weight,
                      std::size_t n) {
        if constexpr (kGrey) {
            if (queued_ != 0) flush();
            add_batch<true>(xa, xb, nullptr, height, weight, n);
        } else {
            for (std::size_t k = 0; k < n; ++k) {
                if (!is_zero(weight[k])) add_segment_now(xa[k], xb[k], height, weight[k]);
            }
        }
    }

private:
    template <bool kOneHeight>
    void add_batch(const double* xa, const double* xb, const double* heights, double height,
                   const double* weights, std::size_t n);
#if defined(__SSE2__) && defined(__x86_64__)
    // add_batch's first pass for pairs 0, 2, 4, ... (two at a time) in AVX2; returns how many
    // pairs it did (an even number; the caller does the last one if `pairs` is odd).
    template <bool kOneHeight>
    [[gnu::target("avx2")]] std::size_t batch_math_avx2(const double* xa_in, const double* xb_in,
                                                        const double* heights, double height,
                                                        const double* weights, std::size_t pairs,
                                                        __m128d* to_cs, __m128d* to_c1s,
                                                        __m128d* to_c2s, std::uint32_t (*cols)[2],
                                                        int* lanes) const;
    static bool has_avx2() {
        static const bool kAvx2 = __builtin_cpu_supports("avx2");
        return kAvx2;
    }
#endif

    [[gnu::always_inline]] void add_segment_now(double xa, double xb, double height, V weight) {
        const V w = weight * height;
        const double xl = std::min(xa, xb), xr = std::max(xa, xb);
        if (xr <= 0.0) {  // wholly left of the image: every pixel lies right of it
            add_cell(0, w);
            return;
        }
        if (xl >= width_) return;  // wholly right of the image: no pixel lies right of it
        if (xl >= 0.0 && xl < width_ - 1.0) {
            // xl >= 0, so truncation is floor: one conversion each way instead of std::floor,
            // which without SSE4.1's roundsd (the build targets baseline x86-64) is a masked
            // sequence with a branch, a fifth of the piece's time on gratings.
            const auto col = static_cast<std::size_t>(static_cast<std::int64_t>(xl));
            const double right = static_cast<double>(col) + 1.0;  // the border of col, col + 1
            if (xr < right + 1.0) {
                // One or two pixels, without branching on which (as good as random on strips
                // and rings): the part right of the border, r = max(xr - right, 0), is a piece
                // of weight w r / span whose mean x lies r / 2 right of the border (it adds its
                // weight times r / 2 to cell c + 2); the rest, of length l, has its mean x
                // l / 2 + max(right - xr, 0) left of the border (it adds its weight times that
                // distance to cell c); cell c + 1 gets what is left of w. add_piece's
                // arithmetic on the two pieces, rearranged.
                const double r = max0(xr - right), span = xr - xl;
                // Without a branch on r > 0 (as good as random on rings): r > 0 implies
                // xl < right < xr, so span >= ulp(1) > DBL_MIN and the divisor is span; r = 0
                // gives w * +0 whatever span is (0 / 0 avoided by the floor at DBL_MIN).
                const V w_right = w * (r / max_min_normal(span)), w_left = w - w_right;
                const V to_c = w_left * (0.5 * (span - r) + max0(right - xr));
                const V to_c2 = w_right * (0.5 * r);
                V* acc = cells_.cells();
                acc[col] += to_c;
                acc[col + 1] += (w - to_c) - to_c2;
                acc[col + 2] += to_c2;
                typename Cells::Flag* touched = cells_.flags();
                touched[col / kBlock] = kSet;
                touched[(col + 2) / kBlock] = kSet;  // c + 1 lies in one of the two blocks
                return;
            }
        }
        add_long_segment(xl, xr, w);
    }

public:
    // Zeroes the touched cells and drops the queue (a row abandoned half-way).
    void clear() {
        queued_ = 0;
        cells_.clear();
    }

    // Background + prefix sums (four cells at a time) into one output row, rounded once to
    // float32; the row is clear after it.
    void resolve(double background, float* out) requires kGrey {
        if (queued_ != 0) flush();
        cells_.template resolve_and_clear<Prefix::kFourWide>(
            background, out, [](std::size_t, double sum) { return static_cast<float>(sum); });
    }
    // The same for colour, into the three planes' rows: each component's sums are the grey
    // row's, rounded once each.
    void resolve(const ChannelValues& background, PlaneRows out) requires(!kGrey) {
        cells_.template resolve_and_clear<Prefix::kFourWide>(
            background, PlaneSink{out},
            [](std::size_t, const ChannelValues& sum) { return sum.rounded(); });
    }

private:
    static constexpr std::size_t kBlock = Cells::kBlock;
    static constexpr typename Cells::Flag kSet = Cells::Flag::kSet;

    void add_cell(std::size_t col, V w) { cells_.writer().add(col, w); }

    // A segment over more than two cells or reaching past the image's sides (xl < xr).
    [[gnu::noinline]] void add_long_segment(double xl, double xr, V w) {
        if (floor_fast(xl) == floor_fast(xr)) {
            add_piece(xl, xr, w);
            return;
        }
        const double span = xr - xl;
        double left = xl;
        if (left < 0.0) {  // the part left of the image covers every pixel
            add_cell(0, w * (0.0 - xl) / span);
            left = 0.0;
        }
        const double right = std::min(xr, static_cast<double>(width_));
        // The partial cell at the left end, then the whole cells, then the partial cell at
        // the right end. A whole cell [c, c + 1] holds the height share k = w / span with its
        // mean x at c + 1/2, so it adds k/2 to acc[c] and k/2 to acc[c + 1] (add_piece's
        // arithmetic, exactly: c + 1 - (c + 1/2) = 1/2): a run of whole cells c0..c1-1 adds
        // k/2, k, ..., k, k/2, a loop without divisions or floors (near-horizontal edges cross
        // hundreds of cells).
        const double first = std::min(floor_fast(left) + 1.0, right);
        add_piece(left, first, w * (first - left) / span);
        left = first;
        if (!(left < right)) return;
        const double last = floor_fast(right);  // whole cells lie in [left, last]
        if (last > left) {
            const V k = w / span;
            const auto c0 = static_cast<std::size_t>(left), c1 = static_cast<std::size_t>(last);
            V* acc = cells_.cells();
            acc[c0] += 0.5 * k;
            for (std::size_t c = c0 + 1; c < c1; ++c) acc[c] += k;
            acc[c1] += 0.5 * k;
            cells_.writer().flag_range(c0, c1);
            left = last;
        }
        if (left < right) add_piece(left, right, w * (right - left) / span);
    }

    void add_piece(double xl, double xr, V w) {
        add_area_piece(cells_.writer(), xl, xr, w, width_);
    }

    // Pieces per flush at most: the queue (four arrays of this many doubles, 8 KB) stays in
    // L1 and is part of the row object, so queueing never allocates.
    static constexpr std::size_t kQueueLength = 256;

    int width_ = 0;
    Cells cells_;
    std::size_t queued_ = 0;
    alignas(16) double queue_xa_[kQueueLength];
    alignas(16) double queue_xb_[kQueueLength];
    alignas(16) double queue_height_[kQueueLength];
    alignas(16) double queue_weight_[kQueueLength];
};

using AreaCoverRow = AreaCoverRowOf<double>;

template <class V>
inline void AreaCoverRowOf<V>::flush() {
    if constexpr (kGrey) {  // colour queues nothing
        const std::size_t n = queued_;
        queued_ = 0;  // add_segment_now below must not flush again
        add_batch<false>(queue_xa_, queue_xb_, queue_height_, 0.0, queue_weight_, n);
    }
}

template <class V>
template <bool kOneHeight>
void AreaCoverRowOf<V>::add_batch(const double* xa_in, const double* xb_in, const double* heights,
                        double height, const double* weights, std::size_t n) {
    auto height_of = [&](std::size_t k) { return kOneHeight ? height : heights[k]; };
    std::size_t k = 0;
#if defined(__SSE2__)
    double* acc = cells_.cells();
    typename Cells::Flag* touched = cells_.flags();
    const __m128d zero = _mm_setzero_pd(), half = _mm_set1_pd(0.5), one = _mm_set1_pd(1.0);
    const __m128d min_normal = _mm_set1_pd(DBL_MIN), last = _mm_set1_pd(width_ - 1.0);
    // Two passes per chunk of pairs: the arithmetic of every pair first (no branch, so the
    // divisions of successive pairs overlap), then the cells, in the pieces' order.
    constexpr std::size_t kPairs = 128;
    alignas(16) __m128d to_cs[kPairs], to_c1s[kPairs], to_c2s[kPairs];
    std::uint32_t cols[kPairs][2];
    int lanes[kPairs];  // bit l: lane l in two pixels; bit 2 + l: lane l of weight 0
    while (k + 2 <= n) {
        const std::size_t pairs = std::min(kPairs, (n - k) / 2);
        std::size_t p = 0;
#if defined(__x86_64__)
        // Four pieces per instruction where the processor has AVX2 (the same lane arithmetic;
        // no FMA, so no contraction): the pass is a third of a grating's render.
        if (has_avx2()) {
            p = batch_math_avx2<kOneHeight>(xa_in + k, xb_in + k, heights ? heights + k : nullptr,
                                            height, weights + k, pairs, to_cs, to_c1s, to_c2s, cols,
                                            lanes);
        }
#endif
        for (; p < pairs; ++p) {
            const std::size_t i = k + 2 * p;
            const __m128d xa = _mm_loadu_pd(xa_in + i), xb = _mm_loadu_pd(xb_in + i);
            const __m128d weight = _mm_loadu_pd(weights + i);
            const __m128d w =
                _mm_mul_pd(weight, kOneHeight ? _mm_set1_pd(height) : _mm_loadu_pd(heights + i));
            // minpd(b, a) is b < a ? b : a, std::min(a, b); maxpd(b, a) is std::max(a, b).
            const __m128d xl = _mm_min_pd(xb, xa), xr = _mm_max_pd(xb, xa);
            // Truncation to int32: only lanes with 0 <= xl < width - 1 use it.
            const __m128i col = _mm_cvttpd_epi32(xl);
            const __m128d right = _mm_add_pd(_mm_cvtepi32_pd(col), one);
            // add_segment_now's one-or-two-pixel case: xr > 0, 0 <= xl < width - 1,
            // xr < right + 1.
            const __m128d in_two = _mm_and_pd(
                _mm_and_pd(_mm_cmpge_pd(xl, zero), _mm_cmplt_pd(xl, last)),
                _mm_and_pd(_mm_cmpgt_pd(xr, zero), _mm_cmplt_pd(xr, _mm_add_pd(right, one))));
            const __m128d r = _mm_max_pd(zero, _mm_sub_pd(xr, right)), span = _mm_sub_pd(xr, xl);
            const __m128d w_right = _mm_mul_pd(w, _mm_div_pd(r, _mm_max_pd(min_normal, span)));
            const __m128d w_left = _mm_sub_pd(w, w_right);
            const __m128d to_c =
                _mm_mul_pd(w_left, _mm_add_pd(_mm_mul_pd(half, _mm_sub_pd(span, r)),
                                              _mm_max_pd(zero, _mm_sub_pd(right, xr))));
            const __m128d to_c2 = _mm_mul_pd(w_right, _mm_mul_pd(half, r));
            to_cs[p] = to_c;
            to_c2s[p] = to_c2;
            to_c1s[p] = _mm_sub_pd(_mm_sub_pd(w, to_c), to_c2);
            cols[p][0] = static_cast<std::uint32_t>(_mm_cvtsi128_si32(col));
            cols[p][1] = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_srli_si128(col, 4)));
            lanes[p] = _mm_movemask_pd(in_two) | _mm_movemask_pd(_mm_cmpeq_pd(weight, zero)) << 2;
        }
        for (std::size_t p = 0; p < pairs; ++p, k += 2) {
            const __m128d to_c = to_cs[p], to_c1 = to_c1s[p], to_c2 = to_c2s[p];
            const std::size_t col0 = cols[p][0], col1 = cols[p][1];
            if (lanes[p] == 3 && col1 - col0 <= 1) {
                // Both pieces in cells c..c + 3 (neighbouring boundaries: a grating's, a
                // chain's pieces): added in registers, lane 0's adds then lane 1's to each
                // cell, which is the scalar order, so the same sums; a cell a lane does not
                // reach gets + 0, which changes no sum (a sum is never -0). Lane 1 no longer
                // waits for lane 0's stores to be forwarded to its loads.
                const std::size_t c = col0;
                const __m128d lane1_c0 = _mm_unpackhi_pd(to_c, to_c);
                const __m128d lane1_c1 = _mm_unpackhi_pd(to_c1, to_c1);
                const __m128d lane1_c2 = _mm_unpackhi_pd(to_c2, to_c2);
                // Lane 0's adds to cells (c, c + 1) and (c + 2, c + 3).
                const __m128d first_lo = _mm_unpacklo_pd(to_c, to_c1);
                const __m128d first_hi = _mm_move_sd(zero, to_c2);
                // Lane 1's: shifted by one cell when it lies one cell right.
                const __m128d shifted = _mm_castsi128_pd(
                    _mm_set1_epi64x(-static_cast<long long>(col1 - c)));  // all ones or zeros
                const __m128d second_lo = select_pd(shifted, _mm_unpacklo_pd(zero, lane1_c0),
                                                    _mm_unpacklo_pd(lane1_c0, lane1_c1));
                const __m128d second_hi = select_pd(shifted, _mm_unpacklo_pd(lane1_c1, lane1_c2),
                                                    _mm_move_sd(zero, lane1_c2));
                // Cell by cell in and out (8-byte loads and stores): a 16-byte load across two
                // earlier stores cannot be forwarded from them and waits for both to retire.
                const __m128d lo = _mm_add_pd(_mm_add_pd(load_cells(acc + c), first_lo), second_lo);
                const __m128d hi =
                    _mm_add_pd(_mm_add_pd(load_cells(acc + c + 2), first_hi), second_hi);
                _mm_storel_pd(acc + c, lo);
                _mm_storeh_pd(acc + c + 1, lo);
                _mm_storel_pd(acc + c + 2, hi);
                _mm_storeh_pd(acc + c + 3, hi);
                touched[c / kBlock] = kSet;
                touched[(c + 2) / kBlock] = kSet;
                touched[(col1 + 2) / kBlock] = kSet;
                continue;
            }
            // In order, lane 0 first: a cell's sum is the same sequence of additions.
            alignas(16) double c0[2], c1[2], c2[2];
            _mm_store_pd(c0, to_c);
            _mm_store_pd(c1, to_c1);
            _mm_store_pd(c2, to_c2);
            for (int lane = 0; lane < 2; ++lane) {
                if (lanes[p] & (4 << lane)) continue;  // weight 0
                if (lanes[p] & (1 << lane)) {
                    const std::size_t c = cols[p][lane];
                    acc[c] += c0[lane];
                    acc[c + 1] += c1[lane];
                    acc[c + 2] += c2[lane];
                    touched[c / kBlock] = kSet;
                    touched[(c + 2) / kBlock] = kSet;
                } else {
                    add_segment_now(xa_in[k + lane], xb_in[k + lane], height_of(k + lane),
                                    weights[k + lane]);
                }
            }
        }
    }
#endif
    for (; k < n; ++k) {
        if (weights[k] != 0.0) add_segment_now(xa_in[k], xb_in[k], height_of(k), weights[k]);
    }
}

#if defined(__SSE2__) && defined(__x86_64__)
template <class V>
template <bool kOneHeight>
std::size_t AreaCoverRowOf<V>::batch_math_avx2(const double* xa_in, const double* xb_in,
                                     const double* heights, double height, const double* weights,
                                     std::size_t pairs, __m128d* to_cs, __m128d* to_c1s,
                                     __m128d* to_c2s, std::uint32_t (*cols)[2], int* lanes) const {
    // The SSE2 pass's operations lane by lane: min/max operand order as there, and ordered
    // compares (false for NaN) as SSE2's cmpge/cmplt/cmpgt/cmpeq.
    const __m256d zero = _mm256_setzero_pd(), half = _mm256_set1_pd(0.5);
    const __m256d one = _mm256_set1_pd(1.0), min_normal = _mm256_set1_pd(DBL_MIN);
    const __m256d last = _mm256_set1_pd(width_ - 1.0);
    std::size_t p = 0;
    for (; p + 2 <= pairs; p += 2) {
        const std::size_t i = 2 * p;
        const __m256d xa = _mm256_loadu_pd(xa_in + i), xb = _mm256_loadu_pd(xb_in + i);
        const __m256d weight = _mm256_loadu_pd(weights + i);
        const __m256d w = _mm256_mul_pd(
            weight, kOneHeight ? _mm256_set1_pd(height) : _mm256_loadu_pd(heights + i));
        const __m256d xl = _mm256_min_pd(xb, xa), xr = _mm256_max_pd(xb, xa);
        const __m128i col = _mm256_cvttpd_epi32(xl);
        const __m256d right = _mm256_add_pd(_mm256_cvtepi32_pd(col), one);
        const __m256d in_two = _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd(xl, zero, _CMP_GE_OS), _mm256_cmp_pd(xl, last, _CMP_LT_OS)),
            _mm256_and_pd(_mm256_cmp_pd(xr, zero, _CMP_GT_OS),
                          _mm256_cmp_pd(xr, _mm256_add_pd(right, one), _CMP_LT_OS)));
        const __m256d r = _mm256_max_pd(zero, _mm256_sub_pd(xr, right));
        const __m256d span = _mm256_sub_pd(xr, xl);
        const __m256d w_right = _mm256_mul_pd(w, _mm256_div_pd(r, _mm256_max_pd(min_normal, span)));
        const __m256d w_left = _mm256_sub_pd(w, w_right);
        const __m256d to_c =
            _mm256_mul_pd(w_left, _mm256_add_pd(_mm256_mul_pd(half, _mm256_sub_pd(span, r)),
                                                _mm256_max_pd(zero, _mm256_sub_pd(right, xr))));
        const __m256d to_c2 = _mm256_mul_pd(w_right, _mm256_mul_pd(half, r));
        const __m256d to_c1 = _mm256_sub_pd(_mm256_sub_pd(w, to_c), to_c2);
        to_cs[p] = _mm256_castpd256_pd128(to_c);
        to_cs[p + 1] = _mm256_extractf128_pd(to_c, 1);
        to_c1s[p] = _mm256_castpd256_pd128(to_c1);
        to_c1s[p + 1] = _mm256_extractf128_pd(to_c1, 1);
        to_c2s[p] = _mm256_castpd256_pd128(to_c2);
        to_c2s[p + 1] = _mm256_extractf128_pd(to_c2, 1);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(&cols[p][0]), col);
        const int two = _mm256_movemask_pd(in_two);
        const int skip = _mm256_movemask_pd(_mm256_cmp_pd(weight, zero, _CMP_EQ_OQ));
        lanes[p] = (two & 3) | (skip & 3) << 2;
        lanes[p + 1] = (two >> 2) | (skip >> 2) << 2;
    }
    return p;
}
#endif

}  // namespace aabench
