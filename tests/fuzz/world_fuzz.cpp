// libFuzzer target: the version-2 scene reader and the world stages (docs/fuzzing.md).
//
// The bytes are scene JSON (the seed corpus holds the built-in 3-D patterns written as
// version-2 scene files, small). A scene the reader accepts is shrunk to at most 24 x 24
// pixels (a world projects onto any size, so the shrunk scene is still valid) and, when it has
// at most kFuzzMaxFaces faces, goes through the world stages: PreparedFrame::prepare
// (projection, culling, shading, patterns, shadows), the exact visible pieces, the box
// reference of them, and one cheap method (`none`, a z-buffer over the ScreenScene). Each must
// either throw InputError with a one-line message or give only finite values. Anything else (a
// non-finite pixel, a multi-line message, another exception, a crash, a sanitizer report)
// aborts, and libFuzzer keeps the input.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/scene/scene_io.h"

namespace {

using namespace aabench;

// Bounds that keep one input to milliseconds: the reader's vertex limit (the seeds have up to
// 404 vertices: foliage at its minimum of 100 leaves plus the backdrop), the faces a world may
// have to be staged, and the image side.
constexpr long long kFuzzMaxVertices = 512;
constexpr std::size_t kFuzzMaxFaces = 160;
constexpr int kFuzzMaxSide = 24;

[[noreturn]] void violation(const std::string& what, const std::string& text) {
    std::fprintf(stderr, "world_fuzz: %s\ninput: %.400s\n", what.c_str(), text.c_str());
    std::abort();
}

void check_one_line(const InputError& error, const char* stage, const std::string& text) {
    const std::string message = error.what();
    if (message.empty() || message.find('\n') != std::string::npos) {
        violation(std::string(stage) + ": empty or multi-line message: " + message, text);
    }
}

template <typename Values>
void check_finite(const Values& values, const char* what, const std::string& text) {
    for (const auto v : values) {
        if (!std::isfinite(v)) violation(std::string(what) + ": a non-finite value", text);
    }
}

void check_scene_finite(const Scene& scene, const char* what, const std::string& text) {
    if (!std::isfinite(scene.background)) violation(std::string(what) + ": background", text);
    for (const Shape& shape : scene.shapes) {
        if (!std::isfinite(shape.value)) violation(std::string(what) + ": a shape's value", text);
        for (const Contour& c : shape.contours) {
            for (const Point& p : c) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                    violation(std::string(what) + ": a non-finite point", text);
                }
            }
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    try {
        scene = parse_scene_json(text, "fuzz", kFuzzMaxVertices);
    } catch (const InputError& error) {
        check_one_line(error, "reader", text);
        return 0;
    }
    if (!scene.world || scene.world->face_count() > kFuzzMaxFaces) return 0;
    scene.width = std::min(scene.width, kFuzzMaxSide);
    scene.height = std::min(scene.height, kFuzzMaxSide);
    try {
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        check_scene_finite(frame.screen(), "projection", text);
        const MethodInstance none = make_method("none");
        Image out(scene.width, scene.height);
        none.method->render(frame.input_for(*none.method), out);
        check_finite(out.data, "none", text);
        check_scene_finite(frame.pieces().scene(), "visibility", text);
        check_finite(box_reference(frame.pieces()).data, "box reference", text);
    } catch (const InputError& error) {
        check_one_line(error, "world stages", text);
    }
    return 0;
}
