#include "methods/scan/multiscan/scanline_visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace aabench {
namespace {

// Tie order of crossings at one x (Nishita & Nakamae §3.2), from which role lies in front:
// rights first, the frontmost role's first (shadow-right, pattern-right, face-right), then
// lefts, the rearmost role's first (face-left, pattern-left, shadow-left).
int right_rank(const RoleFront& front, ShapeRole role) {
    return 2 - front[static_cast<int>(role)];
}
int left_rank(const RoleFront& front, ShapeRole role) {
    return 3 + front[static_cast<int>(role)];
}

template <class T>
std::size_t held(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace

bool has_value_planes(const Scene& scene) {
    for (const Shape& s : scene.shapes) {
        if (s.value_plane) return true;
    }
    return false;
}

void ScanlineVisibility::reset(const Scene& scene, std::span<const double> curve_lines) {
    background_ = scene.background;
    priority_only_ = !has_depth_planes(scene);
    shapes_.clear();
    inv_depth_.clear();
    edges_.clear();
    endpoint_ys_.clear();
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        const Shape& shape = scene.shapes[s];
        if (!shape.inv_depth && !priority_only_) {
            throw std::invalid_argument(
                "ScanlineVisibility: some shapes have depth planes and some do not");
        }
        shapes_.push_back({shape.value_plane ? *shape.value_plane
                                             : AffinePlane{shape.value, 0.0, 0.0},
                           right_rank(role_front_, shape.role), left_rank(role_front_, shape.role),
                           shape.face, role_front_[static_cast<int>(shape.role)],
                           shape.value_plane.has_value()});
        if (!priority_only_) inv_depth_.push_back(*shape.inv_depth);
        append_shape_edges(shape, s, curve_lines, on_lines_, edges_, contour_index_);
    }
    // The edges enter the walk by their top y (the links the builder sets are not needed).
    by_top_.resize(edges_.size());
    for (std::uint32_t k = 0; k < by_top_.size(); ++k) by_top_[k] = k;
    std::sort(by_top_.begin(), by_top_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return edges_[a].y0 < edges_[b].y0; });
    for (const Edge& e : edges_) {
        endpoint_ys_.push_back(e.y0);
        endpoint_ys_.push_back(e.y1);
    }
    std::sort(endpoint_ys_.begin(), endpoint_ys_.end());
    endpoint_ys_.erase(std::unique(endpoint_ys_.begin(), endpoint_ys_.end()), endpoint_ys_.end());
    winding_.assign(shapes_.size(), 0);
    cursor_ = 0;
    active_.clear();
    last_y_ = -std::numeric_limits<double>::infinity();
}

void ScanlineVisibility::advance(double y) {
    if (y < last_y_) {  // lines must come in ascending y; restart the walk if not
        cursor_ = 0;
        active_.clear();
    }
    last_y_ = y;
    while (cursor_ < by_top_.size() && edges_[by_top_[cursor_]].y0 <= y) {
        active_.push_back(by_top_[cursor_++]);
    }
    // An edge stays while y <= y1: the limit from above still needs it on the line y == y1.
    std::size_t kept = 0;
    for (const std::uint32_t idx : active_) {
        if (edges_[idx].y1 >= y) active_[kept++] = idx;
    }
    active_.resize(kept);
}

bool ScanlineVisibility::nearer(int a, int b, double x, double y) const {
    // Two shapes on one face are coplanar (the same depth plane): the tie order of the roles
    // decides, the paper's "shadow, then pattern, in front" (§3.2).
    const ShapeInfo& sa = shapes_[a];
    const ShapeInfo& sb = shapes_[b];
    if (sa.face >= 0 && sa.face == sb.face && sa.front != sb.front) return sa.front > sb.front;
    // Otherwise the one rule (visibility_rule.h): depth with its tie, then the slope, then the
    // later shape; without depth planes, the later shape.
    return seen_over(a, b, inv_depth_, x, y);
}

