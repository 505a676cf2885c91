// gauss-multiscan's region rows summed change by change (SubscanlineTracer::add_region_row,
// methods/scan/multiscan/subscanline.h), the whole-row machinery of box-multiscan applied to eq. 4
// of Nishita & Nakamae 1984 (methods/gauss_multiscan.cpp; docs/methods-multiscan.md).
//
// Eq. 4 per change. On line l of region row r (y = r + 0.5 + l/n), the runs of a region R_i
// (x from i + 0.5 to i + 1.5) scatter to the pixels i and i + 1 of the rows r (with F_l) and
// r + 1 (with F_m, m = n - l). Summed over a line, pixel p of row r receives the integral of
// the visible value v against the filter's cross-section centred on p. Written with the
// changes of v (by dv at x) instead of its runs, a change adds dv times the part of each
// pixel's support right of x: with x' = x - (i + 0.5) in R_i and T = F_l(1) (half a
// cross-section),
//     pixel i          dv (T - F_l(x'))
//     pixel i + 1      dv (T + F_l(1 - x'))
//     pixels > i + 1   dv 2T,
// which in a difference array (prefix sums give the pixels) is three cells: i += dv (T -
// F_l(x')), i + 1 += dv (F_l(x') + F_l(1 - x')), i + 2 += dv (T - F_l(1 - x')). The same with
// F_m in row r + 1. A change left of R_{-1} (x < -0.5) adds dv 2T to every pixel, one right
// of R_{width-1} nothing; pixel -1's cell is folded into pixel 0's.
//
// Why it is cheaper than the line-by-line scatter: a change costs its n lines' terms, the
// lines of a change that stay in one region are summed before anything is written, and the
// two rows' cells lie side by side, so a change writes three pairs; nothing is done per pixel
// but the prefix sum, and that only over the blocks of 8 pixels a change reached. The
// line-by-line scatter traced every line and walked every region not showing the background
// on it. A straight row's changes (add_row_spans) are taken in batches: first every line's
// node and fraction, two changes at once, then the terms, so that the processor overlaps
// many changes' table reads (a grating at 1024^2 took 34 ms, 27 ms after, with the nodes on
// cache lines and n = 3 unrolled).
//
// The terms at x' are interpolated from nodes that hold, for both rows, T - F at x' and at
// 1 - x', with their differences to the next node: one index per line, one cache line per
// node. Linear interpolation of T - F_l between nodes is that of F_l (the paper's table), and
// F_l(1 - x') interpolated in x' between nodes j and j + 1 is F_l interpolated between its
// nodes L - j and L - j - 1: the function CrossSectionTable::at gives, up to rounding. lut = 0
// evaluates them in closed form.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/multiscan/subscanline.h"

namespace aabench {

// Two doubles: a term of pixel row r (upper) and of row r + 1 (lower).
struct RowPair {
    double upper = 0.0, lower = 0.0;
};

class RegionWeights {
public:
    // The weights of `table`'s sub-scanlines (which must outlive this, for lut = 0).
    explicit RegionWeights(const CrossSectionTable& table);

