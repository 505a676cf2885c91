// Meshes from model files through Assimp (mesh_file.h says what is done to them and why).
// Without Assimp (AABENCH_HAVE_ASSIMP unset: CMake did not find it) every load is refused in
// one line.
#include "patterns/scene/mesh_file.h"

#include "patterns/scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#ifdef AABENCH_HAVE_ASSIMP
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <assimp/Importer.hpp>
#endif

namespace aabench {
namespace {

glm::dmat3 rotation_x(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    // glm is column-major: each glm::dvec3 below is a column.
    return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, c, s), glm::dvec3(0, -s, c));
}
glm::dmat3 rotation_y(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    return glm::dmat3(glm::dvec3(c, 0, -s), glm::dvec3(0, 1, 0), glm::dvec3(s, 0, c));
}
glm::dmat3 rotation_z(double rad) {
    const double c = std::cos(rad), s = std::sin(rad);
    return glm::dmat3(glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1));
}

double radians(double deg) { return deg * (std::numbers::pi / 180.0); }

#ifdef AABENCH_HAVE_ASSIMP

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                  aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices |
                                  aiProcess_FindDegenerates | aiProcess_ValidateDataStructure;

void configure(Assimp::Importer& importer) {
    // Everything but the positions and the materials: vertices then join by position alone.
    importer.SetPropertyInteger(
        AI_CONFIG_PP_RVC_FLAGS,
        aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
            aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
            aiComponent_CAMERAS | aiComponent_LIGHTS | aiComponent_TEXTURES);
    // Degenerate triangles become lines and points (counted below), not removed unseen.
    importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, false);
}

std::optional<Rgb> diffuse_colour(const aiScene& scene, unsigned material_index) {
    if (material_index >= scene.mNumMaterials) return std::nullopt;
    const aiMaterial* material = scene.mMaterials[material_index];
    aiString name;
    if (material->Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS &&
        std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0) {
        return std::nullopt;  // Assimp's stand-in: the file named no material
    }
    aiColor3D colour;
    if (material->Get(AI_MATKEY_COLOR_DIFFUSE, colour) != aiReturn_SUCCESS) return std::nullopt;
    const Rgb rgb{colour.r, colour.g, colour.b};
    if (!std::isfinite(luminance(rgb))) return std::nullopt;
    return rgb;
}

// The triangles of an imported scene, joined across its meshes by exact position.
LoadedMesh convert(const aiScene& scene, const std::string& name, const MeshTransform& transform,
                   long long max_triangles) {
    long long faces = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) faces += scene.mMeshes[m]->mNumFaces;
    if (faces > max_triangles) {
        throw MeshError(fmt::format(
            "{}: {} faces, more than the limit of {} triangles per scene (docs/limits.md)", name,
            faces, max_triangles));
    }
    const bool mirrored = transform.scale.x * transform.scale.y * transform.scale.z < 0.0;
    LoadedMesh out;
    struct Key {
        float x, y, z;
        bool operator<(const Key& o) const { return std::tie(x, y, z) < std::tie(o.x, o.y, o.z); }
    };
    std::map<Key, int> index_of;  // ordered: the same file gives the same vertex order
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        const std::optional<Rgb> diffuse = diffuse_colour(scene, mesh.mMaterialIndex);
        // Rec. 709 luminance of the linear colour: a grey colour is this number; one whose
        // components differ keeps its colour beside it, unless a component is beyond the
        // values an image holds (then only the luminance, as before colour came in).
        std::optional<double> reflectance;
        std::optional<Rgb> colour;
        if (diffuse) {
            reflectance = luminance(*diffuse);
            const Rgb& c = *diffuse;
            const bool holdable = std::abs(c[0]) <= kMaxValue && std::abs(c[1]) <= kMaxValue &&
                                  std::abs(c[2]) <= kMaxValue;
            if (holdable && !(c[0] == c[1] && c[1] == c[2])) colour = c;
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) {
                ++out.degenerate;  // a point or a line: no surface
                continue;
            }
            std::array<int, 3> tri{};
            std::array<glm::dvec3, 3> p{};
            for (int k = 0; k < 3; ++k) {
                const unsigned i = face.mIndices[k];
                if (i >= mesh.mNumVertices)
                    throw MeshError(name + ": a face index is out of range");
                const aiVector3D& v = mesh.mVertices[i];
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                    throw MeshError(fmt::format("{}: mesh {} vertex {} is not finite ({}, {}, {})",
                                                name, m, i, v.x, v.y, v.z));
                }
                const Key key{v.x, v.y, v.z};
                auto [it, added] = index_of.try_emplace(key, static_cast<int>(out.vertices.size()));
                if (added) out.vertices.push_back(transform_point(transform, {v.x, v.y, v.z}));
                tri[k] = it->second;
                p[k] = out.vertices[it->second];
            }
            if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
                triangle_has_zero_area(p[0], p[1], p[2])) {
                ++out.degenerate;
                continue;
            }
            if (mirrored) std::swap(tri[1], tri[2]);
            out.triangles.push_back(tri);
            out.reflectance.push_back(reflectance);
            out.colour.push_back(colour);
        }
    }
    if (out.triangles.empty()) {
        throw MeshError(fmt::format("{}: no triangles in the file ({} degenerate left out)", name,
                                    out.degenerate));
    }
    // Keep only the vertices the triangles use, in order of first use.
    std::vector<int> remap(out.vertices.size(), -1);
    std::vector<glm::dvec3> used;
    used.reserve(out.vertices.size());
    for (auto& tri : out.triangles) {
        for (int& i : tri) {
            if (remap[i] < 0) {
                remap[i] = static_cast<int>(used.size());
                used.push_back(out.vertices[i]);
            }
            i = remap[i];
        }
    }
    out.vertices = std::move(used);
    return out;
}

