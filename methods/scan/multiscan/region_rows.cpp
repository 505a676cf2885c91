#include "methods/scan/multiscan/region_rows.h"

#include <algorithm>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace aabench {
namespace {

// A RowPair in a register: a change's terms for both pixel rows are computed and added as one
// vector (two doubles side by side in the cells). Written with SSE2 where there is SSE2:
// GCC, left to pair scalar code itself, stored the scalar sums to the stack and reloaded them
// as one vector, a store-forwarding stall that was a third of the whole-row sums' time.
#if defined(__SSE2__)
using Pair = __m128d;
inline Pair zero() { return _mm_setzero_pd(); }
inline Pair splat(double v) { return _mm_set1_pd(v); }
inline Pair load(const double* p) { return _mm_loadu_pd(p); }
inline Pair load(const RowPair& p) { return _mm_loadu_pd(&p.upper); }
// Two doubles of a node (RegionWeights::nodes(): 16-byte aligned), a load that folds into the
// arithmetic.
inline Pair load_node(const double* p) { return _mm_load_pd(p); }
inline void store(RowPair& p, Pair v) { _mm_storeu_pd(&p.upper, v); }
// (+, - and * on __m128d are GCC's and Clang's vector arithmetic: addpd, subpd, mulpd.)
// max(min(v, hi), 0) in two instructions (a NaN gives 0).
inline double clamp_table(double v, double hi) {
    return _mm_cvtsd_f64(_mm_max_sd(_mm_setzero_pd(), _mm_min_sd(_mm_set_sd(v), _mm_set_sd(hi))));
}
#else
struct Pair {
    double upper, lower;
};
inline Pair zero() { return {0.0, 0.0}; }
inline Pair splat(double v) { return {v, v}; }
inline Pair load(const double* p) { return {p[0], p[1]}; }
inline Pair load(const RowPair& p) { return {p.upper, p.lower}; }
inline Pair load_node(const double* p) { return {p[0], p[1]}; }
inline void store(RowPair& p, Pair v) { p = {v.upper, v.lower}; }
inline Pair operator+(Pair a, Pair b) { return {a.upper + b.upper, a.lower + b.lower}; }
inline Pair operator-(Pair a, Pair b) { return {a.upper - b.upper, a.lower - b.lower}; }
inline Pair operator*(Pair a, Pair b) { return {a.upper * b.upper, a.lower * b.lower}; }
inline double clamp_table(double v, double hi) { return v < hi ? (v > 0.0 ? v : 0.0) : hi; }
#endif

// Line l's terms at t = x' lut from its nodes, added to left and right; -1 < t < lut + 1
// (t == lut reads the last node, whose differences are 0; a t an ulp outside [0, lut], from an
// x an ulp outside its region, reads the first or last node and extrapolates by that ulp).
[[gnu::always_inline]] inline void add_node_terms(const double* nodes, double t, Pair& left,
                                                  Pair& right) {
    const int j = static_cast<int>(t);
    const Pair f = splat(t - j);
    const double* a = nodes + 8 * static_cast<std::size_t>(j);
    left = left + (load_node(a) + f * load_node(a + 4));
    right = right + (load_node(a + 2) + f * load_node(a + 6));
}

// The same for any x' (clamped to [0, 1]).
[[gnu::always_inline]] inline void add_line_terms(const double* nodes, double lut, double x,
                                                  Pair& left, Pair& right) {
    add_node_terms(nodes, clamp_table(x * lut, lut), left, right);
}

}  // namespace

