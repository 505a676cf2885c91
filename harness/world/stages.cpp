#include "harness/world/stages.h"

#include "harness/reference/visibility.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <cmath>

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>

namespace aabench {

StageWorkCounts& work_counts() {
    thread_local StageWorkCounts counts;
    return counts;
}

StageWorkCounts stage_work_counts() {
    StageWorkCounts c = work_counts();
    c.visible_pieces = visible_pieces_calls();
    return c;
}

void reset_stage_work_counts() {
    work_counts() = StageWorkCounts();
    visible_pieces_calls() = 0;
}
namespace {

// Cells and shadow pieces whose area is below this share of their face's squared extent are
// rounding slivers (clipping a convex polygon moves a vertex by ~1e-16 of the coordinates):
// dropped. At the largest magnification a scene file allows a face to reach (a few thousand
// pixels across) a dropped sliver is < 1e-7 px^2, far below what any method resolves.
constexpr double kSliverShare = 1e-14;
// A caster vertex above a receiving plane by less than this share of the receiver's extent is
// on the plane (a box standing on the floor): it casts nothing. Same reasoning as plan.cpp.
constexpr double kOnPlaneShare = 1e-9;

double extent2(const Polygon2& poly) {
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec2& p : poly) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return poly.empty() ? 0.0 : glm::length(hi - lo);
}

glm::dvec2 area_centroid(const Polygon2& poly) {
    // Centroid of the triangle fan about the first vertex, weighted by signed areas.
    glm::dvec2 sum(0.0);
    double area = 0.0;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
        const glm::dvec2 a = poly[i] - poly[0], b = poly[i + 1] - poly[0];
        const double w = a.x * b.y - a.y * b.x;
        sum += w * (a + b) / 3.0;
        area += w;
    }
    return area != 0.0 ? poly[0] + sum / area : poly[0];
}

Polygon2 to_frame(const PlaneFrame& frame, const Polygon3& loop) {
    Polygon2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(frame.to_2d(p));
    return counter_clockwise(std::move(out));
}

// The shadow of `caster` (world polygon) on the plane of `receiver`, in its frame, or empty.
Polygon2 shadow_polygon(const Light& light, const Polygon3& caster, const WorldFace& receiver,
                        double on_plane) {
    const PlaneFrame& fr = receiver.frame;
    // Keep the part of the caster on the lit side of the receiving plane (h >= 0).
    Polygon3 part = clip_half_space(caster, fr.normal, -glm::dot(fr.normal, fr.origin));
    double h_max = 0.0;
    for (const glm::dvec3& p : part) h_max = std::max(h_max, fr.height(p));
    if (part.empty() || h_max <= on_plane) return {};
    Polygon2 shadow;
    if (light.type == LightType::kParallel) {
        const double nd = glm::dot(fr.normal, light.direction);  // < 0: the face is lit
        for (const glm::dvec3& p : part) shadow.push_back(fr.to_2d(p - fr.height(p) / nd * light.direction));
    } else {
        const double hl = fr.height(light.position);
        // Only points between the plane and the light cast; those at the light's height would
        // project to infinity, so the caster stops a hair below it.
        part = clip_half_space(part, -fr.normal, glm::dot(fr.normal, fr.origin) + hl * (1.0 - 1e-9));
        for (const glm::dvec3& p : part) {
            const double s = hl / (hl - fr.height(p));
            shadow.push_back(fr.to_2d(light.position + s * (p - light.position)));
        }
    }
    if (shadow.size() < 3) return {};
    return counter_clockwise(std::move(shadow));
}

// Does light l reach the face's lit side at all (n . l > 0)?
double light_cosine(const Light& light, const WorldFace& face, const glm::dvec3& at) {
    const glm::dvec3 to_light =
        light.type == LightType::kParallel ? -light.direction : light.position - at;
    return glm::dot(face.frame.normal, glm::normalize(to_light));
}

}  // namespace

Polygon2 face_outline(const WorldFace& face) { return to_frame(face.frame, face.loop); }

Polygon2 in_face_frame(const WorldFace& face, const Polygon3& loop) {
    return to_frame(face.frame, loop);
}

double sliver_twice_area(const Polygon2& outline) {
    return kSliverShare * std::pow(extent2(outline), 2);
}

ViewSetup ViewSetup::from(const Camera& camera, int width, int height) {
    ViewSetup v;
    v.view = glm::lookAt(camera.eye, camera.target, camera.up);
    v.focal_px = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_y_deg));
    v.width = width;
    v.height = height;
    v.near = camera.near;
    v.eye = camera.eye;
    v.target_distance = glm::length(camera.target - camera.eye);
    return v;
}

