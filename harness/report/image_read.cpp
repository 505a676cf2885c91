// Reading an image to be scored (harness/report/image_read.h).
#include "harness/report/image_read.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

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

Image read_image_to_score(const std::string& path, bool srgb) {
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
    if (srgb && spec.format.is_floating_point()) {
        fail(path, fmt::format("--srgb: the file holds {} data, linear by definition (--srgb is "
                               "for 8- or 16-bit PNG)",
                               spec.format.c_str()));
    }
    check_image_size(spec.width, spec.height, path);  // before allocating
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    // In double, so that decoding and alpha round once, to float, at the end.
    std::vector<double> value = read_channel(*in, path, 0, pixels), alpha;
    const bool unassociated = spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    if (unassociated && spec.alpha_channel > 0) {
        alpha = read_channel(*in, path, spec.alpha_channel, pixels);
    }
    Image image(spec.width, spec.height);
    for (std::size_t k = 0; k < pixels; ++k) {
        const double light = srgb ? srgb_to_linear(value[k]) : value[k];
        image.data[k] = static_cast<float>(alpha.empty() ? light : light * alpha[k]);
    }
    return image;
}

}  // namespace aabench
