// libFuzzer target: the glyph loader (patterns/scene/text.h) on arbitrary font bytes
// (docs/fuzzing.md). Seeds: the first kilobytes of the two built-in font families and a whole
// font (tests/fuzz/corpus/glyph_fuzz/).
//
// text_outline_from_memory must either throw TextError or return closed contours of finite
// points; every contour must survive bezier_shape (which refuses an open one). Anything else
// (another exception, a crash, a sanitizer report) aborts, and libFuzzer keeps the input.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>

#include "patterns/scene/bezier.h"
#include "patterns/scene/text.h"

namespace {

[[noreturn]] void violation(const char* what) {
    std::fprintf(stderr, "glyph_fuzz: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace aabench;
    TextSpec spec;
    spec.font = "fuzzed";
    // Every ASCII letter class the glyph tables hold: on-curve, off-curve, composite glyphs.
    spec.string = "Ag%0 @";
    spec.size_px = 13.7;
    spec.origin = {2.5, 20.25};
    spec.kerning = size % 2 == 1;
    try {
        const std::vector<SegmentContour> outline =
            text_outline_from_memory(spec, std::span<const unsigned char>(data, size), "fuzzed");
        for (const SegmentContour& c : outline) {
            for (const Segment& s : c) {
                for (int k = 0; k <= s.degree; ++k) {
                    if (!std::isfinite(s.p[k].x) || !std::isfinite(s.p[k].y)) {
                        violation("a non-finite glyph point");
                    }
                }
            }
        }
        if (!outline.empty()) (void)bezier_shape(outline, 1.0);
    } catch (const TextError&) {
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "glyph_fuzz: %s\n", e.what());
        violation("an outline bezier_shape refuses (open contour)");
    }
    return 0;
}