RegionWeights::RegionWeights(const CrossSectionTable& table)
    : table_(&table), n_(table.sub_scanlines()), lut_(table.lut_steps()) {
    fraction_.resize(n_);
    total_.resize(n_);
    for (int l = 0; l < n_; ++l) {
        fraction_[l] = static_cast<double>(l) / n_;
        // F_n = 0: line 0 adds nothing to the row below.
        total_[l] = {2.0 * table.total(l), 2.0 * table.total(n_ - l)};
        total_sum_.upper += total_[l].upper;
        total_sum_.lower += total_[l].lower;
    }
    // Only where whole region rows are taken: n = 256 with lut = 4096 would take 67 MB.
    if (lut_ == 0 || n_ > SubscanlineTracer::kMaxRowIntervals) return;
    nodes_.assign(static_cast<std::size_t>(n_) * (lut_ + 1) * 8, 0.0);
    for (int l = 0; l < n_; ++l) {
        const int m = n_ - l;
        const auto terms = [&](int j, double* a) {
            a[0] = table.total(l) - table.node(l, j);
            a[1] = table.total(m) - table.node(m, j);
            a[2] = table.total(l) - table.node(l, lut_ - j);
            a[3] = table.total(m) - table.node(m, lut_ - j);
        };
        for (int j = 0; j <= lut_; ++j) {
            double* a = nodes_.data() + (static_cast<std::size_t>(l) * (lut_ + 1) + j) * 8;
            terms(j, a);
            if (j == lut_) continue;  // the last node's differences stay 0
            double next[4];
            terms(j + 1, next);
            for (int c = 0; c < 4; ++c) a[4 + c] = next[c] - a[c];
        }
    }
}

void RegionWeights::add_table_terms(int l, double x, RowPair& left, RowPair& right) const {
    const int m = n_ - l;
    left.upper += table_->total(l) - table_->at(l, x);
    left.lower += table_->total(m) - table_->at(m, x);
    right.upper += table_->total(l) - table_->at(l, 1.0 - x);
    right.lower += table_->total(m) - table_->at(m, 1.0 - x);
}

void RegionRowSums::add_start(double start, double weight, int l) {
    const double d = weight * (start - background_);  // 0: every line starts on the background
    const RowPair& total = l >= 0 ? weights_.total(l) : weights_.total_sum();
    cells_.base().upper += d * total.upper;
    cells_.base().lower += d * total.lower;
}

void RegionRowSums::add_line(const LineProfile& line, int l, double weight) {
    add_start(line.start, weight, l);
    double before = line.start;
    for (const ValueChange& change : line.changes) {
        add_line_change(l, change.x, weight * (change.value - before));
        before = change.value;
    }
}

void RegionRowSums::add_line_change(int l, double x, double dv) {
    if (x < -0.5) {  // left of every region: the whole weight to every pixel
        RowPair& cell0 = cells_[0];
        store(cell0, load(cell0) + splat(dv) * load(weights_.total(l)));
    } else if (x < cells_.width() + 0.5) {  // else right of every region (or NaN): nothing
        const double u = x + 0.5;
        const auto q = static_cast<std::int64_t>(u);
        Pair left = zero(), right = zero();
        if (weights_.has_nodes()) {
            add_line_terms(weights_.nodes(l), weights_.lut_steps(), u - q, left, right);
        } else {
            RowPair table_left, table_right;
            weights_.add_table_terms(l, u - q, table_left, table_right);
            left = load(table_left);
            right = load(table_right);
        }
        add_region(cells_, q, left, right, load(weights_.total(l)), dv);
    }
}

template <class P>
[[gnu::always_inline]] inline void RegionRowSums::add_region(RegionCells& cells, std::int64_t q,
                                                             P left, P right, P total, double dv) {
    const P v = splat(dv);
    P a = v * left, b, d = v * right;
    b = v * total - a - d;
    std::size_t c = 0;
    if (q == 0) {  // R_{-1}: pixel -1's cell reaches every pixel from 0 on
        a = a + b;
        b = d;
        d = zero();
    } else {
        c = static_cast<std::size_t>(q - 1);
    }
    RowPair* cell = cells.cells() + c;
    store(cell[0], load(cell[0]) + a);
    store(cell[1], load(cell[1]) + b);
    store(cell[2], load(cell[2]) + d);
    cells.flags()[c / RegionCells::kBlock] = RegionCells::Flag::kSet;
    cells.flags()[(c + 2) / RegionCells::kBlock] = RegionCells::Flag::kSet;
}

