// A uniform grid over the boxes' common extent. Each box is listed in every cell it touches;
// two boxes that overlap share at least one cell, and the pair is reported only from the cell
// holding the lower-left corner of their overlap (max of the two x0, max of the two y0),
// which lies in both boxes' cell ranges because the cell index is a monotone function of the
// coordinate. So every pair comes out exactly once, without a hash set.
//
// The cell side: the mean box side, so that a typical box touches about four cells and a
// typical cell holds a few boxes; but no smaller than the side that gives about four cells
// per box over the extent (scattered small boxes would otherwise ask for a huge, empty grid),
// and never more than kMaxCellsPerAxis per axis (a few huge boxes stretch the extent).
#include "harness/reference/overlap_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace aabench {
namespace {

// Caps the grid at 2^20 cells: 8 MiB of index vectors at most, whatever the extent.
constexpr int kMaxCellsPerAxis = 1024;

class CellAxis {
public:
    CellAxis(double lo, double hi, double side) : lo_(lo) {
        const double extent = hi - lo;
        const double want = side > 0.0 ? std::ceil(extent / side) : 1.0;
        cells_ = static_cast<int>(std::clamp(want, 1.0, static_cast<double>(kMaxCellsPerAxis)));
        side_ = extent > 0.0 ? extent / cells_ : 1.0;
    }
    int cells() const { return cells_; }
    int index(double v) const {
        const double c = std::floor((v - lo_) / side_);
        return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(cells_ - 1)));
    }

private:
    double lo_;
    double side_ = 1.0;
    int cells_ = 1;
};

// The grid of both functions below: the boxes' common extent cut into cells of the side the
// header comment gives. Where that would need more than kMaxCellsPerAxis cells on an axis, a
// few boxes far from the rest stretch the extent (a world's faces clipped just in front of the
// eye project to millions of pixels) and inflate the mean side, and the capped grid would put
// every other box into a few cells (a mesh with shadows at 48 x 48: 214,748 of 246,316 boxes
// in one cell, 2.4e10 box tests). The grid then covers the extent of the boxes without the
// kTrimShare of them that reach farthest out on each side, with cells of the median box side;
// the boxes beyond fall into the border cells, whose index is clamped. Any monotone clamped
// index keeps every pair once (header comment), so only the cost changes.
constexpr double kTrimShare = 0.01;

std::pair<CellAxis, CellAxis> grid_for(const std::vector<Bounds>& boxes) {
    const int n = static_cast<int>(boxes.size());
    Bounds all = boxes[0];
    double side_sum = 0.0;
    for (const Bounds& b : boxes) {
        all.x0 = std::min(all.x0, b.x0);
        all.y0 = std::min(all.y0, b.y0);
        all.x1 = std::max(all.x1, b.x1);
        all.y1 = std::max(all.y1, b.y1);
        side_sum += std::max(b.x1 - b.x0, b.y1 - b.y0);
    }
    const double extent_area = (all.x1 - all.x0) * (all.y1 - all.y0);
    const double side = std::max(side_sum / n, std::sqrt(extent_area / (4.0 * n)));
    const double most = kMaxCellsPerAxis * side;
    if (!(all.x1 - all.x0 > most || all.y1 - all.y0 > most)) {
        return {CellAxis(all.x0, all.x1, side), CellAxis(all.y0, all.y1, side)};
    }
    // The k-th smallest of each box's `lo` and the k-th largest of its `hi`, on each axis.
    const std::size_t k = static_cast<std::size_t>(kTrimShare * n);
    std::vector<double> v(boxes.size());
    auto kth = [&](auto of, std::size_t at) {
        for (std::size_t i = 0; i < boxes.size(); ++i) v[i] = of(boxes[i]);
        std::nth_element(v.begin(), v.begin() + at, v.end());
        return v[at];
    };
    const std::size_t last = boxes.size() - 1;
    const Bounds core{kth([](const Bounds& b) { return b.x0; }, k),
                      kth([](const Bounds& b) { return b.y0; }, k),
                      kth([](const Bounds& b) { return b.x1; }, last - k),
                      kth([](const Bounds& b) { return b.y1; }, last - k)};
    const double median_side =
        kth([](const Bounds& b) { return std::max(b.x1 - b.x0, b.y1 - b.y0); }, last / 2);
    const double core_area = std::max(0.0, (core.x1 - core.x0) * (core.y1 - core.y0));
    const double core_side = std::max(median_side, std::sqrt(core_area / (4.0 * n)));
    return {CellAxis(core.x0, std::max(core.x0, core.x1), core_side),
            CellAxis(core.y0, std::max(core.y0, core.y1), core_side)};
}

