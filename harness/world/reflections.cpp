// The optical-path depth of eq. 9 by ray casting (reflections.h has the definitions).
//
// Embree 3 holds every face of the world as a fan of triangles (faces are planar and convex, so
// the fan covers the face exactly); a hit names a triangle, the triangle names its face, and the
// ray parameter is then recomputed in double against the face's plane: what Embree decides is
// which face, never where on the ray. Faces are two-sided here (no culling): a mirror shows the
// back of what stands before it.
#include "harness/world/reflections.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "harness/world/stages.h"

namespace aabench {
namespace {

// Embree holds positions in float and takes a ray only within +-1.844e18 (its FLT_LARGE; past
// it an assertion stops the process): the world a mirror is traced in must lie within 1e18 of
// the origin, eye included, a narrower range than the 1e100 the other stages compute exactly.
constexpr double kMaxRayCoordinate = 1e18;  // spelled out in the messages below

bool within_ray_range(const glm::dvec3& v) {
    return std::abs(v.x) <= kMaxRayCoordinate && std::abs(v.y) <= kMaxRayCoordinate &&
           std::abs(v.z) <= kMaxRayCoordinate;
}

}  // namespace

struct RayCaster::Impl {
    struct FacePlane {
        glm::dvec3 normal;  // unit
        glm::dvec3 point;   // a vertex of the face
        double mirror = 0.0;
    };
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<float> vertices;     // x, y, z, pad: Embree reads 16 bytes per vertex
    std::vector<unsigned> indices;   // three per triangle
    std::vector<int> triangle_face;  // triangle -> global face index
    std::vector<FacePlane> faces;
};

RayCaster::RayCaster(const World& world) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (std::size_t object = 0; object < world.objects.size(); ++object) {
        const Object& o = world.objects[object];
        const unsigned base = static_cast<unsigned>(m.vertices.size() / 4);
        for (std::size_t k = 0; k < o.vertices.size(); ++k) {
            const glm::dvec3& v = o.vertices[k];
            if (!within_ray_range(v)) {
                throw InputError(fmt::format(
                    "reflections: objects[{}].vertices[{}] lies beyond 1e18, the range in which "
                    "mirrors are traced (Embree works in float; docs/world.md, \"No silent "
                    "non-finite value\")",
                    object, k));
            }
            m.vertices.insert(m.vertices.end(), {static_cast<float>(v.x), static_cast<float>(v.y),
                                                 static_cast<float>(v.z), 0.0f});
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        for (const Face& f : o.faces) {
            const int face = static_cast<int>(m.faces.size());
            m.faces.push_back({face_normal(o, f), o.vertices[f.loop[0]], f.mirror});
            for (std::size_t k = 1; k + 1 < f.loop.size(); ++k) {
                m.indices.insert(m.indices.end(), {base + static_cast<unsigned>(f.loop[0]),
                                                   base + static_cast<unsigned>(f.loop[k]),
                                                   base + static_cast<unsigned>(f.loop[k + 1])});
                m.triangle_face.push_back(face);
            }
        }
    }
    extent_ = m.faces.empty() ? 1.0 : glm::length(hi - lo);
    m.device = rtcNewDevice(nullptr);
    if (!m.device) {
        throw std::runtime_error(fmt::format("reflections: Embree device not created (error {})",
                                             static_cast<int>(rtcGetDeviceError(nullptr))));
    }
    m.scene = rtcNewScene(m.device);
    if (!m.triangle_face.empty()) {
        RTCGeometry geometry = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   m.vertices.data(), 0, 4 * sizeof(float), m.vertices.size() / 4);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   m.indices.data(), 0, 3 * sizeof(unsigned),
                                   m.triangle_face.size());
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(m.scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(m.scene);
    const RTCError error = rtcGetDeviceError(m.device);
    if (error != RTC_ERROR_NONE) {
        rtcReleaseScene(m.scene);
        rtcReleaseDevice(m.device);
        throw std::runtime_error(
            fmt::format("reflections: Embree scene of {} triangles not built (error {})",
                        m.triangle_face.size(), static_cast<int>(error)));
    }
}

RayCaster::~RayCaster() {
    rtcReleaseScene(impl_->scene);
    rtcReleaseDevice(impl_->device);
}

int RayCaster::face_count() const { return static_cast<int>(impl_->faces.size()); }
double RayCaster::mirror(int face) const { return impl_->faces[face].mirror; }
glm::dvec3 RayCaster::normal(int face) const { return impl_->faces[face].normal; }

RayHit RayCaster::cast(const glm::dvec3& origin, const glm::dvec3& dir, double t_min) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (!within_ray_range(origin) || !(std::abs(t_min) <= kMaxRayCoordinate)) {
        throw InputError(fmt::format(
            "reflections: a ray from ({:g}, {:g}, {:g}) starts beyond 1e18, the range in which "
            "mirrors are traced (Embree works in float; docs/world.md, \"No silent non-finite "
            "value\")",
            origin.x, origin.y, origin.z));
    }
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(origin.x);
    rh.ray.org_y = static_cast<float>(origin.y);
    rh.ray.org_z = static_cast<float>(origin.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = static_cast<float>(t_min);
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rh);
    RayHit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.face = impl_->triangle_face[rh.hit.primID];
    hit.float_t = rh.ray.tfar;
    const Impl::FacePlane& plane = impl_->faces[hit.face];
    const double along = glm::dot(plane.normal, dir);
    const double t = along != 0.0 ? glm::dot(plane.normal, plane.point - origin) / along : 0.0;
    // The plane's t is the exact one for that face; a ray parallel to the plane (to rounding)
    // or a recomputed t outside the searched interval keeps Embree's float t.
    hit.t = std::isfinite(t) && t > t_min ? t : static_cast<double>(rh.ray.tfar);
    return hit;
}