// add_region() for a change whose lines lie in the regions R_{q-1} ([0]) and R_q ([1]).
template <class P>
[[gnu::always_inline]] inline void RegionRowSums::add_two_regions(RegionCells& cells,
                                                                  std::int64_t q, const P* left,
                                                                  const P* right, const P* total,
                                                                  double dv) {
    const P v = splat(dv);
    P a[2], b[2], d[2];
    for (int r = 0; r < 2; ++r) {
        a[r] = v * left[r];
        d[r] = v * right[r];
        b[r] = v * total[r] - a[r] - d[r];
    }
    // Cells q - 1 .. q + 2; cell -1 (q == 0) folded into cell 0.
    P sums[4] = {a[0], b[0] + a[1], d[0] + b[1], d[1]};
    std::size_t c = 0;
    if (q == 0) {
        sums[0] = sums[0] + sums[1];
        sums[1] = sums[2];
        sums[2] = sums[3];
        sums[3] = zero();
    } else {
        c = static_cast<std::size_t>(q - 1);
    }
    RowPair* cell = cells.cells() + c;
    for (int k = 0; k < 4; ++k) store(cell[k], load(cell[k]) + sums[k]);
    cells.flags()[c / RegionCells::kBlock] = RegionCells::Flag::kSet;
    cells.flags()[(c + 3) / RegionCells::kBlock] = RegionCells::Flag::kSet;
}

void RegionRowSums::add_change(const double* xs, int first, int end, double lo, double hi,
                               double dv) {
    if (first >= end) return;
    const double width = cells_.width();
    if (lo >= width + 0.5) return;  // right of every region: no pixel of the image is right of it
    RowPair& cell0 = cells_[0];
    const bool all_lines = first == 0 && end == weights_.sub_scanlines();
    const auto whole_weight = [&] {
        if (all_lines) return load(weights_.total_sum());
        Pair total = zero();
        for (int l = first; l < end; ++l) total = total + load(weights_.total(l));
        return total;
    };
    if (hi < -0.5) {  // left of every region: the whole weight to every pixel
        store(cell0, load(cell0) + splat(dv) * whole_weight());
        return;
    }
    const int lut = weights_.has_nodes() ? weights_.lut_steps() : 0;
    // Region R_i holds x when i + 0.5 <= x < i + 1.5: q = i + 1 = floor(x + 0.5), which is the
    // truncation of x + 0.5 >= 0. Rounding is monotonic, so when lo and hi give one q, every
    // line between them does (an interpolated x an ulp outside [lo, hi] lands at x' an ulp
    // outside [0, 1], clamped: the terms are continuous across region borders).
    if (lo >= -0.5 && hi < width + 0.5) {
        const auto q = static_cast<std::int64_t>(lo + 0.5);
        if (hi + 0.5 < q + 1.0) {  // one region on every line: the lines summed first
            Pair left = zero(), right = zero();
            if (lut > 0) {  // x' within rounding of [0, 1]: no clamp (add_node_terms())
                for (int l = first; l < end; ++l) {
                    add_node_terms(weights_.nodes(l), ((xs[l] + 0.5) - q) * lut, left, right);
                }
            } else {
                RowPair table_left, table_right;
                for (int l = first; l < end; ++l) {
                    weights_.add_table_terms(l, (xs[l] + 0.5) - q, table_left, table_right);
                }
                left = load(table_left);
                right = load(table_right);
            }
            add_region(cells_, q, left, right, whole_weight(), dv);
            return;
        }
        if (lut > 0 && hi + 0.5 < q + 2.0) {
            // Two regions (a change crossing a region border within the row: many of a ring's):
            // each line's terms summed into its region's, then four cells written, not three
            // per line.
            // Sums in registers, not an array indexed by region (a store-forwarding chain).
            Pair left0 = zero(), right0 = zero(), total0 = zero();
            Pair left1 = zero(), right1 = zero(), total1 = zero();
            const double border = q + 1.0;
            for (int l = first; l < end; ++l) {
                const double u = xs[l] + 0.5;
                if (u < border) {
                    add_node_terms(weights_.nodes(l), (u - q) * lut, left0, right0);
                    total0 = total0 + load(weights_.total(l));
                } else {
                    add_node_terms(weights_.nodes(l), (u - border) * lut, left1, right1);
                    total1 = total1 + load(weights_.total(l));
                }
            }
            const Pair left[2] = {left0, left1}, right[2] = {right0, right1};
            const Pair total[2] = {total0, total1};
            add_two_regions(cells_, q, left, right, total, dv);
            return;
        }
    }
    // Across more regions: line by line.
    for (int l = first; l < end; ++l) add_line_change(l, xs[l], dv);
}

