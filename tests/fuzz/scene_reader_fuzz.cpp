// libFuzzer target: the scene reader on arbitrary bytes (docs/fuzzing.md).
//
// parse_scene_json must either throw InputError or return a scene that satisfies every rule
// of docs/scene-format.md, and such a scene must survive the writer and the reader again bit
// for bit. The reader's fast first pass must agree with nlohmann's parser wherever it does not
// give up. Anything else (another exception, a crash, a sanitizer report, a broken rule)
// aborts, and libFuzzer keeps the input.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "patterns/scene/plain_json_parser.h"
#include "patterns/scene/scene_io.h"
#include "tests/json_event_log.h"

namespace {

using aabench::Scene;

// A small vertex limit, so that the fuzzer reaches the limit's error path with small inputs.
constexpr long long kFuzzMaxVertices = 64;

[[noreturn]] void violation(const char* what, const std::string& text) {
    std::fprintf(stderr, "scene_reader_fuzz: %s\ninput: %.200s\n", what, text.c_str());
    std::abort();
}

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_bits(const glm::dvec3& a, const glm::dvec3& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

// Version 3's sequence, every number bit for bit (-0.0 included).
bool identical(const std::optional<aabench::SceneSequence>& a,
               const std::optional<aabench::SceneSequence>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return a->motion == b->motion && a->frames == b->frames && same_bits(a->dx_px, b->dx_px) &&
           same_bits(a->dy_px, b->dy_px) && same_bits(a->eye_step, b->eye_step) &&
           same_bits(a->target_step, b->target_step) && same_bits(a->orbit_deg, b->orbit_deg);
}

bool identical(const Scene& a, const Scene& b) {
    if (a.width != b.width || a.height != b.height || !same_bits(a.background, b.background) ||
        !same_bits(a.origin_x, b.origin_x) || !same_bits(a.origin_y, b.origin_y) ||
        a.metadata != b.metadata || a.shapes.size() != b.shapes.size() ||
        !identical(a.sequence, b.sequence)) {
        return false;
    }
    for (std::size_t s = 0; s < a.shapes.size(); ++s) {
        if (!same_bits(a.shapes[s].value, b.shapes[s].value) ||
            a.shapes[s].contours.size() != b.shapes[s].contours.size() ||
            a.shapes[s].outline.size() != b.shapes[s].outline.size()) {
            return false;
        }
        // Version 4's Bezier outline, every control point bit for bit.
        for (std::size_t k = 0; k < a.shapes[s].outline.size(); ++k) {
            const auto& ca = a.shapes[s].outline[k];
            const auto& cb = b.shapes[s].outline[k];
            if (ca.size() != cb.size()) return false;
            for (std::size_t q = 0; q < ca.size(); ++q) {
                if (ca[q].degree != cb[q].degree) return false;
                for (int i = 0; i <= ca[q].degree; ++i) {
                    if (!same_bits(ca[q].p[i].x, cb[q].p[i].x) || !same_bits(ca[q].p[i].y, cb[q].p[i].y)) {
                        return false;
                    }
                }
            }
        }
        for (std::size_t k = 0; k < a.shapes[s].contours.size(); ++k) {
            const auto& ca = a.shapes[s].contours[k];
            const auto& cb = b.shapes[s].contours[k];
            if (ca.size() != cb.size()) return false;
            for (std::size_t p = 0; p < ca.size(); ++p) {
                if (!same_bits(ca[p].x, cb[p].x) || !same_bits(ca[p].y, cb[p].y)) return false;
            }
        }
    }
    return true;
}

void check_valid(const Scene& scene, const std::string& text) {
    if (scene.width < 1 || scene.height < 1 || scene.width > aabench::kMaxImageSide ||
        scene.height > aabench::kMaxImageSide ||
        static_cast<long long>(scene.width) * scene.height > aabench::kMaxImagePixels) {
        violation("size out of range", text);
    }
    if (!std::isfinite(scene.background) || !std::isfinite(scene.origin_x) ||
        !std::isfinite(scene.origin_y)) {
        violation("non-finite background or origin", text);
    }
    // The file's own points count against the reader's limit (kFuzzMaxVertices here); a disc's
    // or ring's polygonisation is made by the reader and counts against the scene's limit
    // (kMaxSceneVertices), whatever the file's limit.
    long long vertices = 0, curve_vertices = 0;
    for (const aabench::Shape& shape : scene.shapes) {
        if (!std::isfinite(shape.value)) violation("non-finite value", text);
        if (shape.contours.empty()) violation("shape without contours", text);
        for (const aabench::Contour& c : shape.contours) {
            if (c.size() < 3) violation("contour of fewer than 3 points", text);
            // A Bezier shape's contours are its flattening, made by the reader like a circle's.
            (shape.circle || !shape.outline.empty() ? curve_vertices : vertices) +=
                static_cast<long long>(c.size());
            for (const aabench::Point& p : c) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) violation("non-finite point", text);
            }
        }
    }
    for (const aabench::Shape& shape : scene.shapes) {
        for (const aabench::SegmentContour& c : shape.outline) {
            if (c.empty()) violation("empty Bezier contour", text);
            for (std::size_t k = 0; k < c.size(); ++k) {
                if (!(c[(k + 1) % c.size()].p[0] == c[k].end())) violation("open Bezier contour", text);
                for (int i = 0; i <= c[k].degree; ++i) {
                    if (!(std::abs(c[k].p[i].x) <= 1e9 && std::abs(c[k].p[i].y) <= 1e9)) {
                        violation("a Bezier point beyond 1e9 px", text);
                    }
                }
            }
        }
    }
    if (vertices > kFuzzMaxVertices) violation("vertex limit not enforced", text);
    if (curve_vertices > aabench::kMaxSceneVertices) {
        violation("curve vertex limit not enforced", text);
    }
    if (const auto& q = scene.sequence) {
        if (q->frames && !(*q->frames >= aabench::kMinSequenceFrames &&
                           *q->frames <= aabench::kMaxSequenceFrames)) {
            violation("sequence frames out of range", text);
        }
        bool finite =
            std::isfinite(q->dx_px) && std::isfinite(q->dy_px) && std::isfinite(q->orbit_deg);
        for (int k = 0; k < 3; ++k) {
            finite = finite && std::isfinite(q->eye_step[k]) && std::isfinite(q->target_step[k]);
        }
        if (!finite) violation("non-finite sequence step", text);
        // The motions a scene may have: 2-D still or translate, camera paths on a world only.
        const bool camera = q->motion == aabench::SequenceMotion::kPath ||
                            q->motion == aabench::SequenceMotion::kOrbit;
        if (camera && !scene.world) violation("a camera path on a 2-D scene", text);
    }
    if (!scene.thin_objects.empty()) violation("a read scene has thin objects", text);
}

