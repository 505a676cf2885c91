// Text shapes (patterns/scene/text.h) against fonts read without FreeType: a TrueType parser
// written here from the OpenType specification (the table directory, head, maxp, hhea, hmtx,
// cmap format 4, loca and glyf's simple glyphs), and stb_truetype's own CFF interpreter for
// the cubic font. Every segment's points must match after the documented scaling; and the
// reader's checks (UTF-8, missing glyphs, sizes, fonts) each refuse in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "patterns/scene/bezier.h"
#include "patterns/scene/text.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>
#pragma GCC diagnostic pop

namespace aabench {
namespace {

// Both sides scale the same font units by the same double factor and add the same pen: the
// only difference can be the order of two roundings, ~1e-13 px at these sizes.
constexpr double kPointTolerancePx = 1e-9;

const char* const kSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const char* const kCffSans = "/usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf";

std::vector<unsigned char> read_file(const char* path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// ---- A TrueType reader of its own ----

class TrueType {
public:
    explicit TrueType(std::vector<unsigned char> bytes) : b_(std::move(bytes)) {
        const int tables = u16(4);
        for (int k = 0; k < tables; ++k) {
            const std::size_t r = 12 + 16 * static_cast<std::size_t>(k);
            tables_[std::string(reinterpret_cast<const char*>(&b_[r]), 4)] = u32(r + 8);
        }
        units_per_em = u16(tables_.at("head") + 18);
        long_loca_ = s16(tables_.at("head") + 50) != 0;
        metrics_ = u16(tables_.at("hhea") + 34);
    }

    int units_per_em = 0;

    // cmap (3, 1) format 4.
    int glyph_of(char32_t c) const {
        const std::size_t cmap = tables_.at("cmap");
        std::size_t sub = 0;
        for (unsigned k = 0; k < u16(cmap + 2); ++k) {
            const std::size_t r = cmap + 4 + 8 * static_cast<std::size_t>(k);
            if (u16(r) == 3 && u16(r + 2) == 1) sub = cmap + u32(r + 4);
        }
        if (sub == 0 || u16(sub) != 4) return 0;
        const int segments = u16(sub + 6) / 2;
        const std::size_t ends = sub + 14, starts = ends + 2 * segments + 2;
        const std::size_t deltas = starts + 2 * segments, ranges = deltas + 2 * segments;
        for (int i = 0; i < segments; ++i) {
            const unsigned end = u16(ends + 2 * i), start = u16(starts + 2 * i);
            if (c > end) continue;
            if (c < start) return 0;
            const int delta = s16(deltas + 2 * i);
            const unsigned range = u16(ranges + 2 * i);
            if (range == 0) return static_cast<int>((c + delta) & 0xFFFF);
            const std::size_t at = ranges + 2 * i + range + 2 * (c - start);
            const unsigned g = u16(at);
            return g == 0 ? 0 : static_cast<int>((g + delta) & 0xFFFF);
        }
        return 0;
    }

    int advance(int glyph) const {
        const int m = glyph < metrics_ ? glyph : metrics_ - 1;
        return u16(tables_.at("hmtx") + 4 * static_cast<std::size_t>(m));
    }

    struct RawPoint {
        double x, y;
        bool on;
    };
    // A simple glyph's contours of points; false for a composite glyph.
    bool contours(int glyph, std::vector<std::vector<RawPoint>>& out) const {
        out.clear();
        const std::size_t loca = tables_.at("loca");
        const std::size_t start = long_loca_ ? u32(loca + 4 * glyph) : 2u * u16(loca + 2 * glyph);
        const std::size_t end =
            long_loca_ ? u32(loca + 4 * (glyph + 1)) : 2u * u16(loca + 2 * (glyph + 1));
        if (end == start) return true;  // no outline (a space)
        std::size_t p = tables_.at("glyf") + start;
        const int n = s16(p);
        if (n < 0) return false;
        std::vector<int> ends;
        for (int k = 0; k < n; ++k) ends.push_back(u16(p + 10 + 2 * k));
        const int points = n == 0 ? 0 : ends.back() + 1;
        p += 10 + 2 * n;
        p += 2 + u16(p);  // instructions
        std::vector<unsigned char> flags;
        while (static_cast<int>(flags.size()) < points) {
            const unsigned char f = b_[p++];
            flags.push_back(f);
            if (f & 8) {
                for (int r = b_[p++]; r > 0; --r) flags.push_back(f);
            }
        }
        std::vector<int> xs(points), ys(points);
        for (int axis = 0; axis < 2; ++axis) {
            const unsigned char short_bit = axis == 0 ? 2 : 4, same_bit = axis == 0 ? 16 : 32;
            int v = 0;
            for (int k = 0; k < points; ++k) {
                const unsigned char f = flags[k];
                if (f & short_bit) {
                    const int d = b_[p++];
                    v += (f & same_bit) ? d : -d;
                } else if (!(f & same_bit)) {
                    v += s16(p);
                    p += 2;
                }
                (axis == 0 ? xs : ys)[k] = v;
            }
        }
        int first = 0;
        for (int e : ends) {
            std::vector<RawPoint> c;
            for (int k = first; k <= e; ++k)
                c.push_back({double(xs[k]), double(ys[k]), (flags[k] & 1) != 0});
            out.push_back(c);
            first = e + 1;
        }
        return true;
    }

private:
    unsigned u16(std::size_t at) const { return (b_[at] << 8) | b_[at + 1]; }
    int s16(std::size_t at) const { return static_cast<std::int16_t>(u16(at)); }
    std::size_t u32(std::size_t at) const {
        return (std::size_t{b_[at]} << 24) | (b_[at + 1] << 16) | (b_[at + 2] << 8) | b_[at + 3];
    }
    std::vector<unsigned char> b_;
    std::map<std::string, std::size_t> tables_;
    bool long_loca_ = false;
    int metrics_ = 0;
};

// The TrueType rule (the spec's): between two off-curve points lies an implied on-curve point
// halfway; a contour starts at its first on-curve point (or, with none, at the midpoint of its
// last and first points) and closes back to it.
SegmentContour segments_of(const std::vector<TrueType::RawPoint>& raw, double pen, double base,
                           double s) {
    auto px = [&](double x, double y) { return Point{pen + x * s, base - y * s}; };
    std::vector<TrueType::RawPoint> seq;
    std::size_t first_on = raw.size();
    for (std::size_t k = 0; k < raw.size(); ++k) {
        if (raw[k].on) {
            first_on = k;
            break;
        }
    }
    if (first_on == raw.size()) {
        seq.push_back(
            {0.5 * (raw.back().x + raw.front().x), 0.5 * (raw.back().y + raw.front().y), true});
        seq.insert(seq.end(), raw.begin(), raw.end());
    } else {
        seq.insert(seq.end(), raw.begin() + first_on, raw.end());
        seq.insert(seq.end(), raw.begin(), raw.begin() + first_on);
    }
    seq.push_back(seq.front());
    SegmentContour out;
    TrueType::RawPoint cur = seq.front();
    for (std::size_t i = 1; i < seq.size(); ++i) {
        if (seq[i].on) {
            if (seq[i].x != cur.x || seq[i].y != cur.y)
                out.push_back(line_segment(px(cur.x, cur.y), px(seq[i].x, seq[i].y)));
            cur = seq[i];
            continue;
        }
        const TrueType::RawPoint& next = seq[i + 1];
        const TrueType::RawPoint end =
            next.on
                ? next
                : TrueType::RawPoint{0.5 * (seq[i].x + next.x), 0.5 * (seq[i].y + next.y), true};
        out.push_back(quad_segment(px(cur.x, cur.y), px(seq[i].x, seq[i].y), px(end.x, end.y)));
        cur = end;
        if (next.on) ++i;
    }
    return out;
}

void expect_same_outline(const std::vector<SegmentContour>& got,
                         const std::vector<SegmentContour>& want, const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t c = 0; c < got.size(); ++c) {
        ASSERT_EQ(got[c].size(), want[c].size()) << what << " contour " << c;
        for (std::size_t k = 0; k < got[c].size(); ++k) {
            ASSERT_EQ(got[c][k].degree, want[c][k].degree)
                << what << " contour " << c << " seg " << k;
            for (int i = 0; i <= got[c][k].degree; ++i) {
                EXPECT_NEAR(got[c][k].p[i].x, want[c][k].p[i].x, kPointTolerancePx) << what;
                EXPECT_NEAR(got[c][k].p[i].y, want[c][k].p[i].y, kPointTolerancePx) << what;
            }
        }
    }
}

bool encloses_something(const SegmentContour& c) {
    if (c.size() >= 3) return true;
    for (const Segment& s : c) {
        if (s.degree > 1) return true;
    }
    return false;
}

TEST(TextOutline, TrueTypeGlyphsMatchAnIndependentParser) {
    const TrueType font(read_file(kSans));
    int simple = 0;
    for (const double size : {7.0, 12.5, 31.0}) {
        TextSpec spec;
        spec.font = "sans";
        spec.string = "Hamburgefonstiv QWERTY 0123456789 ,.;@&%";
        spec.size_px = size;
        spec.origin = {3.3183, 40.2719};
        const std::vector<SegmentContour> got = text_outline(spec, font_file("sans", ""));
        // The same text from the parser above: every glyph simple here (checked).
        const double s = size / font.units_per_em;
        std::vector<SegmentContour> want;
        double pen = spec.origin.x;
        std::vector<std::vector<TrueType::RawPoint>> raw;
        for (const char ch : spec.string) {
            const int glyph = font.glyph_of(static_cast<unsigned char>(ch));
            ASSERT_NE(glyph, 0) << ch;
            ASSERT_TRUE(font.contours(glyph, raw)) << "a composite glyph: " << ch;
            for (const auto& c : raw) {
                SegmentContour seg = segments_of(c, pen, spec.origin.y, s);
                if (encloses_something(seg)) want.push_back(seg);
            }
            if (!raw.empty()) ++simple;
            pen += font.advance(glyph) * s;
        }
        expect_same_outline(got, want, "size " + std::to_string(size));
    }
    EXPECT_GT(simple, 90);
}

// An implied on-curve point is the midpoint in double: the outline is closed and its area
// (Green's theorem on the exact segments) changes sign with nothing but the glyph.
TEST(TextOutline, ImpliedPointsAreExactMidpoints) {
    TextSpec spec{"sans", "o", 1000.0, {0.0, 0.0}};
    const std::vector<SegmentContour> o = text_outline(spec, font_file("sans", ""));
    ASSERT_EQ(o.size(), 2u);  // the bowl and the counter
    for (const SegmentContour& c : o) {
        for (std::size_t k = 1; k + 1 < c.size(); ++k) {
            const Segment& a = c[k];
            const Segment& b = c[k + 1];
            if (a.degree != 2 || b.degree != 2) continue;
            // An end shared by two quadratics that is their controls' midpoint is implied.
            const Point m{0.5 * (a.p[1].x + b.p[1].x), 0.5 * (a.p[1].y + b.p[1].y)};
            if (std::abs(m.x - a.p[2].x) < 1e-6 && std::abs(m.y - a.p[2].y) < 1e-6) {
                EXPECT_EQ(a.p[2].x, m.x);
                EXPECT_EQ(a.p[2].y, m.y);
            }
        }
    }
    // Outer and inner contours wind opposite ways.
    EXPECT_LT(twice_signed_area(o[0]) * twice_signed_area(o[1]), 0.0);
}

// The CFF font's cubics against stb_truetype's charstring interpreter (font units; these
// fonts' points are whole units, which stb's int16 vertices hold exactly).
TEST(TextOutline, CffGlyphsMatchStbTruetypesInterpreter) {
    std::vector<unsigned char> bytes = read_file(kCffSans);
    stbtt_fontinfo info;
    ASSERT_TRUE(stbtt_InitFont(&info, bytes.data(), stbtt_GetFontOffsetForIndex(bytes.data(), 0)));
    TextSpec spec;
    spec.font = "cff-sans";
    spec.string = "Hamburgefonstiv";
    spec.size_px = 1000.0;  // the font's units per em: one unit a pixel
    spec.origin = {0.0, 0.0};
    const std::vector<SegmentContour> got = text_outline(spec, font_file("cff-sans", ""));
    std::vector<SegmentContour> want;
    double pen = 0.0;
    int cubics = 0;
    for (const char ch : spec.string) {
        stbtt_vertex* v = nullptr;
        const int n = stbtt_GetCodepointShape(&info, ch, &v);
        auto px = [&](double x, double y) { return Point{pen + x, -y}; };
        SegmentContour c;
        Point cur{}, start{};
        auto flush = [&] {
            if (!c.empty() && (cur.x != start.x || cur.y != start.y))
                c.push_back(line_segment(cur, start));
            if (encloses_something(c)) want.push_back(c);
            c.clear();
        };
        for (int k = 0; k < n; ++k) {
            const Point p = px(v[k].x, v[k].y);
            if (v[k].type == STBTT_vmove) {
                flush();
                cur = start = p;
            } else if (v[k].type == STBTT_vline) {
                if (p.x != cur.x || p.y != cur.y) c.push_back(line_segment(cur, p));
                cur = p;
            } else if (v[k].type == STBTT_vcubic) {
                c.push_back(cubic_segment(cur, px(v[k].cx, v[k].cy), px(v[k].cx1, v[k].cy1), p));
                cur = p;
                ++cubics;
            }
        }
        flush();
        stbtt_FreeShape(&info, v);
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&info, ch, &advance, &bearing);
        pen += advance;
    }
    EXPECT_GT(cubics, 50);
    expect_same_outline(got, want, "Nimbus Sans");
}

TEST(TextOutline, BadTextIsRefusedNamingTheField) {
    auto field_of = [](TextSpec spec, const std::string& path) {
        try {
            text_outline(spec, path);
        } catch (const TextError& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            return e.field() + ": " + e.what();
        }
        return std::string("accepted");
    };
    const std::string sans = font_file("sans", "");
    TextSpec ok{"sans", "Ab", 12.0, {1.0, 10.0}};
    EXPECT_EQ(field_of(ok, sans), "accepted");
    TextSpec s = ok;
    s.string = "";
    EXPECT_EQ(field_of(s, sans).rfind("string: an empty string", 0), 0u);
    s.string = "A\xC3";
    EXPECT_EQ(field_of(s, sans), "string: invalid UTF-8 at byte 2");
    s.string = "\xC0\x80";  // an overlong NUL
    EXPECT_EQ(field_of(s, sans), "string: invalid UTF-8 at byte 1");
    s.string = "\xED\xA0\x80";  // a surrogate
    EXPECT_EQ(field_of(s, sans), "string: invalid UTF-8 at byte 1");
    s.string = "A\xE4\xB8\x80";  // U+4E00, a CJK ideograph DejaVu Sans lacks
    EXPECT_NE(field_of(s, sans).find("no glyph for U+4E00 (character 2)"), std::string::npos)
        << field_of(s, sans);
    s = ok;
    s.size_px = 0.25;
    EXPECT_EQ(field_of(s, sans).rfind("size_px: ", 0), 0u);
    s.size_px = 4096;
    EXPECT_EQ(field_of(s, sans).rfind("size_px: ", 0), 0u);
    EXPECT_NE(field_of(ok, "/nonexistent/font.ttf").find("font: cannot open font file"),
              std::string::npos);
    EXPECT_NE(field_of(ok, "/etc/hostname").find("not a font file"), std::string::npos)
        << field_of(ok, "/etc/hostname");
    EXPECT_EQ(field_of(ok, "/dev/zero"), "font: /dev/zero is not a regular file");
}

TEST(TextOutline, AFontPathIsRelativeToTheSceneFolder) {
    EXPECT_EQ(font_file("sans", "/some/where"), "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
    EXPECT_EQ(font_file("fonts/x.ttf", "/some/where"), "/some/where/fonts/x.ttf");
    EXPECT_EQ(font_file("/abs/x.ttf", "/some/where"), "/abs/x.ttf");
    EXPECT_EQ(font_file("x.ttf", ""), "x.ttf");
}

// Kerning moves the pen by the font's kern pair (FT_Get_Kerning, unscaled, times the scale);
// letter spacing by its px after every glyph.
TEST(TextOutline, KerningAndLetterSpacingMoveTheLaterGlyphs) {
    TextSpec plain{"sans", "AV", 100.0, {0.0, 100.0}};
    auto first_x = [](const std::vector<SegmentContour>& o, std::size_t contour) {
        return o[contour][0].p[0].x;
    };
    const auto a = text_outline(plain, font_file("sans", ""));
    TextSpec spaced = plain;
    spaced.letter_spacing_px = 2.5;
    const auto b = text_outline(spaced, font_file("sans", ""));
    ASSERT_EQ(a.size(), b.size());
    EXPECT_NEAR(first_x(b, 0) - first_x(a, 0), 0.0, 1e-12);
    EXPECT_NEAR(first_x(b, a.size() - 1) - first_x(a, a.size() - 1), 2.5, 1e-12);
    TextSpec kerned = plain;
    kerned.kerning = true;
    const auto k = text_outline(kerned, font_file("sans", ""));
    // DejaVu Sans kerns A-V together (its kern table), by a whole number of font units.
    const double moved = first_x(k, k.size() - 1) - first_x(a, a.size() - 1);
    EXPECT_LT(moved, 0.0);
    const double units = moved / (100.0 / 2048.0);
    EXPECT_NEAR(units, std::round(units), 1e-9);
}

}  // namespace
}  // namespace aabench
