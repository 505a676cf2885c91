// The world stages: pure functions that turn a World into a ScreenScene, each doing one
// effect (docs/world.md, "The stages"). harness/world/frame.h calls them in order,
// only those the plan keeps, and records what each costs. The cutting of cells
// (cut_patterns, cut_shadows, split_cells) is in cell_cutting.cpp, the rest in stages.cpp.
//
//   collect_faces   every face in world space with its plane (the projection stage's first half)
//   cull_back_faces closed objects' faces turned away from the eye are dropped
//   cut_patterns    patterns clipped to their faces; faces cut into disjoint convex cells
//   find_shadows    for each light with shadows, the exact shadow of every caster on every lit
//                   face (polygons in the receiver's frame)
//   cut_shadows     cells cut again by those shadows and marked with the lights they do not see
//                   (cast_shadows: both)
//   shade           value = reflectance x (ambient + the lights each cell sees), per channel in
//                   a colour world
//   project_cells   near-plane clipping and perspective; each cell a 2-D shape with its face's
//                   depth plane (the projection stage's second half)
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "harness/world/plane_geometry.h"
#include "patterns/scene/scene.h"

namespace aabench {

// How many times each stage's work ran on this thread (the counters sit in the functions that
// do the work, so a planner or caller that repeats a stage is seen). Tests reset and read them.
struct StageWorkCounts {
    long long collect_faces = 0;
    long long cull_back_faces = 0;
    long long cut_patterns = 0;
    long long cast_shadows = 0;
    long long shadow_on_face = 0;  // one clipping of a caster onto a receiver
    long long shade = 0;
    long long project_cells = 0;
    long long build_overlay = 0;  // the scanline methods' input (harness/world/overlay.h)
    long long visible_pieces = 0;
    long long optical_path_depth = 0;
};
StageWorkCounts stage_work_counts();
// The counters themselves (the stage functions and optical_path_depth increment them).
StageWorkCounts& work_counts();
void reset_stage_work_counts();

// The camera as the stages use it: view transform (z_v = depth ahead) and focal length.
struct ViewSetup {
    glm::dmat4 view;  // glm::lookAt: camera space, looking down -z
    double focal_px = 0.0;
    // |target - eye| in world units: the eye-to-screen distance d of the depth image, the
    // screen put at the camera's target (depth_scale()).
    double target_distance = 0.0;
    int width = 0;
    int height = 0;
    double near = 0.01;
    glm::dvec3 eye{0.0};

