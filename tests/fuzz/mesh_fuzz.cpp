// libFuzzer target: the mesh loader (patterns/scene/mesh_file.h) on arbitrary OBJ, PLY and STL
// bytes (docs/fuzzing.md). Seeds: a small valid file of each (tests/fuzz/corpus/mesh_fuzz/).
//
// The format is told from the bytes as a file's extension would tell it: "ply" at the start is
// PLY, "solid" or a binary STL's size (84 + 50 bytes per triangle) is STL, anything else OBJ.
// load_mesh_from_memory must either throw MeshError or return triangles of three distinct
// indices into finite vertices, none of zero area, and at most the limit; find_closure and
// mesh_object must take them. Anything else (another exception, a crash, a sanitizer report)
// aborts, and libFuzzer keeps the input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string>

#include "patterns/scene/mesh_file.h"

namespace {

// Small enough that a mutated count cannot make the loader build millions of faces.
constexpr long long kFuzzMaxTriangles = 100'000;

[[noreturn]] void violation(const char* what) {
    std::fprintf(stderr, "mesh_fuzz: %s\n", what);
    std::abort();
}

std::string format_of(const std::uint8_t* data, std::size_t size) {
    if (size >= 3 && std::memcmp(data, "ply", 3) == 0) return "ply";
    if (size >= 5 && std::memcmp(data, "solid", 5) == 0) return "stl";
    if (size >= 84) {
        std::uint32_t count = 0;
        std::memcpy(&count, data + 80, sizeof count);
        if (84 + 50ull * count == size) return "stl";
    }
    return "obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace aabench;
    MeshTransform transform;
    transform.scale = {1.5, -0.75, 2.0};  // a mirror: the loops are reversed
    transform.rotate_deg = {10.0, 20.0, 30.0};
    transform.translate = {0.25, -3.0, 7.0};
    try {
        const LoadedMesh mesh =
            load_mesh_from_memory(std::span<const unsigned char>(data, size), format_of(data, size),
                                  "fuzzed", transform, kFuzzMaxTriangles);
        if (mesh.triangles.empty()) violation("no triangles, and no MeshError");
        if (static_cast<long long>(mesh.triangles.size()) > kFuzzMaxTriangles) {
            violation("more triangles than the limit");
        }
        if (mesh.reflectance.size() != mesh.triangles.size()) violation("reflectance per triangle");
        for (const glm::dvec3& v : mesh.vertices) {
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                violation("a non-finite vertex");
            }
        }
        const int n = static_cast<int>(mesh.vertices.size());
        for (const auto& t : mesh.triangles) {
            for (const int i : t) {
                if (i < 0 || i >= n) violation("an index out of range");
            }
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) violation("a repeated corner");
            if (triangle_has_zero_area(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                       mesh.vertices[t[2]])) {
                violation("a triangle of zero area kept");
            }
        }
        const Object o = mesh_object(mesh, "fuzzed", "fuzzed", std::nullopt, ClosedMode::kAuto);
        if (o.faces.size() != mesh.triangles.size()) violation("a face per triangle");
    } catch (const MeshError&) {
    }
    return 0;
}