glm::dvec3 ViewSetup::to_view(const glm::dvec3& p) const {
    const glm::dvec4 q = view * glm::dvec4(p, 1.0);
    return {q.x, q.y, -q.z};
}

std::vector<WorldFace> collect_faces(const World& world, const ViewSetup& view) {
    ++work_counts().collect_faces;
    std::vector<WorldFace> faces;
    faces.reserve(world.face_count());
    int global = 0;
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
        const Object& obj = world.objects[o];
        for (std::size_t f = 0; f < obj.faces.size(); ++f, ++global) {
            WorldFace wf;
            wf.object = static_cast<int>(o);
            wf.index = static_cast<int>(f);
            wf.global = global;
            wf.reflectance = obj.faces[f].reflectance;
            wf.reflectance_rgb = obj.faces[f].reflectance_rgb;
            wf.closed = obj.closed;
            wf.loop.reserve(obj.faces[f].loop.size());
            for (int i : obj.faces[f].loop) wf.loop.push_back(obj.vertices[i]);
            glm::dvec3 n = face_normal(obj, obj.faces[f]);
            // Two-sided faces are seen from the eye's side: the normal is taken toward it.
            if (!obj.closed && glm::dot(n, view.eye - wf.loop[0]) < 0.0) n = -n;
            wf.frame = PlaneFrame::from_normal(wf.loop[0], n);
            faces.push_back(std::move(wf));
        }
    }
    return faces;
}

std::size_t cull_back_faces(std::vector<WorldFace>& faces, const ViewSetup& view) {
    ++work_counts().cull_back_faces;
    std::size_t culled = 0;
    for (WorldFace& f : faces) {
        // Seen edge-on or from behind: a closed surface's face turned away is hidden by the
        // object itself.
        if (f.closed && !(glm::dot(f.frame.normal, view.eye - f.frame.origin) > 0.0)) {
            f.visible = false;
            ++culled;
        }
    }
    return culled;
}

std::vector<std::vector<Cell>> initial_cells(const std::vector<WorldFace>& faces) {
    std::vector<std::vector<Cell>> cells(faces.size());
    for (std::size_t k = 0; k < faces.size(); ++k) {
        if (!faces[k].visible) continue;
        Cell c;
        c.loop = to_frame(faces[k].frame, faces[k].loop);
        c.take_reflectance(faces[k]);
        c.value = c.reflectance;
        c.value_rgb = c.reflectance_rgb;
        cells[k].push_back(std::move(c));
    }
    return cells;
}

Polygon2 shadow_on_face(const Light& light, const WorldFace& caster, const WorldFace& receiver) {
    ++work_counts().shadow_on_face;
    // A closed object's silhouette seen from the light is cast by its faces that face the
    // light; the others would add the same shadow again.
    if (caster.closed && !(light_cosine(light, caster, caster.frame.origin) > 0.0)) return {};
    const Polygon2 rec_loop = to_frame(receiver.frame, receiver.loop);
    const double ext = extent2(rec_loop);
    Polygon2 shadow = shadow_polygon(light, caster.loop, receiver, kOnPlaneShare * ext);
    if (shadow.empty()) return {};
    shadow = clip_convex(shadow, rec_loop);
    if (std::abs(twice_area(shadow)) <= kSliverShare * ext * ext) return {};
    return shadow;
}

bool face_is_lit(const Light& light, const WorldFace& face) {
    const Polygon2 loop = to_frame(face.frame, face.loop);
    const glm::dvec3 centre = face.frame.to_3d(area_centroid(loop));
    if (!(light_cosine(light, face, centre) > 0.0)) return false;
    return light.type == LightType::kParallel || face.frame.height(light.position) > 0.0;
}