    static ViewSetup from(const Camera& camera, int width, int height);
    // The depth image's scale: z_s = depth_scale() / z_v = f d / z_v (Saito & Takahashi 1990,
    // eq. 2, z_s = d^2 / (w z_v), with the screen at the target: w = d / f world units per px).
    // On a plane of view-space slope s = dz_v/dx_v its derivative per pixel is s d / z_v, the
    // slope itself at the target's depth, at every resolution and field of view (docs/world.md).
    double depth_scale() const { return focal_px * target_distance; }
    // View-space point with z_v > 0 ahead (the sign flipped from lookAt's -z).
    glm::dvec3 to_view(const glm::dvec3& p) const;
};

struct WorldFace {
    int object = 0;
    int index = 0;   // face index within its object
    int global = 0;  // face index over the whole world (Shape::face)
    Polygon3 loop;   // world coordinates, counter-clockwise seen from its normal's side
    PlaneFrame frame;  // on the face's plane; frame.normal points out (closed) or to the eye
    double reflectance = 1.0;
    std::optional<Rgb> reflectance_rgb;  // a colour world's coloured face (Face::reflectance_rgb)
    bool closed = true;
    bool visible = true;  // false once culled
};

// A disjoint convex piece of one face with what lies on it.
struct Cell {
    Polygon2 loop;  // counter-clockwise, in the face's frame
    double reflectance = 1.0;
    std::optional<Rgb> reflectance_rgb;  // its colour, when coloured (FacePattern, Face)
    std::uint64_t shadowed = 0;  // bit l: light l does not reach this cell
    ShapeRole role = ShapeRole::kFace;
    double value = 0.0;  // set by shade(), else the reflectance
    // A colour world's value per channel (set by shade(), else the reflectance's colour), and
    // `value` its luminance; unset where the value is grey in every channel.
    std::optional<Rgb> value_rgb;
    // What lies on the cell changes its reflectance: a pattern's or a face's, colour and all.
    template <class Source>
    void take_reflectance(const Source& from) {
        reflectance = from.reflectance;
        reflectance_rgb = from.reflectance_rgb;
    }
};

// Up to 64 lights can cast shadows (one bit each in Cell::shadowed).
inline constexpr std::size_t kMaxShadowLights = 64;

std::vector<WorldFace> collect_faces(const World& world, const ViewSetup& view);
// Returns the number of faces culled.
std::size_t cull_back_faces(std::vector<WorldFace>& faces, const ViewSetup& view);
// One cell per visible face (the whole face).
std::vector<std::vector<Cell>> initial_cells(const std::vector<WorldFace>& faces);
// Returns the number of pattern cells made.
std::size_t cut_patterns(const World& world, const std::vector<WorldFace>& faces,
                         std::vector<std::vector<Cell>>& cells);
// The shadow `caster` casts from `light` onto `receiver`, clipped to it, counter-clockwise in
// the receiver's frame; empty when it casts none (or only a rounding sliver).
Polygon2 shadow_on_face(const Light& light, const WorldFace& caster, const WorldFace& receiver);
// Does the light reach the receiver's seen side at all (n . l > 0 at its centroid; a point
// light in front of its plane)?
bool face_is_lit(const Light& light, const WorldFace& face);
// One shadow on a receiving face: the light it hides, its polygon in the face's frame.
struct FaceShadow {
    std::size_t light = 0;
    Polygon2 polygon;
};
// Per face (index as `faces`), the shadows that fall on it, in light-major, caster order.
using ShadowsByFace = std::vector<std::vector<FaceShadow>>;
ShadowsByFace find_shadows(const World& world, const std::vector<WorldFace>& faces);
// One face's cells cut by its shadows in turn, each part inside a shadow marked with its
// light's bit and the shadow role (slivers below min_twice_area dropped, as split_cells).
std::vector<Cell> cut_face_by_shadows(std::vector<Cell> cells,
                                      const std::vector<FaceShadow>& shadows,
                                      double min_twice_area);
// Cuts each face's cells by its shadows, marking the inside parts with the light's bit.
void cut_shadows(const std::vector<WorldFace>& faces, const ShadowsByFace& shadows,
                 std::vector<std::vector<Cell>>& cells);
// Both: returns the number of shadow polygons that fell on a face.
std::size_t cast_shadows(const World& world, const std::vector<WorldFace>& faces,
                         std::vector<std::vector<Cell>>& cells);
std::size_t shadow_count(const ShadowsByFace& shadows);
// In a colour world each channel is computed as channel_world(world, c) computes its one
// (the same operations in the same order), so the channel is that world's grey value, bit for
// bit; `value` is then the luminance of the three.
void shade(const World& world, const std::vector<WorldFace>& faces,
           std::vector<std::vector<Cell>>& cells);
// shade()'s arithmetic without its work counter, for another set of cells on the same faces
// (the overlay): the same values, bit for bit, for the same reflectance and shadow bits.
void shade_values(const World& world, const std::vector<WorldFace>& faces,
                  std::vector<std::vector<Cell>>& cells);
// Cells' value = reflectance, colour and all (no shading stage).
void unshaded(std::vector<std::vector<Cell>>& cells);
// Appends every cell, clipped to the near plane and projected, to scene.shapes.
void project_cells(const std::vector<WorldFace>& faces,
                   const std::vector<std::vector<Cell>>& cells, const ViewSetup& view,
                   Scene& scene);
// project_cells without its work counter (the overlay's projection).
void append_projected(const std::vector<WorldFace>& faces,
                      const std::vector<std::vector<Cell>>& cells, const ViewSetup& view,
                      Scene& scene);

// A face's outline in its own frame, counter-clockwise.
Polygon2 face_outline(const WorldFace& face);
// A polygon on the face's plane (a pattern) in the face's frame, counter-clockwise.
Polygon2 in_face_frame(const WorldFace& face, const Polygon3& loop);
// The rounding-sliver bound of a face: cells and shadow pieces of twice their area at most this
// are dropped (kSliverShare of the squared extent, stages.cpp).
double sliver_twice_area(const Polygon2& face_outline);
// Splits every cell of a face by `cutter`: the parts outside keep what they were, the part
// inside is passed to `mark`. Parts of twice their area at most `min_twice_area` are dropped.
void split_cells(std::vector<Cell>& cells, const Polygon2& cutter, double min_twice_area,
                 const std::function<void(Cell&)>& mark);

// A polygon's bounds in its face's frame, and whether two bounds lie strictly apart (then
// nothing of one lies inside the other).
struct Box2 {
    glm::dvec2 lo{INFINITY}, hi{-INFINITY};
};
Box2 bounds(const Polygon2& poly);
bool apart(const Box2& a, const Box2& b);

// One face's cells with each cell's bounds kept beside it, for cutting them by many cutters in
// turn: a face that receives thousands of shadows (a mesh's shadow on a ground tile). split()
// is split_cells(): the same cells in the same order, bit for bit. But split_cells() takes
// every cell's bounds again and rebuilds the whole list for each cutter, which costs cells x
// cutters in vertex reads, moves and allocation on such a face (the bunny's shadow stage at
// 48 x 48: 58.6 GB allocated); split() compares kept bounds and links a cut cell's parts in
// where it was. The cells are nodes of a list kept in vectors: cells[n], boxes[n] = bounds of
// cells[n].loop, next[n] the node after n in order (-1 at the end), from `head`.
struct BoxedCells {
    std::vector<Cell> cells;
    std::vector<Box2> boxes;
    std::vector<int> next;
    int head = -1;
    int last = -1;
    explicit BoxedCells(std::vector<Cell> from);
    void push(Cell cell);  // at the end
    void split(const Polygon2& cutter, double min_twice_area,
               const std::function<void(Cell&)>& mark);
    std::vector<Cell> take();  // the cells in order
};

// The edges two visible faces of one object share (the same two vertex indices), clipped to
// the near plane and projected: where the exact answer has the object on both sides, and where
// face-by-face compositing leaks the background (the `seams` symptom, harness/measure/).
std::vector<std::array<Point, 2>> shared_edges(const World& world,
                                               const std::vector<WorldFace>& faces,
                                               const ViewSetup& view);

// 1/z_v of a face's plane as an affine function of the screen position.
AffinePlane inverse_depth_plane(const WorldFace& face, const ViewSetup& view);

}  // namespace aabench
