// The HTML report's figure grid (harness/report/html_parts.h): each pattern's reference and
// method images, their signed error maps and magnified crops, written as files and laid out.
//
// Choices a reader of the page depends on:
// - Display transform. Images are linear coverage; shown raw, a 50% edge pixel would look too
//   dark on a screen, and every antialiased edge would look wrong in the same way. So views are
//   the sRGB encoding (IEC 61966-2-1 transfer function) of the values clamped to [0, 1],
//   rounded to 8 bits, computed here exactly (thresholds, no lookup-table rounding) rather than
//   by OpenImageIO's colorconvert, whose result depends on whatever $OCIO config is set.
// - Error maps. error = method - box reference, coloured by a diverging map (ColorBrewer RdBu:
//   blue too dark, white right, red too bright) on a signed log scale over kErrorDecades
//   decades below the pattern's scale S: |error| >= S is full colour, |error| <= S/10^3 is
//   white. S is the largest |error| of any method of the pattern rounded up to 1, 2 or 5 x 10^k,
//   the same for every method of the pattern, so maps compare side by side. A linear scale
//   would be set by the worst method (`none`: errors near 1) and leave the good ones (errors
//   of 1e-2 and below) white; a log scale shows both. The colour bar beside the maps states S.
// - Magnified crops. A window of the size of the scene's "focus" region (or of a 32 px square)
//   where the methods' errors and the reference's detail are largest, cut and magnified by an
//   integer factor with nearest-neighbour sampling (OpenImageIO resample without
//   interpolation), so every pixel is a visible block. The crops are of the 8-bit views, so
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "harness/report/html_parts.h"
#include "harness/report/image_io.h"
#include "harness/report/svg_plot.h"

