// Reading an image to be scored (harness/report/image_read.h).
#include "harness/report/image_read.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "harness/report/png_codec.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw InputError(fmt::format("{}: {}", path, reason));
}

std::string one_line(std::string text) {
    for (char& c : text) c = c == '\n' ? ' ' : c;
    return text.empty() ? "truncated or malformed (the decoder gave no reason)" : text;
}

// One channel in double. 8- and 16-bit codes are read as they are and divided here: OpenImageIO
// converts them through float, which costs the sRGB decoding up to 2.4 float ulps.
std::vector<double> read_channel(OIIO::ImageInput& in, const std::string& path, int channel,
                                 std::size_t pixels) {
    const OIIO::TypeDesc format = in.spec().format;
    std::vector<double> out(pixels);
    auto read = [&](OIIO::TypeDesc type, void* data) {
        if (!in.read_image(0, 0, channel, channel + 1, type, data)) {
            fail(path, "cannot read image: " + one_line(in.geterror()));
        }
    };
    auto read_codes = [&]<class T>(T max_code) {
        std::vector<T> codes(pixels);
        read(OIIO::TypeDesc(OIIO::BaseTypeFromC<T>::value), codes.data());
        for (std::size_t k = 0; k < pixels; ++k) out[k] = codes[k] / static_cast<double>(max_code);
    };
    if (format == OIIO::TypeDesc::UINT8) {
        read_codes(std::uint8_t{255});
    } else if (format == OIIO::TypeDesc::UINT16) {
        read_codes(std::uint16_t{65535});
    } else {
        read(OIIO::TypeDesc::DOUBLE, out.data());
    }
    return out;
}

}  // namespace

double srgb_to_linear(double v) {
    // IEC 61966-2-1: the linear segment near black, the 2.4 power above it.
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

// gAMA 0.45455 (1/2.2, stored as 45455 / 100000) is what the sRGB chunk asks encoders to write
// beside it: a file with that gAMA alone was written for sRGB displays.
constexpr double kSrgbFileGamma = 0.45455;
// A gAMA is stored in units of 1e-5: two values closer than that are the same.
constexpr double kGammaStep = 1e-5;

// Decides the decoding of an integer image from what the file says (Encoding::kAuto).
ScoredImage decide(const std::string& path, int bits) {
    ScoredImage d;
    const std::optional<PngTags> tags = read_png_tags(path);
    const std::string kind = tags ? fmt::format("{}-bit PNG", tags->bit_depth)
                                  : fmt::format("{}-bit image", bits);
    if (tags && tags->srgb) {
        d.used = Encoding::kSrgb;
        d.why = "the PNG's sRGB chunk";
    } else if (tags && tags->icc) {
        std::string name = *tags->icc;
        for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        // A name that says sRGB but linear (scRGB, "Linear sRGB", elle's g10 profiles) is not
        // the sRGB curve: refused like any other profile aabench does not decode.
        const bool linear_named = name.find("linear") != std::string::npos ||
                                  name.find("scrgb") != std::string::npos ||
                                  name.find("g10") != std::string::npos;
        if (name.find("srgb") == std::string::npos || linear_named) {
            fail(path, fmt::format("the PNG carries an ICC profile ('{}') aabench does not decode: "
                                   "give --srgb or --linear",
                                   *tags->icc));
        }
        d.used = Encoding::kSrgb;
        d.why = fmt::format("the PNG's ICC profile '{}'", *tags->icc);
    } else if (tags && tags->gamma) {
        const double g = *tags->gamma;
        if (!(g > 0.0)) fail(path, fmt::format("the PNG's gAMA {} is not positive", g));
        if (std::abs(g - 1.0) < kGammaStep) {
            d.used = Encoding::kLinear;
            d.why = "the PNG's gAMA 1.0 (linear codes)";
        } else if (std::abs(g - kSrgbFileGamma) < kGammaStep) {
            d.used = Encoding::kSrgb;
            d.why = "the PNG's gAMA 0.45455 (written for sRGB displays)";
        } else {
            d.used = Encoding::kLinear;
            d.gamma = g;
            d.why = fmt::format("the PNG's gAMA {:.5f} (light = code^{:.4f})", g, 1.0 / g);
        }
    } else if (bits == 8) {
        d.used = Encoding::kSrgb;
        d.why = fmt::format("untagged {}: renderers write 8-bit images sRGB-encoded (--linear if "
                            "not)",
                            kind);
    } else {
        d.used = Encoding::kLinear;
        d.why = fmt::format("untagged {}: taken as linear codes (--srgb if not)", kind);
    }
    return d;
}

}  // namespace