namespace {

// Above this many faces the casters of a parallel light are found through a grid in the
// light's view instead of trying every face against every receiver (quadratic: a mesh of
// 70,000 triangles is 5e9 pairs). Below it (every built-in pattern but the mesh models) every
// pair is tried, as it always was.
constexpr std::size_t kGriddedShadowFaces = 4096;
// Boxes in the light's view grown by this share of the scene's extent before they are
// compared: a caster whose box misses the receiver's by more casts nothing onto it (its shadow
// is the light-view intersection of the two, empty), and the margin keeps rounding from
// deciding a pair the clipping would have found a sliver in.
constexpr double kGridMarginShare = 1e-9;

// The faces each receiver's shadow may come from under a parallel light: those whose boxes in
// the light's view (the plane across its direction) overlap the receiver's, in ascending order,
// so the shadows are found in the order trying every face gives them.
class LightViewGrid {
public:
    LightViewGrid(const Light& light, const std::vector<WorldFace>& faces) {
        const glm::dvec3 d = glm::normalize(light.direction);
        const glm::dvec3 helper =
            std::abs(d.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
        u_ = glm::normalize(glm::cross(d, helper));
        v_ = glm::cross(d, u_);
        boxes_.resize(faces.size());
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (std::size_t k = 0; k < faces.size(); ++k) {
            auto& [blo, bhi] = boxes_[k];
            blo = glm::dvec2(INFINITY);
            bhi = glm::dvec2(-INFINITY);
            for (const glm::dvec3& p : faces[k].loop) {
                const glm::dvec2 q(glm::dot(p, u_), glm::dot(p, v_));
                blo = glm::min(blo, q);
                bhi = glm::max(bhi, q);
            }
            lo = glm::min(lo, blo);
            hi = glm::max(hi, bhi);
        }
        const double margin = kGridMarginShare * glm::length(hi - lo);
        for (auto& [blo, bhi] : boxes_) {
            blo -= margin;
            bhi += margin;
        }
        lo_ = lo - margin;
        side_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(faces.size()))));
        step_ = (hi - lo + 2.0 * margin) / static_cast<double>(side_);
        cells_.resize(static_cast<std::size_t>(side_) * side_);
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const auto [i0, j0, i1, j1] = span(k);
            for (int j = j0; j <= j1; ++j) {
                for (int i = i0; i <= i1; ++i) cells_[index(i, j)].push_back(static_cast<int>(k));
            }
        }
    }

    // The faces whose boxes overlap face r's (r itself included), ascending.
    const std::vector<int>& candidates(std::size_t r) {
        found_.clear();
        const auto [i0, j0, i1, j1] = span(r);
        const auto& [rlo, rhi] = boxes_[r];
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                for (const int c : cells_[index(i, j)]) {
                    const auto& [clo, chi] = boxes_[c];
                    const bool apart =
                        chi.x < rlo.x || rhi.x < clo.x || chi.y < rlo.y || rhi.y < clo.y;
                    if (!apart) found_.push_back(c);
                }
            }
        }
        std::sort(found_.begin(), found_.end());
        found_.erase(std::unique(found_.begin(), found_.end()), found_.end());
        return found_;
    }

private:
    std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * side_ + i; }
    int cell_of(double value, double lo, double step) const {
        if (!(step > 0.0)) return 0;
        return std::clamp(static_cast<int>(std::floor((value - lo) / step)), 0, side_ - 1);
    }
    std::array<int, 4> span(std::size_t k) const {
        const auto& [blo, bhi] = boxes_[k];
        return {cell_of(blo.x, lo_.x, step_.x), cell_of(blo.y, lo_.y, step_.y),
                cell_of(bhi.x, lo_.x, step_.x), cell_of(bhi.y, lo_.y, step_.y)};
    }

    glm::dvec3 u_{0.0}, v_{0.0};
    std::vector<std::pair<glm::dvec2, glm::dvec2>> boxes_;
    glm::dvec2 lo_{0.0}, step_{0.0};
    int side_ = 1;
    std::vector<std::vector<int>> cells_;
    std::vector<int> found_;
};

}  // namespace

ShadowsByFace find_shadows(const World& world, const std::vector<WorldFace>& faces) {
    ++work_counts().cast_shadows;
    ShadowsByFace out(faces.size());
    for (std::size_t l = 0; l < world.lights.size() && l < kMaxShadowLights; ++l) {
        const Light& light = world.lights[l];
        if (!light.shadows) continue;
        std::optional<LightViewGrid> grid;
        if (light.type == LightType::kParallel && faces.size() > kGriddedShadowFaces) {
            grid.emplace(light, faces);
        }
        for (std::size_t r = 0; r < faces.size(); ++r) {
            const WorldFace& rec = faces[r];
            if (!rec.visible) continue;
            if (!face_is_lit(light, rec)) continue;  // unlit: nothing to darken
            const auto try_caster = [&](std::size_t c) {
                if (c == r) return;
                Polygon2 shadow = shadow_on_face(light, faces[c], rec);
                if (!shadow.empty()) out[r].push_back({l, std::move(shadow)});
            };
            if (grid) {
                for (const int c : grid->candidates(r)) try_caster(static_cast<std::size_t>(c));
            } else {
                for (std::size_t c = 0; c < faces.size(); ++c) try_caster(c);
            }
        }
    }
    return out;
}

std::size_t shadow_count(const ShadowsByFace& shadows) {
    std::size_t n = 0;
    for (const auto& on_face : shadows) n += on_face.size();
    return n;
}