// The importer's scene after the steps of kImportFlags, `read` the scene it read (validated
// only), null when it read nothing: what Importer::ReadFile(path, kImportFlags) does in one call
// (read, validate, then the other steps), with one check between. Debian's Assimp 5.2.5 keeps its
// internal assertions, which abort the process: a face of no corners (its PLY reader makes them
// of a malformed face list, tests/fuzz/corpus/mesh_fuzz/regression-ply-empty-faces.ply) is
// marked a polygon by aiProcess_FindDegenerates, and aiProcess_Triangulate then asserts that a
// mesh marked with polygons gains faces. Such a file is refused before the steps run.
const aiScene* post_processed(Assimp::Importer& importer, const aiScene* read,
                              const std::string& name) {
    if (!read) return nullptr;
    for (unsigned m = 0; m < read->mNumMeshes; ++m) {
        const aiMesh& mesh = *read->mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            if (mesh.mFaces[f].mNumIndices == 0) {
                throw MeshError(
                    fmt::format("{}: mesh {} face {} has no vertex indices", name, m, f));
            }
        }
    }
    return importer.ApplyPostProcessing(kImportFlags & ~aiProcess_ValidateDataStructure);
}

// Assimp 5.2.5's PLY reader loops forever on a header that never ends: a file that starts
// "ply" (the format's magic, which Assimp reads it by) with no line `end_header`
// (tests/fuzz/corpus/mesh_fuzz/regression-ply-no-end-header.ply, where a control byte runs into
// it, and regression-ply-nul-end-header.ply, where NUL bytes do). Such a file is refused before
// Assimp sees it. The line must be the word alone, as a writer puts it (trailing spaces, tabs
// and the CR of a CRLF allowed): the cases the reader was seen to take.
bool has_end_header(std::string_view text) {
    constexpr std::string_view kLine = "end_header";
    for (std::size_t at = text.find(kLine); at != std::string_view::npos;
         at = text.find(kLine, at + 1)) {
        if (at != 0 && text[at - 1] != '\n') continue;
        std::size_t after = at + kLine.size();
        while (after < text.size() &&
               (text[after] == ' ' || text[after] == '\t' || text[after] == '\r')) {
            ++after;
        }
        if (after == text.size() || text[after] == '\n') return true;
    }
    return false;
}
bool starts_ply(std::string_view text) { return text.substr(0, 3) == "ply"; }
void check_ply_header(std::string_view text, const std::string& name) {
    if (starts_ply(text) && !has_end_header(text)) {
        throw MeshError(fmt::format("{}: a PLY header without end_header", name));
    }
}

// What the importer read (`scene`, null when it read nothing), converted; Assimp's own message
// in the error when it read nothing.
LoadedMesh converted(const Assimp::Importer& importer, const aiScene* scene,
                     const std::string& name, const MeshTransform& transform,
                     long long max_triangles) {
    if (!scene) {
        throw MeshError(fmt::format("{}: Assimp cannot read it: {}", name,
                                    std::string(importer.GetErrorString())));
    }
    return convert(*scene, name, transform, max_triangles);
}

#endif

}  // namespace

glm::dvec3 transform_point(const MeshTransform& t, const glm::dvec3& p) {
    const glm::dmat3 r = rotation_z(radians(t.rotate_deg.z)) * rotation_y(radians(t.rotate_deg.y)) *
                         rotation_x(radians(t.rotate_deg.x));
    return r * (t.scale * p) + t.translate;
}

bool mesh_loading_available() {
#ifdef AABENCH_HAVE_ASSIMP
    return true;
#else
    return false;
#endif
}

std::string assimp_version() {
#ifdef AABENCH_HAVE_ASSIMP
    return fmt::format("{}.{}.{}", aiGetVersionMajor(), aiGetVersionMinor(), aiGetVersionPatch());
#else
    return "";
#endif
}