// The reader's fast first pass (patterns/scene/plain_json_parser.h) either gives up or sends
// exactly the SAX events nlohmann's parser sends, numbers of the same type and bits.
void check_fast_parser(const std::string& text) {
    aabench::JsonEventLog fast;
    if (!aabench::scene_io_detail::parse_plain_json(text, fast)) return;
    aabench::JsonEventLog reference;
    if (!nlohmann::json::sax_parse(text, &reference, nlohmann::json::input_format_t::json,
                                   /*strict=*/true)) {
        violation("the fast parser accepted what nlohmann refuses", text);
    }
    if (fast.events != reference.events) violation("the fast parser's events differ", text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    check_fast_parser(text);
    Scene scene;
    try {
        scene = aabench::parse_scene_json(text, "fuzz", kFuzzMaxVertices);
    } catch (const aabench::InputError& error) {
        const std::string message = error.what();
        if (message.find('\n') != std::string::npos) violation("multi-line message", text);
        return 0;
    }
    check_valid(scene, text);
    std::string written;
    try {
        written = aabench::scene_to_json(scene);
    } catch (const aabench::InputError&) {
        // Only metadata that is not valid UTF-8 may be refused by the writer, and the reader
        // refuses such text before it gets here.
        violation("the writer refused a scene the reader accepted", text);
    }
    // The fuzz limit bounds the work per input; the rewritten file spells out what the input
    // may only name (a text shape's glyph outlines), so it is read under the real limit, which
    // the reader's count of the expansion already kept it within.
    const Scene back =
        aabench::parse_scene_json(written, "fuzz-rewritten", aabench::kMaxSceneVertices);
    if (!identical(scene, back)) violation("the round trip changed the scene", text);
    return 0;
}