// Calls visit(a, b) for each overlapping pair, a < b, once; stops when visit returns false.
template <class Visit>
void for_box_pairs(const std::vector<Bounds>& boxes, Visit&& visit) {
    const int n = static_cast<int>(boxes.size());
    if (n < 2) return;
    // Named, not a structured binding: lambdas below capture the axes (C++17 forbids
    // capturing structured bindings, and clang refuses it).
    const std::pair<CellAxis, CellAxis> grid = grid_for(boxes);
    const CellAxis& ax = grid.first;
    const CellAxis& ay = grid.second;

    // Cell lists in compressed form: count, prefix-sum, fill.
    const std::size_t cell_count = static_cast<std::size_t>(ax.cells()) * ay.cells();
    std::vector<std::size_t> start(cell_count + 1, 0);
    auto for_cells = [&](const Bounds& b, auto&& fn) {
        const int i0 = ax.index(b.x0), i1 = ax.index(b.x1);
        const int j0 = ay.index(b.y0), j1 = ay.index(b.y1);
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) fn(static_cast<std::size_t>(j) * ax.cells() + i);
        }
    };
    for (const Bounds& b : boxes) for_cells(b, [&](std::size_t c) { ++start[c + 1]; });
    for (std::size_t c = 0; c < cell_count; ++c) start[c + 1] += start[c];
    std::vector<int> members(start[cell_count]);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (int k = 0; k < n; ++k) for_cells(boxes[k], [&](std::size_t c) { members[fill[c]++] = k; });
    // Each box's first cell column and row: the index is monotone, so the cell of the overlap's
    // corner, index(max(a.x0, b.x0)), is max(index(a.x0), index(b.x0)), two integers compared
    // instead of a division and a floor per axis for every overlapping pair.
    std::vector<std::pair<int, int>> first_cell(n);
    for (int k = 0; k < n; ++k) first_cell[k] = {ax.index(boxes[k].x0), ay.index(boxes[k].y0)};

    for (std::size_t c = 0; c < cell_count; ++c) {
        const int ci = static_cast<int>(c % ax.cells()), cj = static_cast<int>(c / ax.cells());
        for (std::size_t p = start[c]; p < start[c + 1]; ++p) {
            for (std::size_t q = p + 1; q < start[c + 1]; ++q) {
                const Bounds& a = boxes[members[p]];
                const Bounds& b = boxes[members[q]];
                if (!a.overlaps(b)) continue;
                const auto [ai, aj] = first_cell[members[p]];
                const auto [bi, bj] = first_cell[members[q]];
                if (std::max(ai, bi) != ci || std::max(aj, bj) != cj) {
                    continue;  // reported from the cell of the overlap's corner
                }
                // members ascend: p < q -> a < b
                if (!visit(members[p], members[q])) return;
            }
        }
    }
}

}  // namespace

std::vector<std::pair<int, int>> overlapping_box_pairs(const std::vector<Bounds>& boxes,
                                                       bool sorted) {
    std::vector<std::pair<int, int>> pairs;
    for_box_pairs(boxes, [&](int a, int b) {
        pairs.emplace_back(a, b);
        return true;
    });
    if (sorted) std::sort(pairs.begin(), pairs.end());
    return pairs;
}

double count_box_pairs(const std::vector<Bounds>& boxes, double stop_after) {
    double count = 0.0;
    for_box_pairs(boxes, [&](int, int) { return ++count <= stop_after; });
    return count;
}

double box_pair_bound(const std::vector<Bounds>& boxes) {
    if (boxes.size() < 2) return 0.0;
    const auto [ax, ay] = grid_for(boxes);
    std::vector<double> count(static_cast<std::size_t>(ax.cells()) * ay.cells(), 0.0);
    for (const Bounds& b : boxes) {
        for (int j = ay.index(b.y0); j <= ay.index(b.y1); ++j) {
            for (int i = ax.index(b.x0); i <= ax.index(b.x1); ++i) {
                count[static_cast<std::size_t>(j) * ax.cells() + i] += 1.0;
            }
        }
    }
    double pairs = 0.0;
    for (const double k : count) pairs += 0.5 * k * (k - 1.0);
    return pairs;
}

std::vector<int> z_order(const std::vector<Bounds>& boxes) {
    if (boxes.empty()) return {};
    Bounds all = boxes[0];
    for (const Bounds& b : boxes) {
        all.x0 = std::min(all.x0, b.x0);
        all.y0 = std::min(all.y0, b.y0);
        all.x1 = std::max(all.x1, b.x1);
        all.y1 = std::max(all.y1, b.y1);
    }
    constexpr double kCells = 65535.0;  // 16 bits per axis
    const double sx = all.x1 > all.x0 ? kCells / (all.x1 - all.x0) : 0.0;
    const double sy = all.y1 > all.y0 ? kCells / (all.y1 - all.y0) : 0.0;
    auto spread = [](std::uint32_t v) {  // bit k of v to bit 2k
        std::uint64_t x = v;
        x = (x | (x << 8)) & 0x00FF00FFu;
        x = (x | (x << 4)) & 0x0F0F0F0Fu;
        x = (x | (x << 2)) & 0x33333333u;
        x = (x | (x << 1)) & 0x55555555u;
        return x;
    };
    std::vector<std::pair<std::uint64_t, int>> keyed(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const Bounds& b = boxes[k];
        const auto qx = static_cast<std::uint32_t>(std::clamp(
            (0.5 * (b.x0 + b.x1) - all.x0) * sx, 0.0, kCells));
        const auto qy = static_cast<std::uint32_t>(std::clamp(
            (0.5 * (b.y0 + b.y1) - all.y0) * sy, 0.0, kCells));
        keyed[k] = {spread(qx) | (spread(qy) << 1), static_cast<int>(k)};
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<int> order(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) order[k] = keyed[k].second;
    return order;
}

}  // namespace aabench
