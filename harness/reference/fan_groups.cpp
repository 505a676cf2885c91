// Fans resolved by an angular sweep around their apex (fan_groups.h says why and what).
#include "harness/reference/fan_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>

#include "harness/reference/fan_envelope.h"
#include "methods/scan/kernel/visibility_rule.h"

namespace aabench {
namespace {

double cross(const Point& u, const Point& v) { return u.x * v.y - u.y * v.x; }
Point minus(const Point& a, const Point& b) { return {a.x - b.x, a.y - b.y}; }

// A triangle of a fan, its vertices from the apex in positive order: apex, p, q (q is
// counter-clockwise from p in the y-up sense, cross(p - apex, q - apex) > 0).
struct Member {
    int input = 0;
    Point p, q;
    double tolerance = 0.0;
};

// The outline of the union of the triangles taken so far, in polar form around the apex
// (fan_envelope.h): intervals of angle, each reached farthest by one member's chord.
using Interval = FanInterval;
constexpr int kNone = FanEnvelope::kNone;

// Angular buckets over the envelope, each with a lower bound on the envelope's distance from
// the apex over it: a triangle skips every bucket where its chord reaches no farther, without
// visiting the intervals there. This is where coverage saturates: once the later triangles
// cover the fan's middle, an earlier one only visits the buckets at its two outer vertices.
// Two levels: buckets in groups of 64, each group with the least bound of its buckets, so that a
// triangle skips whole groups first. The buckets scale with the fan: about one per two
// triangles (a few intervals each), a power of two from 64 (one group) to 2^16 (100,000
// triangles), so that a small fan does not set up and refresh a table made for a big one.
constexpr int kBucketsPerGroup = 64;
constexpr int kMaxBuckets = 65536;

int bucket_count(std::size_t triangles) {
    const std::size_t wanted = std::bit_ceil(std::max<std::size_t>(triangles, 1)) / 2;
    return static_cast<int>(std::clamp<std::size_t>(wanted, kBucketsPerGroup, kMaxBuckets));
}

class Sweep {
public:
    Sweep(const Point& apex, const std::vector<Member>& members, FanResult& out)
        : apex_(apex),
          members_(members),
          out_(out),
          grid_(bucket_count(members.size())),
          envelope_(grid_, Interval{std::numbers::pi,
                                    {apex.x - 1.0, apex.y},  // the ray at pi
                                    {apex.x - 1.0, apex.y},
                                    -1}),
          least_radius_(grid_.count, 0.0),
          bucket_ray_(grid_.count + 1),
          group_least_(grid_.count / kBucketsPerGroup, 0.0),
          dirty_(grid_.count, 0) {
        for (int b = 0; b <= grid_.count; ++b) {
            const double a = bucket_start(b);
            bucket_ray_[b] = {std::cos(a), std::sin(a)};
        }
    }

    // Takes member s (every later member already taken): adds its visible pieces.
    void take(int s) {
        const Member& m = members_[s];
        const double a_p = angle(m.p), a_q = angle(m.q);
        if (a_q >= a_p) {
            take_range(s, a_p, m.p, a_q, m.q);
        } else {  // the sector crosses the ray at angle pi
            const Point behind{apex_.x - 1.0, apex_.y};
            take_range(s, a_p, m.p, std::numbers::pi, behind);
            take_range(s, -std::numbers::pi, behind, a_q, m.q);
        }
    }

private:
    double angle(const Point& through) const {
        return std::atan2(through.y - apex_.y, through.x - apex_.x);
    }

    // Where member k's chord meets the ray through `through` (its own vertices exactly).
    Point hit(int k, const Point& through) const {
        const Member& m = members_[k];
        if (through == m.p) return m.p;
        if (through == m.q) return m.q;
        const Point d = minus(through, apex_), chord = minus(m.q, m.p);
        const double t = cross(chord, minus(m.p, apex_)) / cross(chord, d);
        return {apex_.x + t * d.x, apex_.y + t * d.y};
    }

    // Where member k's chord meets the ray apex + t d, as t.
    double t_of(int k, const Point& d) const {
        const Member& m = members_[k];
        const Point chord = minus(m.q, m.p);
        return cross(chord, minus(m.p, apex_)) / cross(chord, d);
    }