double optical_path_sample(const RayCaster& caster, const Camera& camera, int width, int height,
                           double x, double y, OpticalDepthStats* stats) {
    const glm::dmat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
    const double focal_px = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_y_deg));
    // glm::lookAt's rows are the camera's right, up and backward axes in world space.
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    const glm::dvec3 forward(-view[0][2], -view[1][2], -view[2][2]);
    // View-depth component 1: a hit's t is its z_v (docs/world.md: x = W/2 + f x_v / z_v).
    glm::dvec3 dir =
        forward + ((x - 0.5 * width) / focal_px) * right - ((y - 0.5 * height) / focal_px) * up;
    glm::dvec3 origin = camera.eye;
    double t_min = camera.near;  // the pipeline clips geometry nearer than `near` (view depth)
    // The depth image's scale: z_s = f d / z_v.
    const double depth_scale = ViewSetup::from(camera, width, height).depth_scale();
    double weight = 1.0, z = 0.0, path = 0.0;
    for (int bounce = 0;; ++bounce) {
        const RayHit hit = caster.cast(origin, dir, t_min);
        if (stats) ++stats->rays;
        if (hit.face < 0) break;  // the background: 0, infinitely far
        path += hit.t;
        const double r = caster.mirror(hit.face);
        if (!(r > 0.0) || bounce == kMaxReflections) {
            z += weight * depth_scale / path;
            break;
        }
        if (stats && bounce == 0) ++stats->mirror_hits;
        z += weight * (1.0 - r) * depth_scale / path;  // eq. 9
        weight *= r;
        origin += hit.t * dir;
        const glm::dvec3 n = caster.normal(hit.face);
        dir -= 2.0 * glm::dot(dir, n) * n;  // the same length: t keeps its unit
        t_min = kReflectedRayOffset * caster.extent() / glm::length(dir);
    }
    return z;
}

Image optical_path_depth(const Scene& scene, OpticalDepthStats* stats) {
    ++work_counts().optical_path_depth;
    if (!scene.world) throw InputError("reflections: a 2-D scene has no optical path");
    const RayCaster caster(*scene.world);
    const int w = scene.width, h = scene.height;
    Image image(w, h);
    std::atomic<long long> rays{0}, mirror_hits{0};
    constexpr int n = kOpticalSamplesPerSide;
    tbb::parallel_for(0, h, [&](int j) {
        OpticalDepthStats row;
        for (int i = 0; i < w; ++i) {
            double sum = 0.0;
            for (int b = 0; b < n; ++b) {
                for (int a = 0; a < n; ++a) {
                    sum += optical_path_sample(caster, scene.world->camera, w, h, i + (a + 0.5) / n,
                                               j + (b + 0.5) / n, &row);
                }
            }
            image.at(i, j) = static_cast<float>(sum / (n * n));
        }
        rays += row.rays;
        mirror_hits += row.mirror_hits;
    });
    if (stats) {
        stats->rays = rays;
        stats->mirror_hits = mirror_hits;
    }
    return image;
}

}  // namespace aabench
