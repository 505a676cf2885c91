// The reflections stage (Saito & Takahashi 1990, §4, eq. 9): the optical-path depth
// image, by casting rays, so that the edge stage finds contours and creases inside reflections.
//
// eq. 9, with no transmission, d_r(n) the summed path length from the eye to the n-th surface
// and r(n) its `mirror` share:
//     z_r(n) = (1 - r(n)) f d / d_r(n) + r(n) z_r(n + 1),      pixel value z_r(1)
// (d = |target - eye|, f in px, as in the depth image's z_s = f d / z_v, docs/world.md). A ray
// that ends in the background adds 0 (infinitely far, as the depth image's background), so a
// mirror that reflects the background is not the background (the paper's reason for the form of
// eq. 9). The
// recursion stops at the first surface with r = 0 or after kMaxReflections mirrors; a surface
// reached at that bound is taken as opaque (weight r(1) ... r(n-1), not r(1) ... r(n)) so that the
// bound adds no step of its own.
//
// Path length, in view-depth units: a primary ray's direction is scaled so that its view-depth
// component is 1 (t = z_v at a hit), a reflected direction keeps that length, and d_r(n) is the
// summed ray parameter, i.e. the Euclidean path length times cos(theta) of the pixel's primary
// ray. On a surface seen directly z_r = f d / z_v: the optical-path image equals the depth image
// z_s wherever no mirror is seen, so the mirror adds lines only where it reflects something.
// (The paper's d_r is the Euclidean length; the two differ by a factor fixed per sample point.)
//
// Antialiasing (§3.5: "average the depth the way the shaded image averages colour"): each pixel
// is the mean of kOpticalSamplesPerSide^2 samples on a regular grid (a box filter over the
// pixel), the supersampling the `ssaa` method does for values.
//
// Rays are cast with Embree 3 (single precision: it says which face a ray meets); the distance
// to that face is then computed again in double from the face's plane, and reflections start
// from that double point. Embree does not decide exact visibility here: near an edge between two
// faces a float ray may pick the other face (tests/reflections_test.cpp measures how often).
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// Samples per pixel side: 3 x 3 = 9, as `ssaa:k=3` and the paper's method D (Nishita & Nakamae)
// take; the image's cost is 9 primary rays per pixel plus one per mirror bounce.
inline constexpr int kOpticalSamplesPerSide = 3;
// Mirrors followed per sample. Each bounce weighs r(n) of the last; at r = 0.8 four bounces weigh
// 0.41 and facing mirrors would otherwise recurse for ever. The `mirror` pattern needs one.
inline constexpr int kMaxReflections = 4;
// A reflected ray starts this share of the scene's extent past the mirror: its origin lies on the
// mirror's plane to double rounding, but Embree's float intersection can report the mirror itself
// within ~1e-7 of the coordinates' magnitude (float epsilon 1.2e-7, a few roundings); 1e-5 is
// 100 times that. What lies nearer than that before a mirror is not seen in it (a sliver; in the
// `mirror` pattern nothing comes within 0.1 of the extent of the mirror's face).
inline constexpr double kReflectedRayOffset = 1e-5;

struct RayHit {
    double t = std::numeric_limits<double>::infinity();  // ray parameter (distance / |dir|)
    int face = -1;  // global face index (Shape::face numbering), -1: the background
    double float_t = std::numeric_limits<double>::infinity();  // Embree's own (float) t
};

// Every face of the world (back faces too: a mirror shows them), triangulated as fans for
// Embree. Built once per scene; cast() may be called from several threads.
class RayCaster {
public:
    explicit RayCaster(const World& world);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // The nearest face the ray origin + t dir meets with t in (t_min, inf), t recomputed in
    // double on that face's plane.
    RayHit cast(const glm::dvec3& origin, const glm::dvec3& dir, double t_min) const;

    int face_count() const;
    double mirror(int face) const;             // the face's `mirror` share r
    glm::dvec3 normal(int face) const;         // unit normal of the face's plane
    double extent() const { return extent_; }  // the diagonal of the world's bounding box

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double extent_ = 0.0;
};

struct OpticalDepthStats {
    long long rays = 0;         // primary and reflected rays cast
    long long mirror_hits = 0;  // samples whose path met a mirror
};

// z_r(1) (eq. 9) of the ray through the screen point (x, y) in the pixel frame of a scene of
// the given size seen by `camera`.
double optical_path_sample(const RayCaster& caster, const Camera& camera, int width, int height,
                           double x, double y, OpticalDepthStats* stats = nullptr);

// The optical-path depth image of a 3-D scene: each pixel the mean of the
// kOpticalSamplesPerSide^2 samples (rows in parallel). Throws InputError for a 2-D scene.
Image optical_path_depth(const Scene& scene, OpticalDepthStats* stats = nullptr);

}  // namespace aabench