namespace aabench::html_parts {
namespace {

namespace fs = std::filesystem;

// Images narrower than this are shown at the largest integer zoom that fits it (pixelated);
// wider ones at their own size, never scaled down (a browser's downscaling would alias).
constexpr int kThumbnailPx = 256;
// Side of the centred square magnified when the scene names no focus region.
constexpr int kDefaultFocusPx = 32;
// The magnified crops are zoomed to about kThumbnailPx, by at most this factor.
constexpr int kMaxZoom = 16;
// The error maps' log scale: from the scale S down to S / 10^kErrorDecades (white). Three
// decades reach from `none`'s errors near 1 to 8-bit quantisation (1/510).
constexpr double kErrorDecades = 3.0;
// When every method is exact up to float32 rounding, the maps still need a scale.
constexpr double kMinErrorScale = 1e-6;

// ColorBrewer RdBu, 11 classes, ordered from the most negative error to the most positive.
constexpr std::array<std::uint32_t, 11> kDivergingKnots = {0x053061, 0x2166ac, 0x4393c3, 0x92c5de,
                                                           0xd1e5f0, 0xf7f7f7, 0xfddbc7, 0xf4a582,
                                                           0xd6604d, 0xb2182b, 0x67001f};

struct Rect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
};

// The magnified region: the scene's "focus" metadata ("x,y,w,h" in px, rounded outwards to
// whole pixels and clipped to the image), or a centred square. `note` says which.
Rect focus_region(const Scene& scene, std::string& note) {
    const int side = std::min({kDefaultFocusPx, scene.width, scene.height});
    const Rect centred{(scene.width - side) / 2, (scene.height - side) / 2, side, side};
    const auto item = std::find_if(scene.metadata.begin(), scene.metadata.end(),
                                   [](const auto& kv) { return kv.first == "focus"; });
    if (item == scene.metadata.end()) {
        note = "centred square (the pattern names no focus region)";
        return centred;
    }
    std::array<double, 4> v{};
    char comma = 0;
    std::istringstream in(item->second);
    bool ok = static_cast<bool>(in >> v[0]);
    for (int k = 1; k < 4 && ok; ++k) ok = static_cast<bool>(in >> comma >> v[k]) && comma == ',';
    ok = ok && (in >> std::ws).eof();
    for (double x : v) ok = ok && std::isfinite(x);
    if (ok) {
        // Clipped in double, before the conversion: a huge coordinate must not overflow an int.
        auto clip = [](double value, int limit) {
            return static_cast<int>(std::clamp(value, 0.0, static_cast<double>(limit)));
        };
        const int x0 = clip(std::floor(v[0]), scene.width);
        const int y0 = clip(std::floor(v[1]), scene.height);
        const int x1 = clip(std::ceil(v[0] + v[2]), scene.width);
        const int y1 = clip(std::ceil(v[1] + v[3]), scene.height);
        if (x1 > x0 && y1 > y0) {
            note = fmt::format("the pattern's focus region ({})", item->second);
            return {x0, y0, x1 - x0, y1 - y0};
        }
    }
    note =
        fmt::format("centred square (focus \"{}\" is not x,y,w,h inside the image)", item->second);
    return centred;
}

// Where the magnified window goes: of every window of the focus region's size, the one with the
// most to see. A fixed spot misses (the torus's centre is its hole); so each pixel weighs the
// methods' |error| there, each method's scaled by its own largest so that `none` does not
// outweigh the rest (methods exact to float32 rounding, below kMinErrorScale, add nothing), plus
// the reference's detail (|horizontal| + |vertical| difference, scaled by its largest). Ties go
// to the window nearest the region the pattern names, then the first in row order.
Rect busiest_window(const PatternFigures& fig, const Rect& region) {
    const int w = fig.reference.width, h = fig.reference.height;
    std::vector<double> weight(static_cast<std::size_t>(w) * h, 0.0);
    const auto add_scaled = [&](const std::vector<double>& values) {
        const double largest = *std::max_element(values.begin(), values.end());
        if (!(largest > kMinErrorScale)) return;
        for (std::size_t p = 0; p < weight.size(); ++p) weight[p] += values[p] / largest;
    };
    std::vector<double> values(weight.size());
    for (const Image& image : fig.images) {
        if (image.data.size() != weight.size()) continue;
        for (std::size_t p = 0; p < values.size(); ++p) {
            const double e = std::abs(image.data[p] - fig.reference.data[p]);
            values[p] = std::isfinite(e) ? e : 0.0;
        }
        add_scaled(values);
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double v = fig.reference.at(x, y);
            values[static_cast<std::size_t>(y) * w + x] =
                (x + 1 < w ? std::abs(fig.reference.at(x + 1, y) - v) : 0.0) +
                (y + 1 < h ? std::abs(fig.reference.at(x, y + 1) - v) : 0.0);
        }
    }
    add_scaled(values);
    // Window sums from a summed-area table.
    std::vector<double> sat(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);
    const auto at = [&](int x, int y) -> double& {
        return sat[static_cast<std::size_t>(y) * (w + 1) + x];
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            at(x + 1, y + 1) = weight[static_cast<std::size_t>(y) * w + x] + at(x, y + 1) +
                               at(x + 1, y) - at(x, y);
        }
    }
    Rect best = region;
    double best_sum = -1.0, best_distance = 0.0;
    // Sums in a relative band this wide are a tie: rounding in the table must not pick a spot.
    constexpr double kTie = 1e-9;
    for (int y = 0; y + region.h <= h; ++y) {
        for (int x = 0; x + region.w <= w; ++x) {
            const double sum = at(x + region.w, y + region.h) - at(x, y + region.h) -
                               at(x + region.w, y) + at(x, y);
            const double distance = std::hypot(x - region.x, y - region.y);
            const double tie = kTie * std::max(1.0, best_sum);
            if (sum > best_sum + tie || (sum >= best_sum - tie && distance < best_distance)) {
                best = {x, y, region.w, region.h};
                best_sum = sum;
                best_distance = distance;
            }
        }
    }
    return best;
}

int zoom_factor(const Rect& region) {
    return std::clamp(kThumbnailPx / std::max(region.w, region.h), 1, kMaxZoom);
}

