#include "methods/scan/region_rows.h"

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
    left = left + (load(a) + f * load(a + 4));
    right = right + (load(a + 2) + f * load(a + 6));
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

void RegionCells::reset(int width) {
    width_ = width;
    // At least width + 2 cells, in whole words of flags.
    constexpr std::size_t kWordCells = kFlagWord * kBlock;
    const std::size_t words = (static_cast<std::size_t>(width) + 2 + kWordCells - 1) / kWordCells;
    cells_.assign(words * kWordCells, RowPair{});
    flags_.assign(words * kFlagWord, Flag::kClear);
    base_ = {};
}

void RegionCells::clear() {
    base_ = {};
    RowPair* cells = cells_.data();
    for (std::size_t w = 0; w < flags_.size(); w += kFlagWord) {
        if (w != 0 && flag_word(w) == 0) continue;
        for (std::size_t b = w; b < w + kFlagWord; ++b) {
            if (b != 0 && flags_[b] == Flag::kClear) continue;
            std::fill(cells + b * kBlock, cells + (b + 1) * kBlock, RowPair{});
            flags_[b] = Flag::kClear;
        }
    }
}

void RegionRowSums::add_start(double start, double weight, int l) {
    const double d = weight * (start - background_);  // 0: every line starts on the background
    const RowPair& total = l >= 0 ? weights_.total(l) : weights_.total_sum();
    cells_.base_.upper += d * total.upper;
    cells_.base_.lower += d * total.lower;
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
        RowPair& cell0 = cells_.cells_[0];
        store(cell0, load(cell0) + splat(dv) * load(weights_.total(l)));
    } else if (x < cells_.width_ + 0.5) {  // else right of every region (or NaN): nothing
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
    RowPair* cell = cells.cells_.data() + c;
    store(cell[0], load(cell[0]) + a);
    store(cell[1], load(cell[1]) + b);
    store(cell[2], load(cell[2]) + d);
    cells.flags_[c / RegionCells::kBlock] = RegionCells::Flag::kSet;
    cells.flags_[(c + 2) / RegionCells::kBlock] = RegionCells::Flag::kSet;
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
    RowPair* cell = cells.cells_.data() + c;
    for (int k = 0; k < 4; ++k) store(cell[k], load(cell[k]) + sums[k]);
    cells.flags_[c / RegionCells::kBlock] = RegionCells::Flag::kSet;
    cells.flags_[(c + 3) / RegionCells::kBlock] = RegionCells::Flag::kSet;
}

void RegionRowSums::add_change(const double* xs, int first, int end, double lo, double hi,
                               double dv) {
    if (first >= end) return;
    const double width = cells_.width_;
    if (lo >= width + 0.5) return;  // right of every region: no pixel of the image is right of it
    RowPair& cell0 = cells_.cells_[0];
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
    add_start(start);
    const double width = cells_.width_;
    const int lut = weights_.lut_steps();
    const Pair total = load(weights_.total_sum());
    double xs[LineIntegralRow::kMaxLines];
    for (std::size_t k = 0; k < count; ++k) {
        const double top = x[2 * k], bottom = x[2 * k + 1];
        const double lo = std::min(top, bottom), hi = std::max(top, bottom);
        // x on line l on the straight line between the borders, x(l/n) (the tracer's
        // add_alternating_row() interpolates the same way).
        if (lut > 0 && lo >= -0.5 && hi < width + 0.5) {
            // One region on every line (add_change()'s test), inline: most changes of a
            // grating, each costing its n table reads and three pairs of cells.
            const auto q = static_cast<std::int64_t>(lo + 0.5);
            if (hi + 0.5 < q + 1.0) {
                // t on line l: (x' on line 0 + (bottom - top) l/n) lut, within rounding of
                // [0, lut] (lo and hi lie in the region).
                const double t0 = ((top + 0.5) - q) * lut, dt = (bottom - top) * lut;
                Pair left = zero(), right = zero();
                add_node_terms(weights_.nodes(0), t0, left, right);
                for (int l = 1; l < n; ++l) {
                    add_node_terms(weights_.nodes(l), t0 + dt * weights_.fraction(l), left, right);
                }
                add_region(cells_, q, left, right, total, dv[k]);
                continue;
            }
        }
        xs[0] = top;
        for (int l = 1; l < n; ++l) xs[l] = top + (bottom - top) * weights_.fraction(l);
        add_change(xs, 0, n, lo, hi, dv[k]);
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

void RegionRowSums::resolve(const RegionCells& from_above, const RegionCells& here,
                            double background, float* out) {
    const RowPair* a = from_above.cells_.data();
    const RowPair* b = here.cells_.data();
    const std::size_t width = static_cast<std::size_t>(here.width_);
    double sum = background + (from_above.base_.lower + here.base_.upper);
    // A block neither row flagged (its cells all +0.0) adds nothing, and is written as one
    // constant; a word of flags at once when neither flagged any of its blocks. (Adding +0.0
    // would give the same sum: sum + 0.0 == sum for every sum from background + 0.0 but -0.0.)
    constexpr std::size_t kBlock = RegionCells::kBlock, kWord = RegionCells::kFlagWord;
    const RegionCells::Flag* fa = from_above.flags_.data();
    const RegionCells::Flag* fb = here.flags_.data();
    std::size_t i = 0;
    for (std::size_t k = 0; i + kBlock <= width; ++k, i += kBlock) {
        if (k % kWord == 0 && k != 0 && i + kWord * kBlock <= width &&
            (from_above.flag_word(k) | here.flag_word(k)) == 0) {
            const float value = static_cast<float>(sum);
            for (std::size_t c = 0; c < kWord * kBlock; ++c) out[i + c] = value;
            k += kWord - 1;
            i += (kWord - 1) * kBlock;
            continue;
        }
        if (k != 0 && fa[k] == RegionCells::Flag::kClear && fb[k] == RegionCells::Flag::kClear) {
            const float value = static_cast<float>(sum);
            for (std::size_t c = 0; c < kBlock; ++c) out[i + c] = value;  // vectorised
            continue;
        }
        for (std::size_t c = 0; c < kBlock; ++c) {
            sum += a[i + c].lower + b[i + c].upper;
            out[i + c] = static_cast<float>(sum);
        }
    }
    for (; i < width; ++i) {
        sum += a[i].lower + b[i].upper;
        out[i] = static_cast<float>(sum);
    }
}

}  // namespace aabench