void RegionRowSums::add_row_spans(double start, const double* x, const double* dv,
                                  std::size_t count, int n) {
    // n = 3, the default (the paper's), with its line loops unrolled: 2 ms of 29 on a grating
    // at 1024^2. The same sums as any other n's code.
    if (n == 3) return add_spans<3>(start, x, dv, count, n);
    add_spans<0>(start, x, dv, count, n);
}

// add_spans()'s batches. The changes whose lines lie in one region, or two (add_change()'s
// tests: most of a grating's, a twentieth of them crossing a region border), are taken in
// batches of kBatch, in two passes. The first (take_one(), take_two()) finds each line's
// region, table node and fraction (x(l/n) on the straight line between the borders, as the
// tracer's add_alternating_row() interpolates), two changes at once where both stay in one
// region; the second (add()) interpolates the nodes and adds the terms. Change by change, the
// chain from x through the region, t, the node index and the fraction to the terms was so long
// that the processor overlapped too few changes. The terms and their order are those of the
// change-by-change sum, bit for bit: a one-region change's t from line 0's plus
// (bottom - top) l/n lut (the batch's and the first half pixel's below), a two-region
// change's add_change()'s. Every member is inlined into add_spans(), whose loop keeps the
// batch in its frame and its window of cells in registers, as one function would.
template <int kLines>
class RegionRowSums::SpanBatch {
public:
    static constexpr std::size_t kBatch = 32;  // as fast as 64 on the grating; 16 was slower

    [[gnu::always_inline]] SpanBatch(RegionRowSums& sums, const double* x, const double* dv, int n)
        : weights_(sums.weights_),
          x_(x),
          dv_(dv),
          width_(sums.cells_.width()),
          lut_(sums.weights_.lut_steps()),
          lines_(static_cast<std::size_t>(n)),
          total_(load(sums.weights_.total_sum())),
          cells_(sums.cells_.cells()),
          flags_(sums.cells_.flags()) {
#if defined(__SSE2__) && defined(__x86_64__)
        for (std::size_t l = 0; l < lines(); ++l) {
            line_fraction_[l] = splat(weights_.fraction(static_cast<int>(l)));
        }
#endif
    }
    // The lines per change: kLines, known here, or n.
    [[gnu::always_inline]] std::size_t lines() const {
        if constexpr (kLines > 0) return kLines;
        return lines_;
    }