    // How much farther from the apex s's chord is than t's along the ray, in pixels.
    double beyond(int s, int t, const Point& through) const {
        const Point d = minus(through, apex_);
        return (t_of(s, d) - t_of(t, d)) * std::sqrt(d.x * d.x + d.y * d.y);
    }

    // The distance from the apex to member k's chord along the ray at angle a (t with a unit
    // direction); k < 0: none, 0.
    double radius(int k, double a) const {
        return k < 0 ? 0.0 : t_of(k, {std::cos(a), std::sin(a)});
    }

    // The least distance from the apex to k's chord over the angles [a0, a1] inside k's sector:
    // the chord's distance along a ray is convex in the angle, least at the foot of the
    // perpendicular from the apex (or at the nearer end).
    double least_radius(int k, double a0, double a1) const {
        if (k < 0) return 0.0;
        const Member& m = members_[k];
        const Point chord = minus(m.q, m.p);
        const double foot = std::atan2(-chord.x, chord.y);  // the normal, pointing away
        if (foot > a0 && foot < a1) {
            return std::abs(cross(chord, minus(m.p, apex_))) / std::hypot(chord.x, chord.y);
        }
        return std::min(radius(k, a0), radius(k, a1));
    }

    int bucket_of(double a) const { return grid_.of(a); }
    double bucket_start(int b) const { return grid_.start(b); }

    // The bucket's least envelope radius, again from the intervals over it.
    void refresh(int b) {
        const double b0 = bucket_start(b), b1 = b0 + grid_.angle;
        double least = std::numeric_limits<double>::infinity();
        for (int n = envelope_.locate(std::max(b0, -std::numbers::pi));
             n != kNone && envelope_[n].lo < b1; n = envelope_[n].next) {
            const FanEnvelope::Node& node = envelope_[n];
            const double c0 = std::max(node.lo, b0), c1 = std::min(node.in.hi, b1);
            least = std::min(least, least_radius(node.in.owner, c0, c1));
        }
        least_radius_[b] = least;
    }

    // Makes `a` an interval end (splitting the interval holding it).
    void split_at(double a, const Point& through) {
        const int n = envelope_.locate(a);
        FanEnvelope::Node& node = envelope_[n];
        if (node.lo == a || !(a < node.in.hi)) return;
        Interval upper = node.in;
        upper.lo_through = through;
        node.in.hi = a;
        node.in.hi_through = through;
        envelope_.insert_after(n, a, upper);
    }

    // Cleans the piece in a reused buffer and appends it to the flat result: no allocation
    // per piece once the buffers have grown.
    void add_piece(int s, std::initializer_list<Point> poly) {
        const double tolerance = members_[s].tolerance;
        scratch_.assign(poly);
        clean_contour(scratch_, tolerance);
        if (scratch_.size() < 3 || is_sliver(scratch_, tolerance)) return;
        out_.pieces.push_back(
            FanResult::Piece{members_[s].input, out_.vertices.size(), scratch_.size()});
        out_.vertices.insert(out_.vertices.end(), scratch_.begin(), scratch_.end());
    }

