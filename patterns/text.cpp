// `text` and `text-cff`: a waterfall of one sample line set at 6, 7, 8, 9, 10, 12, 14, 16,
// 20 and 24 px per em (value 1 on background 0), in a TrueType font (quadratic outlines) or a
// CFF one (cubics), through patterns/scene/text.h.
//
// Aliasing it provokes: small text is where every symptom meets. The stems of the 6-8 px
// lines are thinner than a pixel (thin objects: they break up under point sampling, and a
// method that loses coverage loses them); dots, serifs and counters are small objects that pop
// as the line moves by a fraction of a pixel; bowls and shoulders are curves at every angle,
// where a flattening method cuts its chords inside the arcs. The sizes are pixels, not
// fractions of the image: the lines are laid out from the top left at a fixed line height, and
// what the image cannot hold is cut off (at 64 x 64 only the smallest lines show).
//
// Line k (size s_k) has its pen at x = kMarginPx + phase_px, its baseline kLineHeight s below
// the previous one's (the first at kMarginPx + s_0); kerning from the font's kern table.
//
// Thin objects (Scene::thin_objects): every line, labelled "line <size> px".
//
// Parameters:
//   font      sans (text) or cff-sans (text-cff); any name of the built-in font table
//   sample    hamburgefonstiv  the sample line: hamburgefonstiv | quick-fox | digits
//   phase_px  0.3183  the pen's sub-pixel x phase
//
// `text-page` (not in the default run): a page of one size, `size_px` (12), what a reader
// sees, white on black or (`ink=black`) black on white: lines of the sample repeated (words
// apart by a space) across the whole image width,
// one below the other at the same line height until the image is full. Each line is a shape
// and a thin object ("line <k>"); contours that start right of the image are left out (they
// draw nothing in it). Run at one size after another it gives every figure by size.
#include "patterns/scene/text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

constexpr std::array<double, 10> kSizesPx = {6, 7, 8, 9, 10, 12, 14, 16, 20, 24};
constexpr double kMarginPx = 4.0;
// Baseline to baseline, in ems: about what a text layout sets (1.2 to 1.3).
constexpr double kLineHeight = 1.25;

struct Sample {
    const char* name;
    const char* text;
};
// "Hamburgefonstiv" is the type designers' test word (the letters whose shapes make the rest);
// the pangram has every lower-case letter; the digits are what dashboards draw small.
constexpr Sample kSamples[] = {
    {"hamburgefonstiv", "Hamburgefonstiv"},
    {"quick-fox", "The quick brown fox jumps"},
    {"digits", "0123456789"},
};

// The text of the sample named `name` (a validated choice).
const char* sample_text(const std::string& name) {
    for (const Sample& s : kSamples) {
        if (name == s.name) return s.text;
    }
    return kSamples[0].text;
}

// The samples' names with `first` first (the first choice is the default).
std::vector<std::string> sample_names(const std::string& first) {
    std::vector<std::string> names = {first};
    for (const Sample& s : kSamples) {
        if (s.name != first) names.push_back(s.name);
    }
    return names;
}

// One kerned line of `string` at `size_px`, the pen at x = kMarginPx + phase on `baseline`.
std::vector<SegmentContour> line_outline(const std::string& id, const std::string& font,
                                         const std::string& file, const std::string& string,
                                         double size, double phase, double baseline) {
    TextSpec spec;
    spec.font = font;
    spec.string = string;
    spec.size_px = size;
    spec.origin = {kMarginPx + phase, baseline};
    spec.kerning = true;
    try {
        return text_outline(spec, file);
    } catch (const TextError& e) {
        throw InputError(fmt::format("pattern '{}': {}", id, e.what()));
    }
}

std::vector<std::string> font_names() {
    std::vector<std::string> names;
    for (const FontName& f : font_table()) names.push_back(f.name);
    return names;
}

Scene generate_text(const std::string& id, const ParamValues& values, int width, int height) {
    const std::string& font = values.get_choice("font");
    const std::string& sample = values.get_choice("sample");
    const double phase = values.get_real("phase_px");
    const std::string string = sample_text(sample);
    const std::string file = font_file(font, "");
    Scene scene = begin_pattern_scene(id, values, width, height);
    double baseline = kMarginPx;
    for (std::size_t k = 0; k < kSizesPx.size(); ++k) {
        const double size = kSizesPx[k];
        baseline += k == 0 ? size : kLineHeight * size;
        Shape shape =
            bezier_shape(line_outline(id, font, file, string, size, phase, baseline), 1.0);
        scene.thin_objects.push_back({fmt::format("line {:g} px", size), shape});
        scene.shapes.push_back(std::move(shape));
    }
    // The smallest line's first letters.
    set_focus(scene, kMarginPx + 0.5 * kFocusSidePx, kMarginPx + 0.5 * kSizesPx[0], kFocusSidePx);
    return scene;
}

// The narrowest advance of a glyph and its share of a space, in ems, that a line can have on
// average (DejaVu's and Nimbus's "i" and "l" are about 0.28 em): a string of width / (this x
// size) characters fills any line of the image.
constexpr double kMinMeanAdvanceEm = 0.2;

