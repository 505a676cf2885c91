// Text in scenes (scene file version 4, `"type": "text"`, docs/scene-format.md): a string set
// in a font and expanded into its glyphs' exact outlines, the quadratic segments of a TrueType
// font or the cubic ones of a CFF font, as curve contours (bezier.h).
//
// How a glyph becomes segments. FreeType (the font's parser) loads each glyph unhinted and
// unscaled (FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING: points in font units, as the font stores
// them); the points are scaled here in double by size_px / units_per_EM, not rounded to
// FreeType's 26.6 fixed point, x to the right of the pen, y flipped (fonts are y up, the pixel
// frame y down). Contours are decomposed here, not by FT_Outline_Decompose: TrueType's implied
// on-curve point between two off-curve points is their midpoint, computed in double, where
// FT_Outline_Decompose hands out integer midpoints (truncated in font units, about 1e-5 of a
// glyph's area). Zero-length straight edges are dropped; a contour that encloses nothing (one
// point, or out and back along one line) is left out.
//
// Layout: one line from the pen position `origin` (on the baseline), each glyph at the pen,
// the pen then moved by the glyph's advance (the font's horizontal metrics), plus the kerning
// of the pair (the font's `kern` table through FT_Get_Kerning, when `kerning` is set and the
// font has one; GPOS kerning is not read) and `letter_spacing_px`. No shaping: one glyph per
// code point (FT_Get_Char_Index), left to right.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

inline constexpr double kMinTextSizePx = 0.5;
inline constexpr double kMaxTextSizePx = 2048.0;

struct TextSpec {
    std::string font;    // a name of font_table() or a font file's path
    std::string string;  // UTF-8
    double size_px = 12.0;
    Point origin;  // the pen's start on the baseline
    bool kerning = false;
    double letter_spacing_px = 0.0;
};

// The built-in font names: DejaVu (fonts-dejavu-core, TrueType: quadratics) and URW's Nimbus
// (fonts-urw-base35, OpenType CFF: cubics).
struct FontName {
    const char* name;
    const char* path;
    const char* what;
};
std::span<const FontName> font_table();

// The file `font` names: the table's path for a built-in name, else `font` itself, taken
// relative to `folder` when it is a relative path.
std::string font_file(const std::string& font, const std::string& folder);

// A bad text: `field()` names the spec's key at fault ("font", "string", "size_px",
// "letter_spacing_px") for the reader's message; what() is one line.
class TextError : public std::runtime_error {
public:
    TextError(std::string field, const std::string& what)
        : std::runtime_error(what), field_(std::move(field)) {}
    const std::string& field() const { return field_; }

private:
    std::string field_;
};

// The text's outline in the pixel frame: every glyph's contours, in string order. Reads the
// font from `font_path`. Throws TextError.
std::vector<SegmentContour> text_outline(const TextSpec& spec, const std::string& font_path);
// The same from a font file's bytes (the fuzz target's entry: no file). `font_name` only
// names the font in messages.
std::vector<SegmentContour> text_outline_from_memory(const TextSpec& spec,
                                                     std::span<const unsigned char> font_bytes,
                                                     const std::string& font_name);

// The code points of a UTF-8 string; throws TextError("string", ...) naming the byte offset of
// an invalid sequence (overlong forms, surrogates and values past U+10FFFF are invalid).
std::vector<char32_t> decode_utf8(const std::string& text);

// The version string of the FreeType library linked ("2.12.1").
std::string freetype_version();

}  // namespace aabench