    // Change k into the batch at m; false (nothing taken) when it needs add_change().
    [[gnu::always_inline]] bool take_one(std::size_t k, std::size_t m) {
        const std::size_t lines = this->lines();
        const double top = x_[2 * k], bottom = x_[2 * k + 1];
        const double lo = std::min(top, bottom), hi = std::max(top, bottom);
        // Region R_{-1} (lo < 0.5) folds a cell: add_change().
        if (!(lut_ > 0 && lo >= 0.5 && hi < width_ + 0.5)) return false;
        const auto q = static_cast<std::int64_t>(lo + 0.5);
        const std::size_t at = m * lines;
        if (hi + 0.5 < q + 1.0) {
            // One region: t on line l is (x' on line 0 + (bottom - top) l/n) lut, within
            // rounding of [0, lut] (lo and hi lie in the region); add_node_terms()'s node and
            // fraction.
            const double t0 = ((top + 0.5) - q) * lut_, dt = (bottom - top) * lut_;
            for (std::size_t l = 0; l < lines; ++l) {
                const double t = l == 0 ? t0 : t0 + dt * weights_.fraction(static_cast<int>(l));
                const int j = static_cast<int>(t);
                node_at_[at + l] =
                    weights_.nodes(static_cast<int>(l)) + 8 * static_cast<std::size_t>(j);
                fraction_at_[at + l] = t - j;
            }
            split_at_[m] = false;
        } else if (hi + 0.5 < q + 2.0) {
            // Two regions: each line's x' from its own region's left side.
            const double border = q + 1.0;
            for (std::size_t l = 0; l < lines; ++l) {
                const double xl =
                    l == 0 ? top : top + (bottom - top) * weights_.fraction(static_cast<int>(l));
                const double u = xl + 0.5;
                const bool second = !(u < border);
                const double t = (u - (second ? border : static_cast<double>(q))) * lut_;
                const int j = static_cast<int>(t);
                node_at_[at + l] =
                    weights_.nodes(static_cast<int>(l)) + 8 * static_cast<std::size_t>(j);
                fraction_at_[at + l] = t - j;
                second_at_[at + l] = second;
            }
            split_at_[m] = true;
        } else {
            return false;
        }
        region_at_[m] = static_cast<std::size_t>(q);
        dv_at_[m] = dv_[k];
        return true;
    }

#if defined(__SSE2__) && defined(__x86_64__)  // _mm_cvtsi128_si64
    // Changes k and k + 1 into the batch at m and m + 1 when both stay in one region:
    // take_one()'s arithmetic, lane by lane (the int32 conversions agree with take_one()'s
    // wherever the tests pass: 0 < lo + 0.5 < width + 1).
    [[gnu::always_inline]] bool take_two(std::size_t k, std::size_t m) {
        const std::size_t lines = this->lines();
        const Pair p = _mm_loadu_pd(x_ + 2 * k), r = _mm_loadu_pd(x_ + 2 * k + 2);
        const Pair top = _mm_unpacklo_pd(p, r), bottom = _mm_unpackhi_pd(p, r);
        const Pair lo = _mm_min_pd(top, bottom), hi = _mm_max_pd(top, bottom);
        const Pair half = splat(0.5);
        const __m128i qi = _mm_cvttpd_epi32(lo + half);
        const Pair q = _mm_cvtepi32_pd(qi);
        const Pair in_image =
            _mm_and_pd(_mm_cmpge_pd(lo, half), _mm_cmplt_pd(hi, splat(width_ + 0.5)));
        const Pair one_region = _mm_cmplt_pd(hi + half, q + splat(1.0));
        if (_mm_movemask_pd(_mm_and_pd(in_image, one_region)) != 3) return false;
        const Pair t0 = ((top + half) - q) * splat(lut_), dt = (bottom - top) * splat(lut_);
        const std::size_t at = m * lines;
        for (std::size_t l = 0; l < lines; ++l) {
            const Pair t = l == 0 ? t0 : t0 + dt * line_fraction_[l];
            const __m128i j = _mm_cvttpd_epi32(t);
            const Pair f = t - _mm_cvtepi32_pd(j);
            const auto js = static_cast<std::uint64_t>(_mm_cvtsi128_si64(j));
            const double* nodes = weights_.nodes(static_cast<int>(l));
            node_at_[at + l] = nodes + 8 * (js & 0xffffffffu);
            node_at_[at + lines + l] = nodes + 8 * (js >> 32);
            _mm_storel_pd(fraction_at_ + at + l, f);
            _mm_storeh_pd(fraction_at_ + at + lines + l, f);
        }
        const auto qs = static_cast<std::uint64_t>(_mm_cvtsi128_si64(qi));
        region_at_[m] = qs & 0xffffffffu;
        region_at_[m + 1] = qs >> 32;
        split_at_[m] = split_at_[m + 1] = false;
        dv_at_[m] = dv_[k];
        dv_at_[m + 1] = dv_[k + 1];
        return true;
    }
#endif