    void take_range(int s, double a0, const Point& through0, double a1, const Point& through1) {
        if (!(a0 < a1)) return;
        split_at(a0, through0);
        split_at(a1, through1);
        const double tolerance = members_[s].tolerance;
        changed_.clear();
        // The chord's distance over [angle of d0, angle of d1] is greatest at an end (it is
        // convex in the angle). Ends at bucket starts use the bucket's unit ray; s's own ends
        // their points (distances along unnormalised rays are scaled to pixels).
        auto reach = [&](const Point& d0, const Point& d1) {
            return std::max(t_of(s, d0) * std::sqrt(d0.x * d0.x + d0.y * d0.y),
                            t_of(s, d1) * std::sqrt(d1.x * d1.x + d1.y * d1.y));
        };
        const Point e0 = minus(through0, apex_), e1 = minus(through1, apex_);
        auto ray = [&](int b, bool own, const Point& e) { return own ? e : bucket_ray_[b]; };
        const int f0 = bucket_of(a0), f1 = bucket_of(a1);
        for (int g = f0 / kBucketsPerGroup; g <= f1 / kBucketsPerGroup; ++g) {
            const int b0 = std::max(f0, g * kBucketsPerGroup);
            const int b1 = std::min(f1, g * kBucketsPerGroup + kBucketsPerGroup - 1);
            const bool own0 = a0 > bucket_start(b0), own1 = a1 < bucket_start(b1 + 1);
            if (reach(ray(b0, own0, e0), ray(b1 + 1, own1, e1)) + tolerance <= group_least_[g]) {
                continue;
            }
            for (int b = b0; b <= b1; ++b) {
                const bool first = a0 > bucket_start(b), last = a1 < bucket_start(b + 1);
                const double c0 = first ? a0 : bucket_start(b);
                const double c1 = last ? a1 : bucket_start(b + 1);
                if (!(c0 < c1)) continue;
                if (reach(ray(b, first, e0), ray(b + 1, last, e1)) + tolerance <=
                    least_radius_[b]) {
                    continue;
                }
                take_intervals(s, envelope_.locate(c0), c1, a0, a1);
            }
        }
        std::sort(changed_.begin(), changed_.end());
        for (const int b : changed_) {
            refresh(b);
            dirty_[b] = 0;
        }
        int last_group = -1;
        for (const int b : changed_) {  // ascending: each group once
            const int g = b / kBucketsPerGroup;
            if (g == last_group) continue;
            last_group = g;
            const auto first = least_radius_.begin() + g * kBucketsPerGroup;
            group_least_[g] = *std::min_element(first, first + kBucketsPerGroup);
        }
        merge_around(a0, a1);
    }

    // Takes s over the intervals from `it` that start before c1 (and not before a0, nor at or
    // after a1: s's range).
    void take_intervals(int s, int it, double c1, double a0, double a1) {
        const double tolerance = members_[s].tolerance;
        if (envelope_[it].lo < a0) it = envelope_[it].next;
        auto mark = [&](const Interval& in, double lo) {
            touched_.push_back(lo);
            for (int b = bucket_of(lo); b <= bucket_of(in.hi); ++b) {
                if (!dirty_[b]) {
                    dirty_[b] = 1;
                    changed_.push_back(b);
                }
            }
        };
        while (it != kNone && envelope_[it].lo < a1 && envelope_[it].lo < c1) {
            // References into the envelope hold until split_at below (it may grow the array).
            const double lo = envelope_[it].lo;
            Interval& in = envelope_[it].in;
            const int t = in.owner;
            if (t < 0) {
                add_piece(s, {apex_, hit(s, in.lo_through), hit(s, in.hi_through)});
                in.owner = s;
                mark(in, lo);
                it = envelope_[it].next;
                continue;
            }
            const double d0 = beyond(s, t, in.lo_through), d1 = beyond(s, t, in.hi_through);
            const int side0 = d0 > tolerance ? 1 : (d0 < -tolerance ? -1 : 0);
            const int side1 = d1 > tolerance ? 1 : (d1 < -tolerance ? -1 : 0);
            if (std::max(side0, side1) <= 0) {  // s is nowhere beyond t's chord here
                it = envelope_[it].next;
                continue;
            }
            if (std::min(side0, side1) >= 0) {  // beyond (or level) all the way
                add_piece(s, {hit(t, in.lo_through), hit(s, in.lo_through), hit(s, in.hi_through),
                              hit(t, in.hi_through)});
                in.owner = s;
                mark(in, lo);
                it = envelope_[it].next;
                continue;
            }
            // The chords cross inside the interval (beyond the tolerance at both ends, with
            // opposite signs): split at the ray through their crossing.
            const Member& ms = members_[s];
            const Member& mt = members_[t];
            const Point cs = minus(ms.q, ms.p), ct = minus(mt.q, mt.p);
            const double u = cross(minus(mt.p, ms.p), ct) / cross(cs, ct);
            const Point x{ms.p.x + u * cs.x, ms.p.y + u * cs.y};
            const double ax = angle(x);
            if (!(ax > lo && ax < in.hi)) {  // rounding: a wedge a few ulps wide
                it = envelope_[it].next;
                continue;
            }
            const Point lo_through = in.lo_through, hi_through = in.hi_through;
            split_at(ax, x);  // `it` keeps the lower half
            const int upper = envelope_[it].next;
            if (side0 > 0) {
                add_piece(s, {hit(t, lo_through), hit(s, lo_through), x});
                envelope_[it].in.owner = s;
                mark(envelope_[it].in, envelope_[it].lo);
            } else {
                add_piece(s, {x, hit(s, hi_through), hit(t, hi_through)});
                envelope_[upper].in.owner = s;
                mark(envelope_[upper].in, envelope_[upper].lo);
            }
            it = envelope_[upper].next;
        }
    }

