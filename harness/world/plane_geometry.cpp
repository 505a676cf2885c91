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
}  // namespace

Polygon2 clip_convex(const Polygon2& poly, const Polygon2& convex) {
    Polygon2 cur = poly;
    const std::size_t k = convex.size();
    for (std::size_t i = 0; i < k && !cur.empty(); ++i) {
        double a, b, c;
        left_of(convex[i], convex[(i + 1) % k], a, b, c);
        cur = clip_half_plane(cur, a, b, c);
    }
    return cur;
}

Polygon2 split_by_convex(const Polygon2& poly, const Polygon2& cutter, double min_twice_area,
                         std::vector<Polygon2>& outside) {
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