Scene generate_text_page(const std::string& id, const ParamValues& values, int width,
                         int height) {
    const std::string& font = values.get_choice("font");
    const std::string& sample = values.get_choice("sample");
    const double size = values.get_real("size_px");
    const double phase = values.get_real("phase_px");
    const bool black_ink = values.get_choice("ink") == "black";
    const std::string word = sample_text(sample);
    const double chars_needed = std::ceil(width / (kMinMeanAdvanceEm * size)) + 1.0;
    std::string line_text = word;
    while (static_cast<double>(line_text.size()) < chars_needed) line_text += " " + word;
    Scene scene = begin_pattern_scene(id, values, width, height);
    scene.background = black_ink ? 1.0 : 0.0;
    const std::string file = font_file(font, "");
    int line = 0;
    std::size_t vertices = 0;  // of the flattened view, as the other generators count
    for (double baseline = kMarginPx + size; baseline - size < height;
         baseline += kLineHeight * size) {
        std::vector<SegmentContour> outline =
            line_outline(id, font, file, line_text, size, phase, baseline);
        std::erase_if(outline, [width](const SegmentContour& contour) {
            double x_min = contour.front().p[0].x;
            for (const Segment& seg : contour) {
                for (int q = 0; q <= seg.degree; ++q) x_min = std::min(x_min, seg.p[q].x);
            }
            return x_min >= width;
        });
        if (outline.empty()) break;
        Shape shape = bezier_shape(std::move(outline), black_ink ? 0.0 : 1.0);
        for (const Contour& contour : shape.contours) vertices += contour.size();
        if (vertices > kMaxPatternVertices) {
            throw InputError(fmt::format(
                "pattern '{}': more than {} vertices by line {}; raise size_px ({:g}) or make "
                "the image smaller",
                id, kMaxPatternVertices, line + 1, size));
        }
        scene.thin_objects.push_back({fmt::format("line {}", ++line), shape});
        scene.shapes.push_back(std::move(shape));
    }
    set_focus(scene, kMarginPx + 0.5 * kFocusSidePx, kMarginPx + 0.5 * size, kFocusSidePx);
    return scene;
}

PatternInfo text_pattern_row(const std::string& id, const std::string& font, const char* summary) {
    std::vector<std::string> fonts = font_names();
    // The row's own font first: the first choice is the default.
    std::erase(fonts, font);
    fonts.insert(fonts.begin(), font);
    const std::vector<std::string> samples = sample_names(kSamples[0].name);
    return PatternInfo{
        id,
        summary,
        // clang-format off
        {
            {"font", ParamKind::kChoice, 0, 0, 0, fonts,
             "the font: DejaVu sans/serif/mono (TrueType, quadratics) or URW Nimbus "
             "cff-sans/cff-serif (OpenType CFF, cubics)"},
            {"sample", ParamKind::kChoice, 0, 0, 0, samples,
             "the sample line: Hamburgefonstiv, a pangram's start, or the digits"},
            {"phase_px", ParamKind::kReal, 0.3183, 0.0, 1.0, {},
             "the pen's sub-pixel x phase; off the grid so no stem lines up with a pixel border"},
        },
        // clang-format on
        [id](const ParamValues& values, int width, int height) {
            return generate_text(id, values, width, height);
        },
        /*in_default_run=*/true,
        /*bezier=*/true,
    };
}

}  // namespace

PatternInfo text_pattern() {
    return text_pattern_row(
        "text", "sans",
        "a waterfall of one line at 6 to 24 px in DejaVu Sans (TrueType quadratics); stems "
        "thinner than a pixel, dots and counters that pop");
}

PatternInfo text_page_pattern() {
    // Prose by default: a page of words, not of one test word.
    const std::vector<std::string> samples = sample_names("quick-fox");
    return PatternInfo{
        "text-page",
        "a page of text at one size (12 px): lines of the sample across the whole image, "
        "what a reader sees; run at each size for the figures by size",
        // clang-format off
        {
            {"font", ParamKind::kChoice, 0, 0, 0, font_names(),
             "the font: DejaVu sans/serif/mono (TrueType, quadratics) or URW Nimbus "
             "cff-sans/cff-serif (OpenType CFF, cubics)"},
            {"sample", ParamKind::kChoice, 0, 0, 0, samples,
             "the words repeated along each line"},
            {"size_px", ParamKind::kReal, 12, 4, 96, {},
             "the text size, px per em; lines 1.25 em apart"},
            {"phase_px", ParamKind::kReal, 0.3183, 0.0, 1.0, {},
             "the pen's sub-pixel x phase; off the grid so no stem lines up with a pixel border"},
            {"ink", ParamKind::kChoice, 0, 0, 0, {"white", "black"},
             "white text on black (value 1 on 0, as every pattern) or black on white paper "
             "(0 on 1): blending in sRGB codes thins the one and bolds the other"},
        },
        // clang-format on
        [](const ParamValues& values, int width, int height) {
            return generate_text_page("text-page", values, width, height);
        },
        /*in_default_run=*/false,
        /*bezier=*/true,
    };
}

PatternInfo text_cff_pattern() {
    return text_pattern_row("text-cff", "cff-sans",
                            "the same waterfall in URW Nimbus Sans (OpenType CFF cubics)");
}

}  // namespace aabench