    int sub_scanlines() const { return n_; }
    // Steps of the table, 0: closed form.
    int lut_steps() const { return lut_; }
    // Whether nodes() are built (lut_steps() > 0 and n within whole region rows' bound).
    bool has_nodes() const { return !nodes_.empty(); }
    // l / n, the place of line l between the region row's first line and the next one's.
    double fraction(int l) const { return fraction_[l]; }
    // Line l's nodes (lut_steps() > 0), each on a cache line of its own: node j (x' = j / lut)
    // at 8 j holds the terms
    //     T_l - F_l(x'), T_m - F_m(x'), T_l - F_l(1 - x'), T_m - F_m(1 - x')   (m = n - l)
    // and then their differences to node j + 1 (0 at the last node).
    const double* nodes(int l) const {
        return nodes_.data() + static_cast<std::size_t>(l) * (lut_ + 1) * 8;
    }
    // The same four terms from CrossSectionTable::at (its table or closed form), added to
    // left and right: where there are no nodes.
    void add_table_terms(int l, double x, RowPair& left, RowPair& right) const;
    // Line l's whole weight in rows r and r + 1: (2 T_l, 2 T_m).
    RowPair total(int l) const { return total_[l]; }
    // The sum of total() over the lines 0..n-1.
    RowPair total_sum() const { return total_sum_; }

private:
    const CrossSectionTable* table_;
    int n_;
    int lut_;
    // Storage that starts on a cache line, so that each node is one (and its pairs of doubles
    // are 16-byte aligned, loads that fold into the arithmetic).
    template <class T>
    struct CacheLineAllocator {
        using value_type = T;
        static constexpr std::align_val_t kAlign{64};
        CacheLineAllocator() = default;
        template <class U>
        CacheLineAllocator(const CacheLineAllocator<U>&) {}
        T* allocate(std::size_t count) {
            return static_cast<T*>(::operator new(count * sizeof(T), kAlign));
        }
        void deallocate(T* p, std::size_t) { ::operator delete(p, kAlign); }
        bool operator==(const CacheLineAllocator&) const { return true; }
    };
    // Per line, lut + 1 nodes of 8 (see nodes()).
    std::vector<double, CacheLineAllocator<double>> nodes_;
    std::vector<double> fraction_;
    std::vector<RowPair> total_;
    RowPair total_sum_;
};

// The terms of one region row for its two pixel rows: a kernel cell row of RowPairs
// (methods/scan/kernel/cells.h; cell i changes pixel i and every pixel right of it), with a flag
// per block of 8 cells a change reached, so that the prefix sum and the clearing skip the
// others; its base() is added to every pixel.
using RegionCells = CellRow<RowPair, 8>;

// The sink SubscanlineTracer::add_region_row() fills: region row r's terms into `cells`, which
// it finds empty and, when it declines, leaves empty. The values added are v - background (as
// the line-by-line scatter adds them); the background is resolve_and_clear()'s.
class RegionRowSums {
public:
    RegionRowSums(const RegionWeights& weights, double background, RegionCells& cells)
        : weights_(weights), background_(background), cells_(cells) {}

    // What SubscanlineTracer::add_lines() asks of a sink (subscanline_rows.cpp): changes that
    // run straight from x[2k] on line 0 to x[2k + 1] on line n, or with x on every line
    // (x[k (n + 1) + l]); line n belongs to the next region row and adds nothing.
    void add_row_spans(double start, const double* x, const double* dv, std::size_t count, int n);
    void add_row_lines(double start, const double* x, const double* dv, std::size_t count, int n);
    // One traced line l (0 <= l < n) of the region row, with weight 1, or 1/2 for each limit
    // of a line whose two limits differ: the region rows add_region_row() declined.
    void add_line(const LineProfile& line, int l, double weight);
    // One alternating shape's chains, added as soon as each passed its checks.
    class Tracks {
    public:
        Tracks(RegionRowSums& sums, int n, double outside) : sums_(sums), n_(n) {
            sums.add_start(outside);
        }
        void add(const double* xs, int first, int end, double lo, double hi, double dv) {
            sums_.add_change(xs, first, end < n_ ? end : n_, lo, hi, dv);
        }
        void discard() { sums_.cells_.clear(); }

    private:
        RegionRowSums& sums_;
        int n_;
    };

    // Pixel row r: background + the lower terms of `from_above` (region row r - 1) and the
    // upper terms of `here` (region row r), rounded once to float32; over the blocks neither
    // row flagged, a constant fill. Leaves `from_above` empty (RegionCells::clear()'s state),
    // each block zeroed as it is read.
    static void resolve_and_clear(RegionCells& from_above, const RegionCells& here,
                                  double background, float* out);

private:
    // add_row_spans() with kLines lines (0: n of them).
    template <int kLines>
    void add_spans(double start, const double* x, const double* dv, std::size_t count, int n);
    template <int kLines>
    class SpanBatch;  // add_spans()'s batches of changes (region_rows.cpp)
    // Every line starting at `start` instead of the background: (start - background) times
    // the lines' whole weights on every pixel (times `weight`, of line l alone when l >= 0).
    void add_start(double start, double weight = 1.0, int l = -1);
    // The terms of a change by dv in region R_{q-1} (left: T - F(x'), right: T - F(1 - x'),
    // total: the lines' whole weights, each a pair of the two rows' P) to its three cells.
    template <class P>
    static void add_region(RegionCells& cells, std::int64_t q, P left, P right, P total, double dv);
    template <class P>
    static void add_two_regions(RegionCells& cells, std::int64_t q, const P* left, const P* right,
                                const P* total, double dv);
    // One change by dv at x on line l alone.
    void add_line_change(int l, double x, double dv);
    // One change by dv with x on lines first..end - 1 (xs[l], end <= n), within [lo, hi] up to
    // rounding: its terms to both rows.
    void add_change(const double* xs, int first, int end, double lo, double hi, double dv);

    const RegionWeights& weights_;
    double background_;
    RegionCells& cells_;
};

}  // namespace aabench
