#include "methods/scan/kernel/edge_sweep.h"

#include <algorithm>
#include <cmath>

namespace aabench {

void EdgeSweep::reset(EdgeTable& table) {
    table_ = &table;
    heads_.clear();
    head_keys_.clear();
    const auto& edges = table.edges();
    for (std::uint32_t idx = 0; idx < edges.size(); ++idx) {
        if (edges[idx].above < 0) head_keys_.emplace_back(edges[idx].y0, idx);
    }
    // Every edge lies on exactly one chain (links run strictly downwards, so there is no
    // cycle), and each chain enters the sweep once, at its head's y0. Ties broken by index so
    // that the order, like everything else here, does not depend on the sort's algorithm.
    std::sort(head_keys_.begin(), head_keys_.end());
    for (const auto& key : head_keys_) heads_.push_back(key.second);
    next_head_ = 0;
    active_.clear();
    y_ = -std::numeric_limits<double>::infinity();
    endpoint_on_line_ = false;
    ended_.clear();
    ended_known_ = false;
    seeks_ = advances_ = 0;
}

std::span<const Crossing> EdgeSweep::crossings(double y) {
    if (!(y >= 0.0 && y < table_->height())) {  // no row: the contract says never
        return {};
    }
    if (y == y_) return active_;  // the same line again: nothing moved
    // y_ is -infinity before the first line (advanced to from the top), so `!(y >= y_)` is a
    // line above the last one.
    if (!(y >= y_)) {
        seek(y);
    } else {
        advance(y);
    }
    y_ = y;
    return active_;
}

double EdgeSweep::next_entry() const {
    return next_head_ < heads_.size() ? table_->edges()[heads_[next_head_]].y0
                                      : std::numeric_limits<double>::infinity();
}

bool EdgeSweep::can_take(double y, std::size_t entered) const {
    const std::size_t next = next_head_ + entered;
    return y > y_ && y < table_->height() &&
           !(next < heads_.size() && !(table_->edges()[heads_[next]].y0 > y));
}

void EdgeSweep::took(double y, std::size_t entered) {
    next_head_ += entered;
    y_ = y;
    endpoint_on_line_ = false;
    ended_known_ = false;
    ++advances_;
}

bool EdgeSweep::adopt(double y, std::span<const Crossing> list, std::size_t entered) {
    if (!can_take(y, entered)) return false;
    // Copied, not swapped: swapping would trade the two buffers' capacities row by row, and a
    // warm render could still allocate.
    active_.assign(list.begin(), list.end());
    took(y, entered);
    return true;
}

bool EdgeSweep::move_straight(double y, const double* x) {
    if (!can_take(y, 0)) return false;
    for (std::size_t k = 0; k < active_.size(); ++k) active_[k].x = x[k];
    took(y, 0);
    return true;
}

std::span<const std::uint32_t> EdgeSweep::entering_before(double y) const {
    const auto& edges = table_->edges();
    std::size_t end = next_head_;
    while (end < heads_.size() && edges[heads_[end]].y0 < y) ++end;
    return std::span<const std::uint32_t>(heads_).subspan(next_head_, end - next_head_);
}

Crossing EdgeSweep::entry(std::uint32_t edge, double y) const {
    const Edge& e = table_->edges()[edge];
    return {e.x_at(y), e.winding, e.shape, edge};
}

void EdgeSweep::seek(double y) {
    ++seeks_;
    ended_known_ = false;
    table_->build_rows();
    active_.clear();
    const int height = table_->height();
    const auto& edges = table_->edges();
    const int r = std::min(static_cast<int>(std::floor(y)), height - 1);
    endpoint_on_line_ = false;
    // The line's row holds every edge it meets (crossings_at's argument), and every edge with
    // an endpoint on it except, on an integer y, those ending on it: they are in the row above.
    for (const std::uint32_t idx : table_->row(r)) {
        const Edge& e = edges[idx];
        if (e.y0 == y || e.y1 == y) endpoint_on_line_ = true;
        if (e.y0 <= y && y < e.y1) active_.push_back(entry(idx, y));
    }
    if (r > 0 && y == r) {
        for (const std::uint32_t idx : table_->row(r - 1)) {
            if (edges[idx].y1 == y) endpoint_on_line_ = true;
        }
    }
    std::sort(active_.begin(), active_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    // Chains whose head lies on or above the line are in the list already (or ended).
    const auto first_below =
        std::upper_bound(heads_.begin(), heads_.end(), y,
                         [&](double v, std::uint32_t idx) { return v < edges[idx].y0; });
    next_head_ = static_cast<std::size_t>(first_below - heads_.begin());
}

int EdgeSweep::follow(std::uint32_t edge, double y) {
    const auto& edges = table_->edges();
    for (;;) {
        const Edge& e = edges[edge];
        if (e.y0 == y || e.y1 == y) endpoint_on_line_ = true;
        if (y < e.y1) return static_cast<int>(edge);
        // The next edge of the chain starts where this one ends (its y0 == e.y1 <= y).
        if (e.below < 0) {
            if (e.y1 == y) ended_.push_back(edge);
            return -1;
        }
        edge = static_cast<std::uint32_t>(e.below);
    }
}

void EdgeSweep::advance(double y) {
    ++advances_;
    endpoint_on_line_ = false;
    ended_.clear();
    ended_known_ = true;
    const auto& edges = table_->edges();
    // Carry each entry over: the same edge if the line still meets it (y0 <= y_ < y, so only
    // its end can lie on y, and it does not: y < y1), else the edge of its chain that the line
    // meets, else the chain has ended and the entry goes.
    std::size_t kept = 0;
    bool in_order = true;  // checked here, while x is at hand: most lines need no sorting
    double last_x = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < active_.size(); ++k) {
        std::uint32_t idx = active_[k].edge;
        if (!(y < edges[idx].y1)) {
            const int next = follow(idx, y);
            if (next < 0) continue;
            idx = static_cast<std::uint32_t>(next);  // winding and shape: the chain's
        }
        // Field by field: copying the whole entry made GCC store x to the stack and reload
        // it as part of a 16-byte move, a store-forwarding stall that was two thirds of
        // this loop.
        Crossing& to = active_[kept++];
        to.winding = active_[k].winding;
        to.shape = active_[k].shape;
        to.edge = idx;
        to.x = edges[idx].x_at(y);
        in_order = in_order && !(to.x < last_x);
        last_x = to.x;
    }
    active_.resize(kept);
    if (!in_order) sort_active();
    // Chains starting between the last line and this one (inclusive) enter; a chain lying
    // wholly between the two lines never does, but its endpoints are still noted.
    pending_.clear();
    while (next_head_ < heads_.size() && edges[heads_[next_head_]].y0 <= y) {
        const int idx = follow(heads_[next_head_++], y);
        if (idx >= 0) pending_.push_back(entry(static_cast<std::uint32_t>(idx), y));
    }
    if (!pending_.empty()) merge_pending();
}

void EdgeSweep::sort_active() {
    // Insertion sort: the list was sorted on the last line, and only edges that crossed
    // between the lines are out of order. A scene whose edges cross a great deal (the star's
    // centre, random polygons) would make it quadratic; past a budget of moves linear in the
    // list, the rest is left to std::sort.
    Crossing* a = active_.data();
    const std::size_t n = active_.size();
    const std::size_t budget = 8 * n + 64;
    std::size_t moves = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (!(a[i].x < a[i - 1].x)) continue;
        const Crossing v = a[i];
        std::size_t j = i;
        while (j > 0 && v.x < a[j - 1].x) {
            a[j] = a[j - 1];
            --j;
        }
        a[j] = v;
        moves += i - j;
        if (moves > budget) {
            std::sort(active_.begin(), active_.end(),
                      [](const Crossing& p, const Crossing& q) { return p.x < q.x; });
            return;
        }
    }
}

void EdgeSweep::merge_pending() {
    std::sort(pending_.begin(), pending_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    // Merge from the back into the grown list: no scratch, and no allocation once the list
    // has been this long before.
    const std::size_t n = active_.size(), p = pending_.size();
    active_.resize(n + p);
    std::size_t i = n, j = p, k = n + p;
    while (j > 0) {
        if (i > 0 && pending_[j - 1].x < active_[i - 1].x) {
            active_[--k] = active_[--i];
        } else {
            active_[--k] = pending_[--j];
        }
    }
}

bool EdgeSweep::ties() const {
    for (std::size_t k = 1; k < active_.size(); ++k) {
        if (active_[k].x == active_[k - 1].x) return true;
    }
    return false;
}

}  // namespace aabench