LoadedMesh load_mesh_file(const std::string& path, const std::string& name,
                          const MeshTransform& transform, long long max_triangles) {
#ifdef AABENCH_HAVE_ASSIMP
    // Open it first: Assimp's own message for a missing file does not say why.
    {
        std::FILE* file = std::fopen(path.c_str(), "rb");
        if (!file) throw MeshError(fmt::format("{}: cannot open: {}", name, std::strerror(errno)));
        // The first bytes, and for a PLY file as far as its header's end (check_ply_header).
        std::string head;
        char chunk[1 << 16];
        std::size_t n = 0;
        while ((n = std::fread(chunk, 1, sizeof chunk, file)) > 0) {
            head.append(chunk, n);
            if (!starts_ply(head) || has_end_header(head)) break;
        }
        const bool error = std::ferror(file);
        const int err = errno;
        std::fclose(file);
        if (error) throw MeshError(fmt::format("{}: cannot read: {}", name, std::strerror(err)));
        if (head.empty()) throw MeshError(fmt::format("{}: empty file", name));
        check_ply_header(head, name);
    }
    Assimp::Importer importer;
    configure(importer);
    return converted(
        importer,
        post_processed(importer, importer.ReadFile(path, aiProcess_ValidateDataStructure), name),
        name, transform, max_triangles);
#else
    (void)path;
    (void)transform;
    (void)max_triangles;
    throw MeshError(name +
                    ": this build has no mesh loading (Assimp was not found when it was "
                    "configured: install libassimp-dev, docs/building.md)");
#endif
}

LoadedMesh load_mesh_from_memory(std::span<const unsigned char> bytes,
                                 const std::string& format_hint, const std::string& name,
                                 const MeshTransform& transform, long long max_triangles) {
#ifdef AABENCH_HAVE_ASSIMP
    if (bytes.empty()) throw MeshError(fmt::format("{}: empty file", name));
    check_ply_header(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                     name);
    Assimp::Importer importer;
    configure(importer);
    return converted(importer,
                     post_processed(importer,
                                    importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                                aiProcess_ValidateDataStructure,
                                                                format_hint.c_str()),
                                    name),
                     name, transform, max_triangles);
#else
    (void)bytes;
    (void)format_hint;
    (void)transform;
    (void)max_triangles;
    throw MeshError(name + ": this build has no mesh loading (Assimp was not found)");
#endif
}

Closure find_closure(const std::vector<std::array<int, 3>>& triangles) {
    // Each undirected edge: how many triangles use it, and the sum of its directions (+1 from
    // the lower index to the higher, -1 back): two triangles in opposite directions sum to 0.
    struct Use {
        int count = 0;
        int direction = 0;
    };
    std::unordered_map<std::uint64_t, Use> edges;
    edges.reserve(triangles.size() * 3 / 2 + 1);
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            const auto lo = static_cast<std::uint64_t>(std::min(a, b));
            const auto hi = static_cast<std::uint64_t>(std::max(a, b));
            Use& u = edges[lo << 32 | hi];
            ++u.count;
            u.direction += a < b ? 1 : -1;
        }
    }
    // The first bad edge in a fixed order, so the message is the same every run.
    std::uint64_t open_edge = UINT64_MAX, flipped_edge = UINT64_MAX;
    int open_count = 0;
    for (const auto& [key, use] : edges) {
        if (use.count != 2) {
            if (key < open_edge) {
                open_edge = key;
                open_count = use.count;
            }
        } else if (use.direction != 0 && key < flipped_edge) {
            flipped_edge = key;
        }
    }
    const auto name = [](std::uint64_t key) {
        return fmt::format("({}, {})", key >> 32, key & 0xffffffffu);
    };
    if (open_edge != UINT64_MAX) {
        return {false, fmt::format("open: edge {} is used by {} triangle{}", name(open_edge),
                                   open_count, open_count == 1 ? "" : "s")};
    }
    if (flipped_edge != UINT64_MAX) {
        return {false, fmt::format("not consistently oriented: edge {} runs the same way in both "
                                   "its triangles",
                                   name(flipped_edge))};
    }
    return {true, "watertight and consistently oriented"};
}

Object mesh_object(const LoadedMesh& mesh, const std::string& name, const std::string& file,
                   std::optional<double> reflectance, ClosedMode mode, MeshColours colours,
                   std::optional<Rgb> reflectance_rgb) {
    Object o;
    o.name = name;
    o.vertices = mesh.vertices;
    o.faces.reserve(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        Face f;
        f.loop.assign(mesh.triangles[i].begin(), mesh.triangles[i].end());
        if (reflectance) {
            f.reflectance = *reflectance;
            f.reflectance_rgb = reflectance_rgb;
        } else if (mesh.reflectance[i]) {
            f.reflectance = *mesh.reflectance[i];
            if (colours == MeshColours::kColour && i < mesh.colour.size()) {
                f.reflectance_rgb = mesh.colour[i];
            }
        }
        o.faces.push_back(std::move(f));
    }
    const Closure closure = find_closure(mesh.triangles);
    o.closed = mode == ClosedMode::kTrue || (mode == ClosedMode::kAuto && closure.closed);
    o.mesh.file = file;
    o.mesh.triangles = mesh.triangles.size();
    o.mesh.degenerate_dropped = mesh.degenerate;
    o.mesh.closed_mode = mode == ClosedMode::kAuto   ? "auto"
                         : mode == ClosedMode::kTrue ? "true"
                                                     : "false";
    o.mesh.closure = closure.finding;
    return o;
}

}  // namespace aabench
