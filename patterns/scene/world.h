// The 3-D scene model (scene file version 2, docs/scene-format.md): a camera, lights and
// objects made of planar convex faces with patterns on them, plus the effects the scene calls
// for. Pure data: harness/world/ turns it into a ScreenScene (projection, culling, shading,
// patterns, shadows) and harness/reference/ into exact visible pieces.
//
// Conventions. World space is right-handed, y up, any unit. The camera looks from `eye` toward
// `target`, `up` fixing the roll; its focal length is f = (H/2) / tan(fov_y/2) px, and a
// view-space point (x_v, y_v, z_v), z_v > 0 ahead, lands at (W/2 + f x_v/z_v, H/2 - f y_v/z_v)
// in the pixel frame of version 1 (pixel (i, j) covers [i, i+1] x [j, j+1], y down). The
// contracts: docs/world.md, "The world's contracts". All 3-D math is double, with GLM.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "patterns/scene/rgb.h"

namespace aabench {

struct Camera {
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 40.0;
    double near = 0.01;  // view depth (world units) below which geometry is clipped
    bool operator==(const Camera&) const = default;
};

enum class LightType { kParallel, kPoint };

struct Light {
    LightType type = LightType::kParallel;
    // Parallel: the way the light travels (from the light toward the scene); l = -direction.
    glm::dvec3 direction{0.0, -1.0, 0.0};
    glm::dvec3 position{0.0, 0.0, 0.0};  // point light
    double intensity = 1.0;
    // A coloured light (scene file version 4): its intensity per channel, `intensity` then its
    // luminance. Unset: grey, `intensity` in every channel.
    std::optional<Rgb> intensity_rgb;
    bool shadows = false;
    bool operator==(const Light&) const = default;
};

// A convex polygon in its face's plane, drawn over the face (later over earlier); it changes
// the reflectance only.
struct FacePattern {
    std::vector<glm::dvec3> loop;
    double reflectance = 0.0;
    std::optional<Rgb> reflectance_rgb;  // as Face::reflectance_rgb
    bool operator==(const FacePattern&) const = default;
};

// A planar convex polygon: vertex indices, counter-clockwise seen from outside (the
// right-hand normal points out).
struct Face {
    std::vector<int> loop;
    double reflectance = 1.0;
    // A coloured face (scene file version 4): its reflectance per channel, `reflectance` then
    // its luminance. Unset: grey, `reflectance` in every channel.
    std::optional<Rgb> reflectance_rgb;
    double mirror = 0.0;  // share reflected (Saito & Takahashi 1990, eq. 9's optical path)
    std::vector<FacePattern> patterns;
    bool operator==(const Face&) const = default;
};

// Where an object's faces came from when a mesh file made them (scene file version 4,
// `"mesh"`; patterns/scene/mesh_file.h), for `aabench plan` to say. Provenance, not geometry:
// it compares equal always, so a world read from a mesh and the same triangles written out as
// version 2 (which carries no provenance) are the same world.
struct MeshSource {
    std::string file;  // as the scene names it; empty: the object is no mesh
    std::size_t triangles = 0;
    std::size_t degenerate_dropped = 0;  // triangles of zero area left out (mesh_file.h)
    std::string closed_mode;             // "auto", "true" or "false", as the scene asked
    std::string closure;                 // what the edge check found (find_closure)
    bool operator==(const MeshSource&) const { return true; }
};

struct Object {
    std::string name;
    // true: a closed surface, faces turned away from the eye are culled. false: faces are
    // two-sided, the normal taken toward the eye.
    bool closed = true;
    std::vector<glm::dvec3> vertices;
    std::vector<Face> faces;
    MeshSource mesh;
    bool operator==(const Object&) const = default;
};

// Edge enhancement (Saito & Takahashi 1990): the scene asks for it by having this block.
struct EdgesSpec {
    std::string contour = "sobel";      // "sobel" (eq. 3) | "prewitt" (eq. 4)
    std::string crease = "laplacian8";  // "laplacian4" (eq. 5) | "laplacian8" (eq. 6) | "none"
    double kp = 10.0;                   // eq. 7
    double kl = 2.0;                    // eq. 8
    std::string style = "black";        // "black" (Fig. 3 h') | "white-convex" (Fig. 3 h)
    double contour_weight = 1.0;
    double crease_weight = 0.5;
    bool operator==(const EdgesSpec&) const = default;
};

// Switches that turn off an effect the scene contains, to measure with and without.
struct EffectSwitches {
    bool shadows = true;
    bool patterns = true;
    bool shading = true;
    bool edges = true;
    bool reflections = true;
    bool operator==(const EffectSwitches&) const = default;
};

struct World {
    Camera camera;
    double ambient = 0.0;
    std::optional<Rgb> ambient_rgb;  // a coloured ambient illuminance, `ambient` its luminance
    // No lights: illuminance 1 everywhere (the value is the reflectance).
    std::vector<Light> lights;
    std::vector<Object> objects;
    std::optional<EdgesSpec> edges;
    EffectSwitches effects;
    bool operator==(const World&) const = default;

    std::size_t face_count() const;
    // A colour world (docs/colour.md, "Colour worlds"): some reflectance, intensity or the
    // ambient is a colour. Its scene has three channels.
    bool is_colour() const;
};

// Channel `c` (0 R, 1 G, 2 B) of a world as a grey world: every reflectance, intensity and the
// ambient replaced by its value in that channel, colours dropped. The pipeline computes each
// channel of a colour world as it computes this world (harness/world/stages.h, shade()), so the
// channel's image is this world's grey image, bit for bit. A grey world is returned as it is.
World channel_world(const World& world, int c);

// Checks what the scene file format demands of a world (docs/scene-format.md, "Version 2 checks")
// and throws InputError naming the JSON path of the first violation, e.g.
// "<source>: objects[1].faces[4].loop[2]: index 9 out of range (object has 8 vertices)":
// indices in range, faces of >= 3 distinct vertices, planar and convex (tolerances in
// world_check.cpp with their reasons), patterns in their face's plane and convex, camera eye !=
// target, up not parallel to the view, fov in (0, 180), near > 0, light directions nonzero,
// finite numbers. The reader calls it after parsing; generators' tests call it too.
void check_world(const World& world, const std::string& source);

// True when the triangle a, b, c has zero area by check_world's rule (its Newell vector at
// most 1e-12 x its extent squared): what the mesh loader drops as degenerate, so that no
// triangle it keeps is refused afterwards.
bool triangle_has_zero_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// The unit normal of a face by Newell's method (robust for any planar polygon), pointing out
// for a counter-clockwise loop; zero for a degenerate face.
glm::dvec3 face_normal(const Object& object, const Face& face);

}  // namespace aabench