Image read_image_to_score(const std::string& path, bool srgb) {
    return read_image_to_score(path, srgb ? Encoding::kSrgb : Encoding::kLinear).image;
}

ScoredImage read_image_to_score(const std::string& path, Encoding encoding) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) fail(path, "cannot read: no such file");
    if (std::filesystem::is_directory(status)) fail(path, "cannot read: is a directory");
    // Unassociated: a PNG's codes as stored. OpenImageIO would otherwise multiply by alpha in
    // the file's own 8 bits (254 x 128/255 comes back as 127/255, not 127.5/255), and before
    // the transfer function is undone (alpha scales light, not codes). Formats that store
    // associated alpha (EXR) are read as they are and not multiplied again.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) fail(path, "cannot read image: " + one_line(OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep || spec.depth > 1 || spec.nchannels < 1) {
        fail(path, "cannot read image: not a flat 2-D image");
    }
    ScoredImage scored;
    if (spec.format.is_floating_point()) {
        if (encoding == Encoding::kSrgb) {
            fail(path, fmt::format("--srgb: the file holds {} data, linear by definition (--srgb "
                                   "is for 8- or 16-bit PNG)",
                                   spec.format.c_str()));
        }
        scored.used = Encoding::kLinear;
        scored.why = fmt::format("{} data are linear", spec.format.c_str());
    } else if (encoding == Encoding::kAuto) {
        scored = decide(path, static_cast<int>(spec.format.size()) * 8);
    } else {
        scored.used = encoding;
        scored.why = encoding == Encoding::kSrgb ? "--srgb" : "--linear";
    }
    check_image_size(spec.width, spec.height, path);  // before allocating
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    // In double, so that decoding and alpha round once, to float, at the end.
    std::vector<double> value = read_channel(*in, path, 0, pixels), alpha;
    const bool unassociated = spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    if (unassociated && spec.alpha_channel > 0) {
        alpha = read_channel(*in, path, spec.alpha_channel, pixels);
    }
    const bool srgb = scored.used == Encoding::kSrgb;
    const double power = scored.gamma > 0.0 ? 1.0 / scored.gamma : 1.0;
    auto decoded = [&](const std::vector<double>& codes) {
        Image plane(spec.width, spec.height);
        for (std::size_t k = 0; k < pixels; ++k) {
            const double light = srgb ? srgb_to_linear(codes[k])
                                 : power != 1.0 ? std::pow(codes[k], power)
                                                : codes[k];
            plane.data[k] = static_cast<float>(alpha.empty() ? light : light * alpha[k]);
        }
        return plane;
    };
    scored.image = decoded(value);
    // Three colour channels (alpha not among the first three): R, G, B as planes too.
    const bool rgb = spec.nchannels >= 3 && spec.alpha_channel != 1 && spec.alpha_channel != 2;
    if (rgb) {
        ImagePlanes planes;
        planes.planes.push_back(scored.image);
        for (int c = 1; c < 3; ++c) planes.planes.push_back(decoded(read_channel(*in, path, c, pixels)));
        scored.channels_differ = planes[1].data != planes[0].data || planes[2].data != planes[0].data;
        scored.colour = std::move(planes);
    }
    return scored;
}

}  // namespace aabench