// Linear values where the 8-bit sRGB code steps up: code c is shown for values in
// [threshold[c-1], threshold[c]). Decoding the half-codes (c + 0.5) / 255 gives rounding to
// nearest of the encoded value exactly, with no table resolution to worry about.
const std::array<double, 255>& srgb_thresholds() {
    static const std::array<double, 255> thresholds = [] {
        std::array<double, 255> t{};
        for (int c = 0; c < 255; ++c) {
            const double encoded = (c + 0.5) / 255.0;
            t[c] = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
        }
        return t;
    }();
    return thresholds;
}

// The 8-bit sRGB code of a linear value; NaN is 0 (it is counted in the table's nonfinite).
std::uint8_t srgb_code(double v) {
    const auto& thresholds = srgb_thresholds();
    return std::isnan(v) ? 0
                         : static_cast<std::uint8_t>(
                               std::upper_bound(thresholds.begin(), thresholds.end(), v) -
                               thresholds.begin());
}

// 8-bit sRGB view of linear values.
template <class T>
OIIO::ImageBuf srgb_view(const Raster<T>& image) {
    std::vector<std::uint8_t> codes(image.pixel_count());
    for (std::size_t p = 0; p < codes.size(); ++p) codes[p] = srgb_code(image.data[p]);
    OIIO::ImageBuf view(OIIO::ImageSpec(image.width, image.height, 1, OIIO::TypeDesc::UINT8));
    view.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, codes.data());
    return view;
}

// 8-bit sRGB view of a colour image's linear R, G, B planes, each as srgb_view encodes a grey
// one; a grey image's one plane is srgb_view's.
template <class T>
OIIO::ImageBuf srgb_colour_view(const Planes<T>& image) {
    if (image.channels() == 1) return srgb_view(image[0]);
    const std::size_t n = image[0].pixel_count();
    std::vector<std::uint8_t> codes(n * 3);
    for (std::size_t p = 0; p < n; ++p) {
        for (int c = 0; c < 3; ++c) {
            codes[p * 3 + static_cast<std::size_t>(c)] = srgb_code(image[c].data[p]);
        }
    }
    OIIO::ImageBuf view(OIIO::ImageSpec(image.width(), image.height(), 3, OIIO::TypeDesc::UINT8));
    view.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, codes.data());
    return view;
}

// Largest |error| over every method of the pattern, rounded up to 1, 2 or 5 x 10^k.
double error_scale(const PatternFigures& figures) {
    double largest = 0.0;
    for (const Image& image : figures.images) {
        if (image.data.size() != figures.reference.data.size()) continue;
        for (std::size_t p = 0; p < image.data.size(); ++p) {
            const double e = std::abs(image.data[p] - figures.reference.data[p]);
            if (std::isfinite(e)) largest = std::max(largest, e);
        }
    }
    largest = std::max(largest, kMinErrorScale);
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        // The small tolerance keeps 0.2000000001 (a float32 error of 0.2) from becoming 0.5.
        if (largest <= step * decade * (1.0 + 1e-6)) return step * decade;
    }
    return 10.0 * decade;
}

// Position of an error on the colour map, in [0, 1] (0.5 white); NaN stays NaN.
float error_position(double error, double scale) {
    if (!std::isfinite(error)) return std::numeric_limits<float>::quiet_NaN();
    const double magnitude = std::abs(error) / scale;
    const double white_below = std::pow(10.0, -kErrorDecades);
    const double level = magnitude <= white_below
                             ? 0.0
                             : std::min(1.0, std::log10(magnitude / white_below) / kErrorDecades);
    return static_cast<float>(0.5 + 0.5 * std::copysign(level, error));
}

