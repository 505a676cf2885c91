#include "harness/world/plane_geometry.h"

#include <algorithm>
#include <cmath>

namespace aabench {

PlaneFrame PlaneFrame::from_normal(const glm::dvec3& origin, const glm::dvec3& unit_normal) {
    // u: the world axis least aligned with the normal, made perpendicular; any choice gives an
    // orthonormal frame, this one is never near-degenerate.
    const glm::dvec3 a = glm::abs(unit_normal);
    const glm::dvec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1, 0, 0)
                            : (a.y <= a.z)             ? glm::dvec3(0, 1, 0)
                                                       : glm::dvec3(0, 0, 1);
    const glm::dvec3 u = glm::normalize(axis - glm::dot(axis, unit_normal) * unit_normal);
    const glm::dvec3 v = glm::cross(unit_normal, u);
    return PlaneFrame{origin, u, v, unit_normal};
}

double twice_area(const Polygon2& poly) {
    if (poly.size() < 3) return 0.0;
    // About the first vertex: smaller terms than about the origin, less cancellation.
    double sum = 0.0;
    const glm::dvec2 o = poly[0];
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
        const glm::dvec2 a = poly[i] - o, b = poly[i + 1] - o;
        sum += a.x * b.y - a.y * b.x;
    }
    return sum;
}

Polygon2 clip_half_plane(const Polygon2& poly, double a, double b, double c) {
    Polygon2 out;
    const std::size_t n = poly.size();
    if (n == 0) return out;
    out.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2& p = poly[i];
        const glm::dvec2& q = poly[(i + 1) % n];
        const double fp = a * p.x + b * p.y + c, fq = a * q.x + b * q.y + c;
        if (fp >= 0.0) out.push_back(p);
        // A new vertex only where the edge strictly crosses the line: a vertex on the line is
        // kept once (above), never duplicated.
        if ((fp > 0.0 && fq < 0.0) || (fp < 0.0 && fq > 0.0)) {
            const double t = fp / (fp - fq);
            out.push_back(p + t * (q - p));
        }
    }
    if (out.size() < 3) out.clear();
    return out;
}

Polygon3 clip_half_space(const Polygon3& poly, const glm::dvec3& n, double c) {
    Polygon3 out;
    const std::size_t k = poly.size();
    if (k == 0) return out;
    out.reserve(k + 1);
    for (std::size_t i = 0; i < k; ++i) {
        const glm::dvec3& p = poly[i];
        const glm::dvec3& q = poly[(i + 1) % k];
        const double fp = glm::dot(n, p) + c, fq = glm::dot(n, q) + c;
        if (fp >= 0.0) out.push_back(p);
        if ((fp > 0.0 && fq < 0.0) || (fp < 0.0 && fq > 0.0)) {
            const double t = fp / (fp - fq);
            out.push_back(p + t * (q - p));
        }
    }
    if (out.size() < 3) out.clear();
    return out;
}

namespace {
// The line through a -> b as a*x + b*y + c >= 0 on its left (the inside of a
// counter-clockwise polygon).
void left_of(const glm::dvec2& p, const glm::dvec2& q, double& a, double& b, double& c) {
    a = -(q.y - p.y);
    b = q.x - p.x;
    c = -(a * p.x + b * p.y);
}

// Two consecutive vertices of a convex clipper closer than this share of its extent are one
// vertex. The edge between them has no direction worth the name: at length 0 its line is
// 0 >= 0, which keeps everything on both sides (split_by_convex then returned the whole
// polygon as inside and again as outside: the same cell lit and in shadow, drawn twice); a
// few ulps long, its line through the vertex points anywhere and cuts the inside by a line
// the clipper does not have. Both come from a shadow whose caster shares a vertex with its
// receiver (the vertex casts onto itself, and clipping to the receiver adds it again): mesh
// models, where every triangle touches its neighbours. Merging moves the clipper by at most
// this share, far below the slivers dropped as rounding (kSliverShare, stages.cpp: 1e-14 of
// the squared extent, i.e. 1e-7 of it across).
constexpr double kCoincidentShare = 1e-9;

// `convex` without its coincident vertices (the first of a run kept), or `convex` itself
// (the common case, no copy) when it has none; fewer than 3 left: empty.
const Polygon2& distinct_vertices(const Polygon2& convex, Polygon2& scratch) {
    const std::size_t k = convex.size();
    if (k < 3) return convex;
    glm::dvec2 lo = convex[0], hi = convex[0];
    for (const glm::dvec2& p : convex) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double tol = kCoincidentShare * std::max(hi.x - lo.x, hi.y - lo.y);
    const auto near = [&](const glm::dvec2& p, const glm::dvec2& q) {
        return std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol;
    };
    bool any = false;
    for (std::size_t i = 0; i < k && !any; ++i) any = near(convex[i], convex[(i + 1) % k]);
    if (!any) return convex;
    scratch.clear();
    for (const glm::dvec2& p : convex) {
        if (scratch.empty() || !near(scratch.back(), p)) scratch.push_back(p);
    }
    while (scratch.size() > 1 && near(scratch.back(), scratch.front())) scratch.pop_back();
    if (scratch.size() < 3) scratch.clear();
    return scratch;
}
}  // namespace

Polygon2 clip_convex(const Polygon2& poly, const Polygon2& clipper) {
    Polygon2 scratch;
    const Polygon2& convex = distinct_vertices(clipper, scratch);
    if (convex.size() < 3 && clipper.size() >= 3) return {};  // a clipper of no area
    Polygon2 cur = poly;
    const std::size_t k = convex.size();
    for (std::size_t i = 0; i < k && !cur.empty(); ++i) {
        double a, b, c;
        left_of(convex[i], convex[(i + 1) % k], a, b, c);
        cur = clip_half_plane(cur, a, b, c);
    }
    return cur;
}

Polygon2 split_by_convex(const Polygon2& poly, const Polygon2& convex, double min_twice_area,
                         std::vector<Polygon2>& outside) {
    Polygon2 scratch;
    const Polygon2& cutter = distinct_vertices(convex, scratch);
    if (cutter.size() < 3 && convex.size() >= 3) {  // no area: nothing inside, all outside
        if (std::abs(twice_area(poly)) > min_twice_area) outside.push_back(poly);
        return {};
    }
    Polygon2 cur = poly;
    const std::size_t k = cutter.size();
    for (std::size_t i = 0; i < k && !cur.empty(); ++i) {
        double a, b, c;
        left_of(cutter[i], cutter[(i + 1) % k], a, b, c);
        Polygon2 out_part = clip_half_plane(cur, -a, -b, -c);
        if (std::abs(twice_area(out_part)) > min_twice_area) outside.push_back(std::move(out_part));
        cur = clip_half_plane(cur, a, b, c);
    }
    if (std::abs(twice_area(cur)) <= min_twice_area) cur.clear();
    return cur;
}

Polygon2 counter_clockwise(Polygon2 poly) {
    if (twice_area(poly) < 0.0) std::reverse(poly.begin(), poly.end());
    return poly;
}

}  // namespace aabench