    // The terms of the batch's m changes, in order. The three cells c..c + 2 of the last
    // change are held in registers (w0..w2) while the changes stay near (they come left to
    // right, a grating's two in most regions): each cell is loaded when it enters and stored
    // when it leaves, so it sees the same additions in the same order as in the array (bit for
    // bit), without every change waiting for the store of the one before (two of its three
    // cells are the last one's).
    [[gnu::always_inline]] void add(std::size_t m) {
        const std::size_t lines = this->lines();
        RowPair* const cells = cells_;
        RegionCells::Flag* const flags = flags_;
        std::size_t c = region_at_[0] - 1;
        Pair w0 = load(cells[c]), w1 = load(cells[c + 1]), w2 = load(cells[c + 2]);
        flags[c / RegionCells::kBlock] = RegionCells::Flag::kSet;
        flags[(c + 2) / RegionCells::kBlock] = RegionCells::Flag::kSet;
        const auto move_to = [&](std::size_t first) {
            if (first == c) return;
            if (first == c + 1) {  // one cell on: c leaves, c + 3 enters
                store(cells[c], w0);
                w0 = w1;
                w1 = w2;
                w2 = load(cells[first + 2]);
            } else {
                store(cells[c], w0);
                store(cells[c + 1], w1);
                store(cells[c + 2], w2);
                w0 = load(cells[first]);
                w1 = load(cells[first + 1]);
                w2 = load(cells[first + 2]);
            }
            c = first;
            flags[first / RegionCells::kBlock] = RegionCells::Flag::kSet;
            flags[(first + 2) / RegionCells::kBlock] = RegionCells::Flag::kSet;
        };
        for (std::size_t i = 0; i < m; ++i) {
            const std::size_t at = i * lines;
            const Pair v = splat(dv_at_[i]);
            const std::size_t first = region_at_[i] - 1;
            if (!split_at_[i]) {  // add_change()'s one region: add_region()'s three cells
                Pair left = zero(), right = zero();
                for (std::size_t l = 0; l < lines; ++l) {
                    const double* a = node_at_[at + l];
                    const Pair f = splat(fraction_at_[at + l]);
                    left = left + (load_node(a) + f * load_node(a + 4));
                    right = right + (load_node(a + 2) + f * load_node(a + 6));
                }
                const Pair a = v * left, d = v * right;
                const Pair b = v * total_ - a - d;
                move_to(first);
                w0 = w0 + a;
                w1 = w1 + b;
                w2 = w2 + d;
                continue;
            }
            // add_change()'s two regions: each line's terms summed into its region's, then
            // add_two_regions()'s four cells q - 1 .. q + 2, the last straight to the array
            // (it is not in the window, which loads it if it enters).
            Pair left0 = zero(), right0 = zero(), total0 = zero();
            Pair left1 = zero(), right1 = zero(), total1 = zero();
            for (std::size_t l = 0; l < lines; ++l) {
                const double* a = node_at_[at + l];
                const Pair f = splat(fraction_at_[at + l]);
                const Pair left_l = load_node(a) + f * load_node(a + 4);
                const Pair right_l = load_node(a + 2) + f * load_node(a + 6);
                const Pair total_l = load(weights_.total(static_cast<int>(l)));
                if (second_at_[at + l]) {
                    left1 = left1 + left_l;
                    right1 = right1 + right_l;
                    total1 = total1 + total_l;
                } else {
                    left0 = left0 + left_l;
                    right0 = right0 + right_l;
                    total0 = total0 + total_l;
                }
            }
            const Pair a0 = v * left0, d0 = v * right0, b0 = v * total0 - a0 - d0;
            const Pair a1 = v * left1, d1 = v * right1, b1 = v * total1 - a1 - d1;
            move_to(first);
            w0 = w0 + a0;
            w1 = w1 + (b0 + a1);
            w2 = w2 + (d0 + b1);
            store(cells[first + 3], load(cells[first + 3]) + d1);
            flags[(first + 3) / RegionCells::kBlock] = RegionCells::Flag::kSet;
        }
        store(cells[c], w0);
        store(cells[c + 1], w1);
        store(cells[c + 2], w2);
    }

private:
    static constexpr std::size_t kMaxLines = LineIntegralRow::kMaxLines;
    const RegionWeights& weights_;
    const double* x_;
    const double* dv_;
    double width_;
    int lut_;
    std::size_t lines_;
    Pair total_;
    RowPair* cells_;
    RegionCells::Flag* flags_;
    const double* node_at_[kBatch * kMaxLines];  // change i's line l: [i * lines + l]
    double fraction_at_[kBatch * kMaxLines];
    bool second_at_[kBatch * kMaxLines];  // (two regions) the line lies in region q, not q - 1
    std::size_t region_at_[kBatch];       // q: the change's (first) region is R_{q-1}
    bool split_at_[kBatch];               // its lines lie in two regions, R_{q-1} and R_q
    double dv_at_[kBatch];
#if defined(__SSE2__) && defined(__x86_64__)
    Pair line_fraction_[kMaxLines];
#endif
};