// The signed error map as an 8-bit RGB view (OpenImageIO color_map over kDivergingKnots);
// non-finite errors are black, which no colour of the map is.
OIIO::ImageBuf error_view(const Image& error, double scale) {
    OIIO::ImageBuf positions(OIIO::ImageSpec(error.width, error.height, 1, OIIO::TypeDesc::FLOAT));
    std::vector<float> values(error.pixel_count());
    for (std::size_t p = 0; p < values.size(); ++p) {
        const float position = error_position(error.data[p], scale);
        values[p] = std::isnan(position) ? 0.5f : position;
    }
    positions.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, values.data());
    std::vector<float> knots;
    for (std::uint32_t rgb : kDivergingKnots) {
        for (int shift : {16, 8, 0}) knots.push_back(((rgb >> shift) & 0xff) / 255.0f);
    }
    const OIIO::ImageBuf colours = OIIO::ImageBufAlgo::color_map(
        positions, 0, static_cast<int>(kDivergingKnots.size()), 3, knots);
    if (colours.has_error()) throw InputError("error map colouring failed: " + colours.geterror());
    std::vector<std::uint8_t> rgb(error.pixel_count() * 3);
    colours.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
    for (std::size_t p = 0; p < values.size(); ++p) {
        if (std::isnan(error_position(error.data[p], scale))) {
            rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = 0;
        }
    }
    OIIO::ImageBuf view(OIIO::ImageSpec(error.width, error.height, 3, OIIO::TypeDesc::UINT8));
    view.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
    return view;
}

// `region` of `view`, each pixel a factor x factor block.
OIIO::ImageBuf magnify(const OIIO::ImageBuf& view, const Rect& region, int factor) {
    const OIIO::ImageBuf crop = OIIO::ImageBufAlgo::cut(
        view, OIIO::ROI(region.x, region.x + region.w, region.y, region.y + region.h));
    const OIIO::ROI zoomed(0, region.w * factor, 0, region.h * factor, 0, 1, 0, view.nchannels());
    OIIO::ImageBuf out = OIIO::ImageBufAlgo::resample(crop, /*interpolate=*/false, zoomed);
    if (out.has_error()) throw InputError("magnifying failed: " + out.geterror());
    return out;
}

void write_view(const fs::path& path, const OIIO::ImageBuf& view) {
    const OIIO::ImageSpec& spec = view.spec();
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height *
                                     spec.nchannels);
    view.get_pixels(view.roi(), OIIO::TypeDesc::UINT8, pixels.data());
    write_display_png(path.string(), spec.width, spec.height, spec.nchannels, pixels.data());
}

// At each pixel, the error of the channel whose error is largest in magnitude (signed; the
// first such channel on a tie): what a luminance error map hides where the channels' errors
// cancel in Y.
Image largest_channel_error(const ImagePlanes& image, const CoveragePlanes& reference) {
    Image out(image.width(), image.height());
    for (std::size_t p = 0; p < out.data.size(); ++p) {
        double largest = 0.0;
        for (int c = 0; c < image.channels(); ++c) {
            const double e = image[c].data[p] - reference.planes[c].data[p];
            if (std::abs(e) > std::abs(largest) || std::isnan(e)) largest = e;
            if (std::isnan(largest)) break;
        }
        out.data[p] = static_cast<float>(largest);
    }
    return out;
}

Image to_float(const Coverage& coverage) {
    Image out(coverage.width, coverage.height);
    for (std::size_t p = 0; p < out.data.size(); ++p)
        out.data[p] = static_cast<float>(coverage.data[p]);
    return out;
}