std::size_t cast_shadows(const World& world, const std::vector<WorldFace>& faces,
                         std::vector<std::vector<Cell>>& cells) {
    const ShadowsByFace shadows = find_shadows(world, faces);
    cut_shadows(faces, shadows, cells);
    return shadow_count(shadows);
}

void shade(const World& world, const std::vector<WorldFace>& faces,
           std::vector<std::vector<Cell>>& cells) {
    ++work_counts().shade;
    shade_values(world, faces, cells);
}

namespace {

// One channel's illuminance of a cell: the ambient plus the share of each light it sees.
double cell_illuminance(double ambient, const std::vector<double>& share, std::uint64_t shadowed) {
    double illuminance = ambient;
    for (std::size_t l = 0; l < share.size(); ++l) {
        const bool blocked = l < kMaxShadowLights && (shadowed >> l & 1u);
        if (!blocked) illuminance += share[l];
    }
    return illuminance;
}

// reflectance x illuminance, refused when it overflows.
double shaded_value(const WorldFace& f, double reflectance, double illuminance) {
    const double value = reflectance * illuminance;
    if (!std::isfinite(value)) {
        throw InputError(fmt::format("shading: objects[{}].faces[{}]: the value {} x {} overflows",
                                     f.object, f.index, reflectance, illuminance));
    }
    return value;
}

}  // namespace

void shade_values(const World& world, const std::vector<WorldFace>& faces,
                  std::vector<std::vector<Cell>>& cells) {
    // A colour world: each channel as channel_world(world, c) computes it (its intensities,
    // ambient and reflectances), with the same operations in the same order.
    const int channels = world.is_colour() ? 3 : 1;
    std::array<std::vector<double>, 3> share;
    for (std::size_t k = 0; k < faces.size(); ++k) {
        if (cells[k].empty()) continue;
        const WorldFace& f = faces[k];
        const glm::dvec3 centre = f.frame.to_3d(area_centroid(to_frame(f.frame, f.loop)));
        // Flat shading (Nishita's I(S) per polygon): each light's share at the face's centroid.
        for (int ch = 0; ch < channels; ++ch) share[ch].assign(world.lights.size(), 0.0);
        for (std::size_t l = 0; l < world.lights.size(); ++l) {
            const Light& light = world.lights[l];
            double falloff = 1.0;
            if (light.type == LightType::kPoint) {
                const glm::dvec3 d = light.position - centre;
                falloff = 1.0 / glm::dot(d, d);
            }
            const double cosine = std::max(0.0, light_cosine(light, f, centre));
            for (int ch = 0; ch < channels; ++ch) {
                const double intensity = channels == 1
                                             ? light.intensity
                                             : channel_of(light.intensity, light.intensity_rgb, ch);
                share[ch][l] = intensity * cosine * falloff;
                // The reader refuses a point light at a centroid; this catches what it cannot
                // see (a centroid an ulp away in its own arithmetic, a World built in code).
                if (!std::isfinite(share[ch][l])) {
                    throw InputError(
                        fmt::format("shading: objects[{}].faces[{}]: lights[{}] gives a non-finite "
                                    "illuminance (distance {:g} from the face's centroid)",
                                    f.object, f.index, l, glm::length(light.position - centre)));
                }
            }
        }
        for (Cell& c : cells[k]) {
            if (channels == 1) {
                c.value = shaded_value(f, c.reflectance,
                                       cell_illuminance(world.ambient, share[0], c.shadowed));
                continue;
            }
            Rgb value{};
            for (int ch = 0; ch < 3; ++ch) {
                value[ch] =
                    shaded_value(f, channel_of(c.reflectance, c.reflectance_rgb, ch),
                                 cell_illuminance(channel_of(world.ambient, world.ambient_rgb, ch),
                                                  share[ch], c.shadowed));
            }
            c.value_rgb = value;
            c.value = luminance(value);
        }
    }
}

void unshaded(std::vector<std::vector<Cell>>& cells) {
    for (auto& face_cells : cells) {
        for (Cell& c : face_cells) {
            c.value = c.reflectance;
            c.value_rgb = c.reflectance_rgb;
        }
    }
}

AffinePlane inverse_depth_plane(const WorldFace& face, const ViewSetup& view) {
    // The face's plane in view space: n . X = c. A screen point (x, y) sees the ray
    // X = z_v * ((x - W/2) / f, -(y - H/2) / f, 1), so 1/z_v = n . ray / c: affine in (x, y).
    const glm::dvec3 o = view.to_view(face.frame.origin);
    // The normal turned by the view's rotation alone (z negated as in to_view): origin +
    // normal would lose the unit normal in the rounding of an origin far from 1 (at 1e100 the
    // two points are equal, and the plane 0/0).
    glm::dvec3 n = glm::dmat3(view.view) * face.frame.normal;
    n.z = -n.z;
    const double c = glm::dot(n, o);
    const double f = view.focal_px, cx = 0.5 * view.width, cy = 0.5 * view.height;
    return AffinePlane{(n.z - n.x * cx / f + n.y * cy / f) / c, n.x / (f * c), -n.y / (f * c)};
}

