// Text expanded into glyph outlines through FreeType (text.h).
#include "patterns/scene/text.h"

#include <fmt/format.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>

#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// The largest font file read (the largest fonts people ship, CJK collections, are ~60 MiB).
constexpr std::uintmax_t kMaxFontBytes = std::uintmax_t{256} << 20;

constexpr FontName kFonts[] = {
    {"sans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "DejaVu Sans (TrueType)"},
    {"serif", "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf", "DejaVu Serif (TrueType)"},
    {"mono", "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf", "DejaVu Sans Mono (TrueType)"},
    {"cff-sans", "/usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf",
     "Nimbus Sans (OpenType CFF)"},
    {"cff-serif", "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf",
     "Nimbus Roman (OpenType CFF)"},
};

// FreeType's library and one face, released together.
struct FreeTypeFace {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~FreeTypeFace() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

std::string code_point_name(char32_t c) {
    std::string name = fmt::format("U+{:04X}", static_cast<unsigned>(c));
    if (c >= 0x21 && c < 0x7f) name += fmt::format(" '{}'", static_cast<char>(c));
    return name;
}

struct Vec {
    double x, y;
};

// One glyph's outline (font units) into pixel-frame segment contours: x = pen + x s,
// y = baseline - y s.
class GlyphDecomposer {
public:
    GlyphDecomposer(double pen_x, double baseline, double scale)
        : pen_x_(pen_x), baseline_(baseline), scale_(scale) {}

    void add(const FT_Outline& outline, std::vector<SegmentContour>& out) const {
        int first = 0;
        for (int c = 0; c < outline.n_contours; ++c) {
            const int last = outline.contours[c];
            if (last < first || last >= outline.n_points) return;  // a broken outline: no more
            SegmentContour contour = decompose(outline, first, last);
            if (encloses_something(contour)) out.push_back(std::move(contour));
            first = last + 1;
        }
    }

private:
    Point to_pixels(Vec v) const { return {pen_x_ + v.x * scale_, baseline_ - v.y * scale_}; }

    static bool encloses_something(const SegmentContour& c) {
        if (c.size() >= 3) return true;
        for (const Segment& s : c) {
            if (s.degree > 1) return true;
        }
        return false;
    }

    // The contour's points first..last as segments: TrueType's conic (quadratic) controls,
    // with implied on-curve midpoints between two of them, and CFF's pairs of cubic controls.
    // An ill-formed sequence (a cubic control alone, a contour of controls only with a cubic
    // one) ends the contour there, closed by a straight edge, as a parser of a broken font
    // must do something definite.
    SegmentContour decompose(const FT_Outline& outline, int first, int last) const {
        struct Item {
            Vec p;
            int tag;
        };
        std::vector<Item> items;
        const int n = last - first + 1;
        int start = -1;
        for (int k = 0; k < n; ++k) {
            const FT_Vector& v = outline.points[first + k];
            const int tag = FT_CURVE_TAG(outline.tags[first + k]);
            items.push_back({{static_cast<double>(v.x), static_cast<double>(v.y)}, tag});
            if (start < 0 && tag == FT_CURVE_TAG_ON) start = k;
        }
        std::vector<Item> seq;
        if (start >= 0) {
            seq.insert(seq.end(), items.begin() + start, items.end());
            seq.insert(seq.end(), items.begin(), items.begin() + start);
        } else {
            // Only off-curve points: the contour starts at the midpoint of the last and first.
            const Vec a = items.back().p, b = items.front().p;
            seq.push_back({{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}, FT_CURVE_TAG_ON});
            seq.insert(seq.end(), items.begin(), items.end());
        }
        seq.push_back(seq.front());  // back to the start: the last segment closes the contour
        SegmentContour contour;
        Vec cur = seq.front().p;
        auto same = [](Vec a, Vec b) { return a.x == b.x && a.y == b.y; };
        auto line_to = [&](Vec p) {
            if (!same(cur, p)) contour.push_back(line_segment(to_pixels(cur), to_pixels(p)));
            cur = p;
        };
        std::size_t i = 1;
        while (i < seq.size()) {
            const Item& item = seq[i];
            if (item.tag == FT_CURVE_TAG_ON) {
                line_to(item.p);
                ++i;
            } else if (item.tag == FT_CURVE_TAG_CONIC) {
                Vec control = item.p;
                ++i;
                while (true) {
                    const Item& next = seq[i];  // the last item is on-curve: i stays in range
                    if (next.tag == FT_CURVE_TAG_CUBIC) return close(contour, cur, seq.front().p);
                    const bool on = next.tag == FT_CURVE_TAG_ON;
                    const Vec end =
                        on ? next.p
                           : Vec{0.5 * (control.x + next.p.x), 0.5 * (control.y + next.p.y)};
                    contour.push_back(
                        quad_segment(to_pixels(cur), to_pixels(control), to_pixels(end)));
                    cur = end;
                    if (on) {
                        ++i;
                        break;
                    }
                    control = next.p;
                    ++i;
                }
            } else {
                if (i + 2 >= seq.size() || seq[i + 1].tag != FT_CURVE_TAG_CUBIC ||
                    seq[i + 2].tag != FT_CURVE_TAG_ON) {
                    return close(contour, cur, seq.front().p);
                }
                contour.push_back(cubic_segment(to_pixels(cur), to_pixels(item.p),
                                                to_pixels(seq[i + 1].p), to_pixels(seq[i + 2].p)));
                cur = seq[i + 2].p;
                i += 3;
            }
        }
        return contour;
    }

    SegmentContour close(SegmentContour& contour, Vec cur, Vec start) const {
        if (cur.x != start.x || cur.y != start.y) {
            contour.push_back(line_segment(to_pixels(cur), to_pixels(start)));
        }
        return std::move(contour);
    }

    double pen_x_, baseline_, scale_;
};

std::vector<SegmentContour> lay_out(const TextSpec& spec, FT_Face face, const std::string& name) {
    if (!(spec.size_px >= kMinTextSizePx && spec.size_px <= kMaxTextSizePx)) {
        throw TextError("size_px", fmt::format("{:g} px is outside {:g}..{:g} px", spec.size_px,
                                               kMinTextSizePx, kMaxTextSizePx));
    }
    if (!std::isfinite(spec.letter_spacing_px)) {
        throw TextError("letter_spacing_px", "expected a finite number");
    }
    if (!FT_IS_SCALABLE(face) || face->units_per_EM == 0) {
        throw TextError("font", fmt::format("{} has no outlines (a bitmap font)", name));
    }
    const std::vector<char32_t> text = decode_utf8(spec.string);
    if (text.empty()) throw TextError("string", "an empty string draws nothing");
    const double scale = spec.size_px / face->units_per_EM;
    const bool kern = spec.kerning && FT_HAS_KERNING(face);
    std::vector<SegmentContour> out;
    double pen = spec.origin.x;
    FT_UInt previous = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const FT_UInt glyph = FT_Get_Char_Index(face, text[k]);
        if (glyph == 0) {
            throw TextError("string", fmt::format("{} has no glyph for {} (character {})", name,
                                                  code_point_name(text[k]), k + 1));
        }
        if (kern && previous != 0) {
            FT_Vector delta{};
            if (FT_Get_Kerning(face, previous, glyph, FT_KERNING_UNSCALED, &delta) == 0) {
                pen += static_cast<double>(delta.x) * scale;
            }
        }
        const FT_Error error =
            FT_Load_Glyph(face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
        if (error != 0) {
            throw TextError("font", fmt::format("{}: cannot load the glyph of {} (FreeType error "
                                                "0x{:02X})",
                                                name, code_point_name(text[k]), error));
        }
        const FT_GlyphSlot slot = face->glyph;
        if (slot->format == FT_GLYPH_FORMAT_OUTLINE) {
            GlyphDecomposer(pen, spec.origin.y, scale).add(slot->outline, out);
        }
        pen += static_cast<double>(slot->metrics.horiAdvance) * scale + spec.letter_spacing_px;
        previous = glyph;
    }
    if (out.empty()) throw TextError("string", "the string draws no glyph outline");
    return out;
}

std::string open_error(FT_Error error) {
    if (error == FT_Err_Unknown_File_Format) return "not a font file FreeType reads";
    return fmt::format("not a font file FreeType reads (FreeType error 0x{:02X})", error);
}

}  // namespace

std::span<const FontName> font_table() { return kFonts; }

std::string font_file(const std::string& font, const std::string& folder) {
    for (const FontName& f : kFonts) {
        if (font == f.name) return f.path;
    }
    const std::filesystem::path path(font);
    if (path.is_absolute() || folder.empty()) return font;
    return (std::filesystem::path(folder) / path).string();
}

std::vector<char32_t> decode_utf8(const std::string& text) {
    std::vector<char32_t> out;
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    for (std::size_t k = 0; k < n;) {
        const unsigned char b = s[k];
        int length = 0;
        char32_t c = 0, min = 0;
        if (b < 0x80) {
            length = 1, c = b;
        } else if ((b & 0xE0) == 0xC0) {
            length = 2, c = b & 0x1F, min = 0x80;
        } else if ((b & 0xF0) == 0xE0) {
            length = 3, c = b & 0x0F, min = 0x800;
        } else if ((b & 0xF8) == 0xF0) {
            length = 4, c = b & 0x07, min = 0x10000;
        }
        bool ok = length > 0 && k + length <= n;
        for (int m = 1; ok && m < length; ++m) {
            ok = (s[k + m] & 0xC0) == 0x80;
            c = (c << 6) | (s[k + m] & 0x3F);
        }
        if (!ok || c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
            throw TextError("string", fmt::format("invalid UTF-8 at byte {}", k + 1));
        }
        out.push_back(c);
        k += length;
    }
    return out;
}

std::vector<SegmentContour> text_outline(const TextSpec& spec, const std::string& font_path) {
    // Read here, so that a missing or unreadable file says why in the system's words. Only a
    // regular file of at most kMaxFontBytes: a device or a pipe (/dev/zero) would never end.
    std::error_code error;
    const bool regular = std::filesystem::is_regular_file(font_path, error);
    if (!error && std::filesystem::exists(font_path, error) && !regular) {
        throw TextError("font", fmt::format("{} is not a regular file", font_path));
    }
    if (regular && std::filesystem::file_size(font_path, error) > kMaxFontBytes) {
        throw TextError("font", fmt::format("{} is larger than {} MiB: not a font", font_path,
                                            kMaxFontBytes >> 20));
    }
    std::ifstream file(font_path, std::ios::binary);
    if (!file) {
        throw TextError(
            "font", fmt::format("cannot open font file {}: {}", font_path, std::strerror(errno)));
    }
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)),
                                           std::istreambuf_iterator<char>());
    if (file.bad()) {
        throw TextError("font", fmt::format("cannot read font file {}", font_path));
    }
    return text_outline_from_memory(spec, bytes, font_path);
}

std::vector<SegmentContour> text_outline_from_memory(const TextSpec& spec,
                                                     std::span<const unsigned char> font_bytes,
                                                     const std::string& font_name) {
    FreeTypeFace ft;
    if (FT_Init_FreeType(&ft.library) != 0) throw TextError("font", "FreeType did not start");
    const FT_Error error = FT_New_Memory_Face(ft.library, font_bytes.data(),
                                              static_cast<FT_Long>(font_bytes.size()), 0, &ft.face);
    if (error != 0) {
        throw TextError("font", fmt::format("{}: {}", font_name, open_error(error)));
    }
    return lay_out(spec, ft.face, font_name);
}

std::string freetype_version() {
    FreeTypeFace ft;
    if (FT_Init_FreeType(&ft.library) != 0) return "unknown";
    FT_Int major = 0, minor = 0, patch = 0;
    FT_Library_Version(ft.library, &major, &minor, &patch);
    return fmt::format("{}.{}.{}", major, minor, patch);
}

}  // namespace aabench