template <int kLines>
void RegionRowSums::add_spans(double start, const double* x, const double* dv, std::size_t count,
                              int n) {
    if constexpr (kLines > 0) n = kLines;
    add_start(start);
    const int lut = weights_.lut_steps();
    const Pair total = load(weights_.total_sum());
    constexpr std::size_t kBatch = SpanBatch<kLines>::kBatch;
    SpanBatch<kLines> batch(*this, x, dv, n);
    double xs[LineIntegralRow::kMaxLines];
    std::size_t k = 0;
    while (k < count) {
        std::size_t m = 0;
        bool declined = false;  // changes[k] needs add_change()
        while (k < count && m < kBatch) {
#if defined(__SSE2__) && defined(__x86_64__)
            if (lut > 0 && k + 1 < count && m + 1 < kBatch && batch.take_two(k, m)) {
                k += 2;
                m += 2;
                continue;
            }
#endif
            if (!batch.take_one(k, m)) {
                declined = true;
                break;
            }
            ++k;
            ++m;
        }
        if (m > 0) batch.add(m);
        if (declined) {
            const double top = x[2 * k], bottom = x[2 * k + 1];
            const double lo = std::min(top, bottom), hi = std::max(top, bottom);
            // One region R_{-1} (the first half pixel): its t from line 0's as in the batch,
            // not add_change()'s per-line x (another rounding), and add_region() folds cell -1.
            if (lut > 0 && lo >= -0.5 && hi + 0.5 < 1.0) {
                const double t0 = (top + 0.5) * lut, dt = (bottom - top) * lut;
                Pair left = zero(), right = zero();
                add_node_terms(weights_.nodes(0), t0, left, right);
                for (int l = 1; l < n; ++l) {
                    add_node_terms(weights_.nodes(l), t0 + dt * weights_.fraction(l), left, right);
                }
                add_region(cells_, 0, left, right, total, dv[k]);
                ++k;
                continue;
            }
            xs[0] = top;
            for (int l = 1; l < n; ++l) xs[l] = top + (bottom - top) * weights_.fraction(l);
            add_change(xs, 0, n, lo, hi, dv[k]);
            ++k;
        }
    }
}

void RegionRowSums::add_row_lines(double start, const double* x, const double* dv,
                                  std::size_t count, int n) {
    add_start(start);
    const int lines = n + 1;
    for (std::size_t k = 0; k < count; ++k) {
        const double* xs = x + k * static_cast<std::size_t>(lines);
        const auto [lo, hi] = std::minmax_element(xs, xs + n);
        add_change(xs, 0, n, *lo, *hi, dv[k]);
    }
}

// Pixel row r's sum of two rows' cells, in order (the kernel row's prefix sum, cells.h): a block
// neither row flagged adds nothing and is written as one constant. `from_above` is zeroed and
// unflagged as it is read, and its blocks past the last pixel after the row: a second pass over
// its flags and cells was a fifth of gauss-multiscan's render on star.
void RegionRowSums::resolve_and_clear(RegionCells& from_above, const RegionCells& here,
                                      double background, float* out) {
    const double start = background + (from_above.base().lower + here.base().upper);
    const RowPair* a = from_above.cells();
    const RowPair* b = here.cells();
    from_above.resolve_and_clear(
        start, out, [](std::size_t, double sum) { return static_cast<float>(sum); },
        [a, b](std::size_t i) { return a[i].lower + b[i].upper; }, &here);
}

}  // namespace aabench
