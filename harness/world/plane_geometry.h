// Convex polygons on a plane in 3-D: the one piece of geometry the world stages share.
//
// A face's plane gets an orthonormal 2-D basis (PlaneFrame); patterns, shadows and cells are
// convex polygons in those 2-D coordinates, cut by half-planes (Sutherland-Hodgman against
// one line at a time, which is exact up to one rounding per new vertex for convex input).
// Splitting a cell by a convex polygon K gives the part inside K and at most |K| convex parts
// outside it (one per edge of K): every piece stays convex, so the cells of a face are always
// disjoint convex polygons.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace aabench {

using Polygon2 = std::vector<glm::dvec2>;
using Polygon3 = std::vector<glm::dvec3>;

// An orthonormal frame on a plane: p = origin + a * u + b * v, normal = u x v.
struct PlaneFrame {
    glm::dvec3 origin;
    glm::dvec3 u, v, normal;

    static PlaneFrame from_normal(const glm::dvec3& origin, const glm::dvec3& unit_normal);
    glm::dvec2 to_2d(const glm::dvec3& p) const {
        const glm::dvec3 d = p - origin;
        return {glm::dot(d, u), glm::dot(d, v)};
    }
    glm::dvec3 to_3d(const glm::dvec2& q) const { return origin + q.x * u + q.y * v; }
    double height(const glm::dvec3& p) const { return glm::dot(p - origin, normal); }
};

// Twice the signed area (counter-clockwise positive in the frame's (u, v) axes).
double twice_area(const Polygon2& poly);

// The part of `poly` where a*x + b*y + c >= 0 (a half-plane through its boundary line).
Polygon2 clip_half_plane(const Polygon2& poly, double a, double b, double c);

// The same in 3-D: the part of a planar polygon where dot(n, p) + c >= 0.
Polygon3 clip_half_space(const Polygon3& poly, const glm::dvec3& n, double c);

// poly ∩ convex; `convex` must be counter-clockwise (positive twice_area). Consecutive
// vertices of `convex` within 1e-9 of its extent count as one (plane_geometry.cpp says why).
Polygon2 clip_convex(const Polygon2& poly, const Polygon2& convex);

// Splits `poly` by the counter-clockwise convex polygon `cutter`: returns the part inside
// (possibly empty) and appends the parts outside to `outside`. Parts of area below
// `min_twice_area` are dropped (slivers from rounding; the caller names the bound). The
// cutter's coincident vertices count as one, as in clip_convex.
Polygon2 split_by_convex(const Polygon2& poly, const Polygon2& cutter, double min_twice_area,
                         std::vector<Polygon2>& outside);

// Counter-clockwise copy (reversed when the area is negative).
Polygon2 counter_clockwise(Polygon2 poly);

}  // namespace aabench