void ScanlineVisibility::left(int shape, double x, double y) {
    if (current_ < 0) {
        current_ = shape;
    } else if (nearer(shape, current_, x, y)) {
        next_.push_back(current_);
        current_ = shape;
    } else {
        next_.push_back(shape);
    }
}

void ScanlineVisibility::right(int shape, double x, double y) {
    if (shape != current_) {  // a hidden shape ends: it leaves NEXT
        const auto it = std::find(next_.begin(), next_.end(), shape);
        if (it != next_.end()) {
            *it = next_.back();
            next_.pop_back();
        }
        return;
    }
    if (next_.empty()) {
        current_ = -1;
        return;
    }
    std::size_t best = 0;
    for (std::size_t k = 1; k < next_.size(); ++k) {
        if (nearer(next_[k], next_[best], x, y)) best = k;
    }
    current_ = next_[best];
    next_[best] = next_.back();
    next_.pop_back();
}

void ScanlineVisibility::apply_group(std::size_t first, std::size_t last, double x, double y) {
    touched_.clear();
    before_.clear();
    for (std::size_t k = first; k < last; ++k) {
        const int s = crossings_[k].shape;
        if (std::find(touched_.begin(), touched_.end(), s) == touched_.end()) {
            touched_.push_back(s);
            before_.push_back(winding_[s]);
        }
        winding_[s] += crossings_[k].winding;
    }
    events_.clear();
    for (std::size_t t = 0; t < touched_.size(); ++t) {
        const int s = touched_[t];
        const bool was_in = before_[t] != 0, is_in = winding_[s] != 0;
        if (was_in && !is_in) events_.push_back({shapes_[s].rank_right, s, false});
        if (!was_in && is_in) events_.push_back({shapes_[s].rank_left, s, true});
    }
    std::sort(events_.begin(), events_.end(), [](const Event& a, const Event& b) {
        return a.rank != b.rank ? a.rank < b.rank : a.shape < b.shape;
    });
    for (const Event& e : events_) {
        if (e.left) {
            left(e.shape, x, y);
        } else {
            right(e.shape, x, y);
        }
    }
}

void ScanlineVisibility::walk(double y, bool from_below, LineProfile& out) {
    crossings_.clear();
    for (const std::uint32_t idx : active_) {
        const Edge& e = edges_[idx];
        const bool hit = from_below ? (e.y0 <= y && y < e.y1) : (e.y0 < y && y <= e.y1);
        if (hit) crossings_.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(crossings_.begin(), crossings_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    current_ = -1;
    next_.clear();
    out.start = background_;
    out.changes.clear();
    out.affine = false;
    AffinePlane shown{background_, 0.0, 0.0};
    const std::size_t count = crossings_.size();
    for (std::size_t i = 0; i < count;) {
        const double x = crossings_[i].x;
        std::size_t j = i + 1;
        while (j < count && crossings_[j].x == x) ++j;
        apply_group(i, j, x, y);
        i = j;
        const AffinePlane& now =
            current_ < 0 ? AffinePlane{background_, 0.0, 0.0} : shapes_[current_].value;
        // Only visible changes are emitted (the paper's "visible crossings", §3.3).
        if (now == shown) continue;
        shown = now;
        out.changes.push_back({x, now.at(x, y), now.gx});
        if (now.gx != 0.0) out.affine = true;
    }
    // Closed contours cross a line with net winding 0, so every winding is back at 0 here;
    // reset anyway (cheap) so that no line can inherit another's state.
    for (const Crossing& c : crossings_) winding_[c.shape] = 0;
}

bool ScanlineVisibility::trace(double y, LineProfile& below, LineProfile& above) {
    advance(y);
    walk(y, true, below);
    const bool split = std::binary_search(endpoint_ys_.begin(), endpoint_ys_.end(), y);
    if (split) walk(y, false, above);
    return split;
}

std::size_t ScanlineVisibility::bytes_held() const {
    return held(shapes_) + held(inv_depth_) + held(edges_) + held(by_top_) + held(contour_index_) +
           held(active_) + held(endpoint_ys_) + held(crossings_) + held(winding_) + held(before_) +
           held(touched_) + held(events_) + held(next_);
}

}  // namespace aabench