    // Joins the intervals at the ends of s's range and those s took with their neighbours of
    // the same owner: the envelope stays as small as the outline it describes, at a cost in the
    // intervals that changed.
    void merge_around(double a0, double a1) {
        touched_.push_back(a0);
        touched_.push_back(a1);
        for (const double key : touched_) {
            int it = envelope_.locate(key);
            if (envelope_[it].lo != key) continue;  // merged into its predecessor already
            const int prev = envelope_[it].prev;
            if (prev != kNone && envelope_[prev].in.owner == envelope_[it].in.owner) {
                envelope_[prev].in.hi = envelope_[it].in.hi;
                envelope_[prev].in.hi_through = envelope_[it].in.hi_through;
                envelope_.erase(it);
                it = prev;
            }
            for (int next = envelope_[it].next;
                 next != kNone && envelope_[next].in.owner == envelope_[it].in.owner;
                 next = envelope_[it].next) {
                envelope_[it].in.hi = envelope_[next].in.hi;
                envelope_[it].in.hi_through = envelope_[next].in.hi_through;
                envelope_.erase(next);
            }
        }
        touched_.clear();
    }

    Point apex_;
    const std::vector<Member>& members_;
    FanResult& out_;
    FanBuckets grid_;
    FanEnvelope envelope_;
    std::vector<double> least_radius_;
    std::vector<Point> bucket_ray_;  // unit, at each bucket's start
    std::vector<double> group_least_;
    std::vector<char> dirty_;
    Contour scratch_;              // the piece being cleaned (add_piece)
    std::vector<int> changed_;     // buckets whose envelope grew during one take_range
    std::vector<double> touched_;  // intervals (their starts) s took during one take_range
};

// The plane of `w` agrees with `ref` at the polygon's vertices to half a depth tie.
bool same_plane(const AffinePlane& w, const AffinePlane& ref, const Contour& poly) {
    for (const Point& v : poly) {
        if (!(std::abs(w.at(v.x, v.y) - ref.at(v.x, v.y)) <=
              0.5 * depth_tie_tolerance(w, ref, v.x, v.y))) {
            return false;
        }
    }
    return true;
}

}  // namespace

FanResult resolve_fans(const std::vector<FanInput>& inputs) {
    FanResult out;
    out.group.assign(inputs.size(), -1);
    // Shared vertices of triangles, counted; those of kMinFanTriangles or more are apexes.
    // Counted by sorting them (600,000 vertices of a 200,000-triangle soup: a tenth of the
    // time a hash map took).
    std::size_t triangles = 0;
    for (const FanInput& in : inputs) triangles += in.poly->size() == 3;
    if (triangles < static_cast<std::size_t>(kMinFanTriangles)) return out;
    std::vector<Point> corners;
    corners.reserve(3 * triangles);
    for (const FanInput& in : inputs) {
        if (in.poly->size() != 3) continue;
        for (const Point& v : *in.poly) corners.push_back(v);
    }
    // -0 and 0 are one vertex, as Point's == has it.
    std::sort(corners.begin(), corners.end(), [](const Point& a, const Point& b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    std::vector<std::pair<int, Point>> apexes;
    for (std::size_t i = 0; i < corners.size();) {
        std::size_t end = i + 1;
        while (end < corners.size() && corners[end] == corners[i]) ++end;
        if (end - i >= static_cast<std::size_t>(kMinFanTriangles)) {
            apexes.emplace_back(static_cast<int>(end - i), corners[i]);
        }
        i = end;
    }
    if (apexes.empty()) return out;
    std::sort(apexes.begin(), apexes.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first
                                  : (a.second.x != b.second.x ? a.second.x < b.second.x
                                                              : a.second.y < b.second.y);
    });
    for (const auto& entry : apexes) {
        // A named copy, not a structured binding: the lambda below captures it, which C++17
        // rules (clang-14) refuse for a binding.
        const Point apex = entry.second;
        std::vector<int> around;  // the free triangles with this vertex
        for (int k = 0; k < static_cast<int>(inputs.size()); ++k) {
            const Contour& poly = *inputs[k].poly;
            if (out.group[k] >= 0 || poly.size() != 3) continue;
            if (std::find(poly.begin(), poly.end(), apex) != poly.end()) around.push_back(k);
        }
        if (around.size() < static_cast<std::size_t>(kMinFanTriangles)) continue;
        // The fan's plane: of the first, middle and last triangle's planes, the one most of
        // them share (a few triangles off the plane do not split the fan).
        auto agreeing = [&](const AffinePlane& ref, std::vector<Member>* members) {
            std::size_t count = 0;
            for (const int k : around) {
                const Contour& poly = *inputs[k].poly;
                const std::optional<AffinePlane>& w = *inputs[k].inv_depth;
                if (w && !same_plane(*w, ref, poly)) continue;
                ++count;
                if (members) {
                    const auto i = static_cast<std::size_t>(
                        std::find(poly.begin(), poly.end(), apex) - poly.begin());
                    members->push_back(Member{k, poly[(i + 1) % 3], poly[(i + 2) % 3],
                                              inputs[k].side_tolerance});
                }
            }
            return count;
        };
        AffinePlane ref;
        if (*inputs[around[0]].inv_depth) {
            std::size_t best = 0;
            for (const int k : {around.front(), around[around.size() / 2], around.back()}) {
                const AffinePlane& candidate = **inputs[k].inv_depth;
                const std::size_t count = agreeing(candidate, nullptr);
                if (count > best) {
                    best = count;
                    ref = candidate;
                }
            }
        }
        std::vector<Member> members;
        agreeing(ref, &members);
        if (members.size() < static_cast<std::size_t>(kMinFanTriangles)) continue;
        const int group = static_cast<int>(out.fans++);
        for (const Member& m : members) out.group[m.input] = group;
        Sweep sweep(apex, members, out);
        // The later triangle is seen where two tie: the last one first.
        for (int s = static_cast<int>(members.size()) - 1; s >= 0; --s) sweep.take(s);
    }
    return out;
}

std::vector<std::size_t> fan_pieces_by_input(const FanResult& fans,
                                             std::vector<std::size_t>& first) {
    const std::size_t inputs = fans.group.size();
    first.assign(inputs + 1, 0);
    for (const FanResult::Piece& p : fans.pieces) ++first[p.input + 1];
    for (std::size_t k = 0; k < inputs; ++k) first[k + 1] += first[k];
    std::vector<std::size_t> order(fans.pieces.size());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t q = 0; q < fans.pieces.size(); ++q) order[fill[fans.pieces[q].input]++] = q;
    return order;
}

Scene one_fan_scene(const Scene& screen, const std::vector<int>& shapes, const FanResult& fans) {
    std::vector<std::size_t> first;
    const std::vector<std::size_t> order = fan_pieces_by_input(fans, first);
    Scene out = without_shapes(screen);
    out.shapes.reserve(fans.pieces.size());
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        if (first[k] == first[k + 1]) continue;
        const Shape proto = without_contours(screen.shapes[static_cast<std::size_t>(shapes[k])]);
        for (std::size_t q = first[k]; q < first[k + 1]; ++q) {
            const std::span<const Point> contour = fans.contour(fans.pieces[order[q]]);
            Shape& shape = out.shapes.emplace_back(proto);
            shape.contours.emplace_back(contour.begin(), contour.end());
        }
    }
    return out;
}

}  // namespace aabench
