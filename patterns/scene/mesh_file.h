// Meshes from model files (scene file version 4, `"mesh"`, docs/scene-format.md): every format
// Assimp reads (OBJ, PLY, STL, glTF, 3DS, ...), turned into an Object of triangle faces like
// any other (world.h).
//
// How a file becomes triangles. Assimp reads it with aiProcess_Triangulate (polygons fanned
// into triangles), aiProcess_PreTransformVertices (the file's node transforms baked in, so the
// parts of a glTF model sit where the file places them), aiProcess_RemoveComponent of normals,
// texture coordinates, colours, tangents, bones and animations, then
// aiProcess_JoinIdenticalVertices (with the other attributes gone, vertices join by position
// alone: a cube's corners are shared by its faces, as closedness needs) and
// aiProcess_FindDegenerates without removal (a triangle with a repeated corner becomes a line
// or point, which is counted). The meshes of one file are then joined into one vertex list by
// exact position, the transform below applied in double, and every triangle that has zero area
// by check_world's rule (triangle_has_zero_area) after it is dropped and counted too, so that no
// triangle kept is refused later. Lines and points in the file are not surfaces and are
// counted with the degenerate triangles.
//
// The transform: p' = R_z R_y R_x S p + t: scale first (per axis), then right-handed rotations
// of the points about x, then y, then z (degrees), then the translation. A negative scale
// with an odd number of negative axes mirrors the mesh, and each triangle's loop is reversed
// so that it stays counter-clockwise seen from outside.
//
// Reflectance: the diffuse colour (AI_MATKEY_COLOR_DIFFUSE) of each triangle's material, where
// the file has one, and its luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709, linear);
// Assimp's stand-in material for a file that names none (AI_DEFAULT_MATERIAL_NAME) is no
// colour of the file's. A scene file's mesh object takes the colour (a colour world,
// docs/colour.md), a built-in pattern its luminance (the `models` patterns are grey).
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "patterns/scene/world.h"

namespace aabench {

// Triangles per scene, all meshes together (docs/limits.md: about 1.3 KB per triangle measured
// through the world stages, so about 5.5 GB at the limit, within the job's 8 GiB budget).
inline constexpr long long kMaxMeshTriangles = 1LL << 22;

struct MeshTransform {
    glm::dvec3 scale{1.0};
    glm::dvec3 rotate_deg{0.0};
    glm::dvec3 translate{0.0};
};

// p' = R_z R_y R_x S p + t (above).
glm::dvec3 transform_point(const MeshTransform& transform, const glm::dvec3& p);

// A bad mesh: one line, naming the file. The reader prefixes the JSON path.
class MeshError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct LoadedMesh {
    std::vector<glm::dvec3> vertices;  // transformed; only the ones the triangles use
    // Counter-clockwise seen from outside (the file's front faces: the right-hand normal).
    std::vector<std::array<int, 3>> triangles;
    // Per triangle: the luminance of its material's diffuse colour, when the file has one.
    std::vector<std::optional<double>> reflectance;
    // Per triangle: that colour, when its components differ (a grey colour is its luminance).
    std::vector<std::optional<Rgb>> colour;
    std::size_t degenerate = 0;  // triangles of zero area, lines and points left out
};

// False in a build without Assimp (CMake says so when it configures): a mesh is then refused.
bool mesh_loading_available();
// "5.2.5", or "" without Assimp.
std::string assimp_version();

// Reads the model file at `path` (`name` names it in messages), transformed. More than
// `max_triangles` triangles in the file, a file that cannot be opened or read, a format Assimp
// does not read (its own message), no triangle left, a vertex that is not finite: MeshError.
// So are two malformations on which Assimp 5.2.5 aborts or never returns, refused before it
// gets to them (mesh_file.cpp): a file that starts "ply" without an `end_header` line, and a
// face of no vertex index.
LoadedMesh load_mesh_file(const std::string& path, const std::string& name,
                          const MeshTransform& transform, long long max_triangles);
// The same from a file's bytes, `format_hint` its extension ("obj", "ply", "stl"): the fuzz
// target's entry.
LoadedMesh load_mesh_from_memory(std::span<const unsigned char> bytes,
                                 const std::string& format_hint, const std::string& name,
                                 const MeshTransform& transform, long long max_triangles);

// Whether a triangle mesh is a closed, consistently oriented surface: every edge shared by
// exactly two triangles that run along it in opposite directions.
struct Closure {
    bool closed = false;
    std::string finding;  // "watertight and consistently oriented", or the first edge that is not
};
Closure find_closure(const std::vector<std::array<int, 3>>& triangles);

enum class ClosedMode { kAuto, kTrue, kFalse };

// What a mesh object's faces take of their materials' colours: the luminance (grey) or the
// colour itself.
enum class MeshColours { kLuminance, kColour };

// The object of the mesh's triangles: one face per triangle, the reflectance `reflectance`
// (with its colour `reflectance_rgb`, if any) when given, else the triangle's material's (its
// colour with kColour), else 1 (Face's default). Closed as `mode` says; kAuto: closed (back
// faces culled) exactly when find_closure says so. `file` names it in the object's MeshSource.
Object mesh_object(const LoadedMesh& mesh, const std::string& name, const std::string& file,
                   std::optional<double> reflectance, ClosedMode mode,
                   MeshColours colours = MeshColours::kLuminance,
                   std::optional<Rgb> reflectance_rgb = std::nullopt);

}  // namespace aabench