// The colour bar of the error maps: the same knots as the maps, ticks at each decade. `name`
// (the pattern's) makes the gradient's id unique in the page.
std::string colour_bar(double scale, const std::string& name) {
    constexpr double kBarWidth = 240.0;
    constexpr double kX0 = 12.0;
    std::string stops;
    for (std::size_t k = 0; k < kDivergingKnots.size(); ++k) {
        stops +=
            fmt::format(R"~(<stop offset="{:.3f}" stop-color="#{:06x}"/>)~",
                        static_cast<double>(k) / (kDivergingKnots.size() - 1), kDivergingKnots[k]);
    }
    const std::string id = xml_escape("errbar-" + name);
    std::string svg = fmt::format(
        R"~(<svg xmlns="http://www.w3.org/2000/svg" width="264" height="52" viewBox="0 0 264 52" )~"
        R"~(font-size="10" )~"
        R"~(font-family="DejaVu Sans, Verdana, sans-serif"><defs><linearGradient id="{id}">{})~"
        R"~(</linearGradient></defs><rect x="{x:.0f}" y="4" width="{w:.0f}" height="14" )~"
        R"~(fill="url(#{id})" stroke="#999"/>)~",
        stops, fmt::arg("id", id), fmt::arg("x", kX0), fmt::arg("w", kBarWidth));
    for (int d = 0; d <= static_cast<int>(kErrorDecades); ++d) {
        const double value = scale * std::pow(10.0, -d);
        for (int sign : {-1, 1}) {
            if (d == static_cast<int>(kErrorDecades) && sign < 0) continue;
            const double x = kX0 + kBarWidth * error_position(sign * value, scale);
            const std::string label = d == static_cast<int>(kErrorDecades)
                                          ? std::string("0")
                                          : fmt::format("{:+g}", sign * value);
            svg +=
                fmt::format(R"~(<line x1="{x:.1f}" y1="18" x2="{x:.1f}" y2="22" stroke="#555"/>)~"
                            R"~(<text x="{x:.1f}" y="33" text-anchor="middle">{}</text>)~",
                            label, fmt::arg("x", x));
        }
    }
    svg += fmt::format(R"~(<text x="{:.0f}" y="47" fill="#555">log scale; |error| &lt; {:g} )~"
                       R"~(white, black NaN</text></svg>)~",
                       kX0, scale * std::pow(10.0, -kErrorDecades));
    return svg;
}

std::string img(const std::string& src, int width, int height, const std::string& alt) {
    return fmt::format(R"~(<img src="{}" width="{}" height="{}" alt="{}">)~", xml_escape(src),
                       width, height, xml_escape(alt));
}

}  // namespace

// The views side by side, left to right, `gap` white pixels apart, top-aligned (one channel:
// the sRGB views): the paper's comparison figures (Fig. 5, 6) as one image.
void write_strip(const fs::path& path, const std::vector<OIIO::ImageBuf>& views) {
    constexpr int kGapPx = 4;
    int width = 0, height = 0;
    for (const OIIO::ImageBuf& v : views) {
        width += v.spec().width + (width > 0 ? kGapPx : 0);
        height = std::max(height, v.spec().height);
    }
    if (width == 0 || height == 0) return;
    std::vector<std::uint8_t> strip(static_cast<std::size_t>(width) * height, 255);
    int x0 = 0;
    for (const OIIO::ImageBuf& v : views) {
        const int w = v.spec().width, h = v.spec().height;
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h);
        OIIO::ROI one = v.roi();
        one.chend = one.chbegin + 1;
        v.get_pixels(one, OIIO::TypeDesc::UINT8, pixels.data());
        for (int y = 0; y < h; ++y) {
            std::copy_n(pixels.data() + static_cast<std::size_t>(y) * w, w,
                        strip.data() + static_cast<std::size_t>(y) * width + x0);
        }
        x0 += w + kGapPx;
    }
    write_display_png(path.string(), width, height, 1, strip.data());
}

OIIO::ImageBuf display_view(const Image& image) { return srgb_view(image); }
OIIO::ImageBuf signed_view(const Image& values, double scale) { return error_view(values, scale); }
void write_png_view(const fs::path& path, const OIIO::ImageBuf& view) { write_view(path, view); }
std::string img_tag(const std::string& src, int width, int height, const std::string& alt) {
    return img(src, width, height, alt);
}
std::string signed_colour_bar(double scale, const std::string& name) {
    return colour_bar(scale, name);
}