void project_cells(const std::vector<WorldFace>& faces,
                   const std::vector<std::vector<Cell>>& cells, const ViewSetup& view,
                   Scene& scene) {
    ++work_counts().project_cells;
    append_projected(faces, cells, view, scene);
}

void append_projected(const std::vector<WorldFace>& faces,
                      const std::vector<std::vector<Cell>>& cells, const ViewSetup& view,
                      Scene& scene) {
    const double f = view.focal_px, cx = 0.5 * view.width, cy = 0.5 * view.height;
    std::size_t cell_count = 0;
    for (const std::vector<Cell>& face_cells : cells) cell_count += face_cells.size();
    scene.shapes.reserve(scene.shapes.size() + cell_count);
    Polygon3 v;  // one buffer for every cell
    for (std::size_t k = 0; k < faces.size(); ++k) {
        if (cells[k].empty()) continue;
        const WorldFace& face = faces[k];
        const AffinePlane inv_depth = inverse_depth_plane(face, view);
        for (const Cell& c : cells[k]) {
            v.clear();
            bool behind_near = false;
            for (const glm::dvec2& q : c.loop) {
                v.push_back(view.to_view(face.frame.to_3d(q)));
                behind_near |= v.back().z - view.near < 0.0;
            }
            // z_v >= near. A cell wholly in front of at least 3 vertices comes out of the clip
            // as it went in (the clip empties one of fewer).
            if (behind_near || v.size() < 3) {
                v = clip_half_space(v, glm::dvec3(0, 0, 1), -view.near);
            }
            if (v.empty()) continue;
            Shape s;
            Contour contour;
            contour.reserve(v.size());
            for (const glm::dvec3& p : v) contour.push_back({cx + f * p.x / p.z, cy - f * p.y / p.z});
            s.contours.push_back(std::move(contour));
            s.value = c.value;
            s.rgb = c.value_rgb;
            s.inv_depth = inv_depth;
            s.face = face.global;
            s.role = c.role;
            scene.shapes.push_back(std::move(s));
        }
    }
}

std::vector<std::array<Point, 2>> shared_edges(const World& world,
                                               const std::vector<WorldFace>& faces,
                                               const ViewSetup& view) {
    std::vector<std::array<Point, 2>> out;
    const double f = view.focal_px, cx = 0.5 * view.width, cy = 0.5 * view.height;
    std::size_t first = 0;  // faces are object-major: faces[first..] belong to object o
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
        const Object& obj = world.objects[o];
        // Every edge of a visible face as (lower, higher) vertex index, sorted: an edge used by
        // exactly two visible faces is a run of two.
        std::vector<std::pair<int, int>> visible_uses;
        for (std::size_t k = 0; k < obj.faces.size(); ++k) {
            if (!faces[first + k].visible) continue;
            const std::vector<int>& loop = obj.faces[k].loop;
            for (std::size_t i = 0; i < loop.size(); ++i) {
                visible_uses.push_back(std::minmax(loop[i], loop[(i + 1) % loop.size()]));
            }
        }
        first += obj.faces.size();
        std::sort(visible_uses.begin(), visible_uses.end());
        for (std::size_t i = 0; i < visible_uses.size();) {
            std::size_t end = i + 1;
            while (end < visible_uses.size() && visible_uses[end] == visible_uses[i]) ++end;
            const std::pair<int, int> edge = visible_uses[i];
            const std::size_t uses = end - i;
            i = end;
            if (uses != 2) continue;
            glm::dvec3 a = view.to_view(obj.vertices[edge.first]);
            glm::dvec3 b = view.to_view(obj.vertices[edge.second]);
            if (a.z < view.near && b.z < view.near) continue;
            // Clip to z_v >= near, as the faces are.
            if (a.z < view.near) a += (view.near - a.z) / (b.z - a.z) * (b - a);
            if (b.z < view.near) b += (view.near - b.z) / (a.z - b.z) * (a - b);
            out.push_back({Point{cx + f * a.x / a.z, cy - f * a.y / a.z},
                           Point{cx + f * b.x / b.z, cy - f * b.y / b.z}});
        }
    }
    return out;
}

}  // namespace aabench