// Writes the pattern's images and returns its figure grid.
std::string figure_grid(const fs::path& dir, const Section& section, const ReportData& data) {
    const PatternFigures& fig = *section.figures;
    const int width = fig.reference.width;
    const int height = fig.reference.height;
    const std::string rel = "images/" + section.name + "/";
    const fs::path image_dir = dir / "images" / section.name;
    std::error_code ec;
    fs::create_directories(image_dir, ec);
    if (ec) {
        throw InputError(
            fmt::format("{}: cannot create directory ({})", image_dir.string(), ec.message()));
    }

    // The scene names the focus; a scene of another size (not filled in) cannot.
    Scene sized;
    sized.width = width;
    sized.height = height;
    const bool scene_fits = fig.scene.width == width && fig.scene.height == height;
    std::string focus_note;
    const Rect named = focus_region(scene_fits ? fig.scene : sized, focus_note);
    const Rect focus = busiest_window(fig, named);
    focus_note =
        fmt::format("the {}×{} px window with the most error and reference detail (size from {})",
                    named.w, named.h, focus_note);
    const int zoom = zoom_factor(focus);
    const int shown_scale = std::max(1, kThumbnailPx / width);
    const int view_w = width * shown_scale;
    const int view_h = height * shown_scale;
    const int zoom_w = focus.w * zoom;
    const int zoom_h = focus.h * zoom;
    const double scale = error_scale(fig);

    std::string html = fmt::format(
        "<p class=\"note\">Views: the linear values clamped to [0, 1] and sRGB-encoded (IEC "
        "61966-2-1 transfer function, 8 bits){}. Error = method &minus; exact box reference, "
        "colour-mapped (not transformed): blue too dark, red too bright, on one signed log "
        "scale for every method of this pattern (colour bar). Magnified: {}, x {}..{}, y "
        "{}..{} ({}&times;{} px), nearest-neighbour &times;{}, outlined in orange on the "
        "reference. EXR links: float32 linear data (the error is the method's EXR minus the "
        "reference's).{}</p>\n",
        shown_scale > 1 ? fmt::format(", shown at {}&times; (nearest neighbour)", shown_scale)
                        : std::string(),
        xml_escape(focus_note), focus.x, focus.x + focus.w, focus.y, focus.y + focus.h, focus.w,
        focus.h, zoom,
        fig.colour_reference
            ? " A colour scene: the views and EXRs are in colour (linear R, G, B, each channel "
              "encoded as above); the error maps are of the luminance Y = 0.2126 R + 0.7152 G + "
              "0.0722 B, and the last column maps at each pixel the error of the channel whose "
              "error is largest in magnitude, signed (an error of chroma the luminance does "
              "not show: red against a green of the same Y), on the same scale."
            : "");
    // Reference row: the image with the focus outlined, the colour bar, the magnified crop.
    // A colour scene's views and EXRs are in colour; its error maps are the luminance's, and
    // a fifth column the largest channel's.
    const bool colour = fig.colour_reference && fig.colour_images.size() == fig.images.size();
    const int columns = colour ? 5 : 4;
    html += fmt::format(
        "<table class=\"figures\"><tr><th>image</th><th>error vs box reference</th><th>"
        "magnified</th><th>error, magnified</th>{}</tr>\n",
        colour ? "<th>largest channel's error</th>" : "");
    const OIIO::ImageBuf reference_view =
        colour ? srgb_colour_view(*fig.colour_reference) : srgb_view(fig.reference);
    write_view(image_dir / "reference.png", reference_view);
    if (colour) {
        ImagePlanes planes;
        for (const Coverage& plane : fig.colour_reference->planes)
            planes.planes.push_back(to_float(plane));
        write_image((image_dir / "reference.exr").string(), planes);
    } else {
        write_image((image_dir / "reference.exr").string(), to_float(fig.reference));
    }
    std::vector<OIIO::ImageBuf> strip = {magnify(reference_view, focus, zoom)};
    write_view(image_dir / "reference.zoom.png", strip.front());
    html += fmt::format(
        "<tr><td colspan=\"{c}\" class=\"caption\"><b>reference</b>: exact box coverage "
        "(computed in double) <a href=\"{r}reference.exr\">EXR</a></td></tr>\n<tr><td><span "
        "class=\"focusbox\">{}<span style=\"left:{:.3f}%;top:{:.3f}%;width:{:.3f}%;height:"
        "{:.3f}%\"></span></span></td><td>{}</td><td>{}</td><td></td>{}</tr>\n",
        img(rel + "reference.png", view_w, view_h, "reference"), 100.0 * focus.x / width,
        100.0 * focus.y / height, 100.0 * focus.w / width, 100.0 * focus.h / height,
        colour_bar(scale, section.name),
        img(rel + "reference.zoom.png", zoom_w, zoom_h, "reference, magnified"),
        colour ? "<td></td>" : "", fmt::arg("r", rel), fmt::arg("c", columns));

    std::set<std::string> taken = {"reference"};
    for (std::size_t k = 0; k < fig.methods.size() && k < fig.images.size(); ++k) {
        const Image& image = fig.images[k];
        if (image.width != width || image.height != height) {
            throw InputError(fmt::format("report: {} on {} is {}x{}, the reference {}x{}",
                                         fig.methods[k], section.spec, image.width, image.height,
                                         width, height));
        }
        const std::string name = unique_name(slug(fig.methods[k]), taken);
        Image error(width, height);
        for (std::size_t p = 0; p < error.data.size(); ++p) {
            error.data[p] = static_cast<float>(image.data[p] - fig.reference.data[p]);
        }
        const OIIO::ImageBuf view =
            colour ? srgb_colour_view(fig.colour_images[k]) : srgb_view(image);
        const OIIO::ImageBuf error_map = error_view(error, scale);
        write_view(image_dir / (name + ".png"), view);
        if (colour) {
            write_image((image_dir / (name + ".exr")).string(), fig.colour_images[k]);
        } else {
            write_image((image_dir / (name + ".exr")).string(), image);
        }
        write_view(image_dir / (name + ".error.png"), error_map);
        strip.push_back(magnify(view, focus, zoom));
        write_view(image_dir / (name + ".zoom.png"), strip.back());
        write_view(image_dir / (name + ".error.zoom.png"), magnify(error_map, focus, zoom));
        std::string channel_cell;
        if (colour) {
            const Image largest =
                largest_channel_error(fig.colour_images[k], *fig.colour_reference);
            write_view(image_dir / (name + ".error.channel.png"), error_view(largest, scale));
            channel_cell = "<td>" +
                           img(rel + name + ".error.channel.png", view_w, view_h,
                               fig.methods[k] + ", largest channel's error") +
                           "</td>";
        }

        // The row's figures, when the run has it (it should: figures are of default rows).
        std::string figures_text;
        for (std::size_t r : section.rows) {
            const ResultRow& row = data.rows[r];
            if (row.method == fig.methods[k] && !row.sweep_point) {
                figures_text = fmt::format(
                    " &nbsp; box_rmse {:.4g}, max_abs {:.4g} at ({}, {}), "
                    "bias {:+.3g}, time {:.4g} ms",
                    row[metric::kBoxRmse], row[metric::kBoxMaxAbs], row[metric::kBoxMaxX],
                    row[metric::kBoxMaxY], row[metric::kBoxBias],
                    row[metric::kTimeMedianNs] * 1e-6);
                break;
            }
        }
        const std::string spec = xml_escape(fig.methods[k]);
        html += fmt::format(
            "<tr><td colspan=\"{c}\" class=\"caption\"><b class=\"m\">{spec}</b>{} &nbsp; <a "
            "href=\"{r}{n}.exr\">EXR</a></td></tr>\n"
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td>{}</tr>\n",
            figures_text, img(rel + name + ".png", view_w, view_h, fig.methods[k]),
            img(rel + name + ".error.png", view_w, view_h, fig.methods[k] + ", error"),
            img(rel + name + ".zoom.png", zoom_w, zoom_h, fig.methods[k] + ", magnified"),
            img(rel + name + ".error.zoom.png", zoom_w, zoom_h,
                fig.methods[k] + ", error magnified"),
            channel_cell, fmt::arg("spec", spec), fmt::arg("r", rel),
            fmt::arg("n", xml_escape(name)), fmt::arg("c", columns));
    }
    html += "</table>\n";
    // Every magnified crop in one row, as the paper's figures compare methods side by side.
    write_strip(image_dir / "strip.zoom.png", strip);
    html += fmt::format(
        "<p class=\"note\">Side by side, the magnified crops: reference, then each method in "
        "run order (<a href=\"{r}strip.zoom.png\">strip.zoom.png</a>).</p>\n",
        fmt::arg("r", rel));
    return html;
}

}  // namespace aabench::html_parts
