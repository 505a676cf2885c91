// Image and text files, written atomically (harness/report/image_io.h).
//
// Which library writes what, and why. The failure cases were found by limiting the file size
// to 4096 bytes (setrlimit RLIMIT_FSIZE: every later write() fails with EFBIG, as on a full
// disk; seen in strace); tests/image_io_test.cpp, FailedWriteLeavesThePreviousFileAndNoTemporary,
// now checks that every format reports it.
// - EXR: OpenImageIO. ImageOutput::create(path) picks the plugin from the real extension, then
//   open(temporary, spec) writes to the temporary name, which need not have that extension.
//   It reports the failed write ("Failed OpenEXR write ... File output failed").
// - PFM: written here, header and raw floats. OpenImageIO 2.4 has no PFM writer ("could not
//   find a format writer"). OpenCV 4.6's PFM encoder does store the bottom row first, "Pf",
//   scale -1, but ignores write errors: cv::imwrite(".pfm") returns true on a truncated file,
//   and cv::imencode(".pfm") goes through a file in /tmp and returns its first 4096 bytes as the
//   whole encoding. A truncated file reported as written is what this module must not allow.
// - PNG: libpng into memory (harness/report/png_codec.h: OpenCV's encoder cannot write the
//   gAMA and sRGB chunks that say what the codes mean), then our checked write_bytes().
//   OpenImageIO 2.4's PNG writer ignores write errors too (a truncated file, and success).
//
// Reading is OpenImageIO for every format, PFM included: its reader takes either byte order
// and turns the rows top-down, and every truncation of a file we write fails cleanly (tested at
// every byte). Its PNG reader (libpng's default handler) also prints "libpng error: ..." to
// stderr for a corrupt PNG; the InputError is still the one reported.
#include "harness/report/image_io.h"

#include "harness/report/interrupt.h"
#include "harness/report/png_codec.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <system_error>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

enum class ImageFormat { kExr, kPfm, kPng };

constexpr double kPngMaxCode = 65535.0;  // 16-bit grey

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw InputError(fmt::format("{}: {}", path, reason));
}

// OpenImageIO and OpenCV messages can span lines; ours are one line.
std::string one_line(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '\n' ? std::string("; ") : std::string(1, c);
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    // OpenImageIO's PFM reader fails on a short file without saying why.
    return out.empty() ? "truncated or malformed (the decoder gave no reason)" : out;
}

ImageFormat format_for(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".exr") return ImageFormat::kExr;
    if (extension == ".pfm") return ImageFormat::kPfm;
    if (extension == ".png") return ImageFormat::kPng;
    const std::string found =
        extension.empty() ? std::string("no extension") : fmt::format("\"{}\"", extension);
    fail(path, fmt::format("unknown image format: {} (expected .exr|.pfm|.png)", found));
}

// A temporary file next to the target, removed unless commit() renamed it into place.
class TempFile {
public:
    explicit TempFile(const std::string& target) : target_(target) {
        const fs::path target_path(target);
        if (target_path.filename().empty()) fail(target, "not a file name");
        const fs::path directory =
            target_path.has_parent_path() ? target_path.parent_path() : fs::path(".");
        std::error_code error;
        if (!fs::is_directory(directory, error)) {
            fail(target,
                 fmt::format("cannot write: directory \"{}\" does not exist", directory.string()));
        }
        // Same directory, so the rename is atomic (same filesystem); hidden, so a glob for
        // results does not pick it up; pid and counter make it unique across processes and
        // threads; the target's name is cut so that one near NAME_MAX (255) still fits.
        static std::atomic<unsigned> counter{0};
        constexpr std::size_t kMaxNameInTemp = 200;
        const std::string name = target_path.filename().string().substr(0, kMaxNameInTemp);
        path_ = (directory / fmt::format(".{}.tmp-{}-{}", name, ::getpid(), counter.fetch_add(1)))
                    .string();
        // Before the file exists: a Ctrl-C from here on removes it (harness/report/interrupt.h).
        slot_ = register_temp_file(path_);
    }
    ~TempFile() {
        if (!committed_) {
            std::error_code ignored;
            fs::remove(path_, ignored);
        }
        unregister_temp_file(slot_);
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    const std::string& path() const { return path_; }

    void commit() {
        std::error_code error;
        fs::rename(path_, target_, error);
        if (error) fail(target_, "cannot replace: " + error.message());
        committed_ = true;
        // Renamed: the name is the target's now, which a signal must leave alone.
        unregister_temp_file(slot_);
        slot_ = -1;
    }

private:
    std::string target_;
    std::string path_;
    bool committed_ = false;
    int slot_ = -1;
};

void write_bytes(const std::string& target, const std::string& path, const void* data,
                 std::size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail(target, fmt::format("cannot write: {}", std::strerror(errno)));
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t written = ::write(fd, bytes, size);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            const int saved = errno;
            ::close(fd);
            fail(target, fmt::format("cannot write: {}", std::strerror(saved)));
        }
        bytes += written;
        size -= static_cast<std::size_t>(written);
    }
    // close() can report a deferred write error (NFS, quota): the file is not good then.
    if (::close(fd) != 0) fail(target, fmt::format("cannot write: {}", std::strerror(errno)));
}

// The pixels to write: `channels` interleaved float32 values per pixel (1 grey, 3 R, G, B),
// row 0 at the top.
struct Pixels {
    int width = 0;
    int height = 0;
    int channels = 1;
    std::vector<float> values;  // interleaved; empty for one plane (then `grey` is read)
    const Image* grey = nullptr;
    float at(std::size_t pixel, int c) const {
        return grey != nullptr ? grey->data[pixel]
                               : values[pixel * static_cast<std::size_t>(channels) +
                                        static_cast<std::size_t>(c)];
    }
    const float* data() const { return grey != nullptr ? grey->data.data() : values.data(); }
};

void check_writable_plane(const std::string& path, const Image& image) {
    if (image.width < 1 || image.height < 1) {
        fail(path, fmt::format("cannot write an empty image ({}x{})", image.width, image.height));
    }
    if (image.data.size() != static_cast<std::size_t>(image.width) * image.height) {
        fail(path, fmt::format("image is {}x{} but holds {} values", image.width, image.height,
                               image.data.size()));
    }
}

Pixels pixels_of(const std::string& path, const ImagePlanes& planes) {
    if (planes.channels() != 1 && planes.channels() != 3) {
        fail(path, fmt::format("cannot write {} planes (expected 1 or 3)", planes.channels()));
    }
    for (const Image& plane : planes.planes) {
        check_writable_plane(path, plane);
        if (plane.width != planes.width() || plane.height != planes.height()) {
            fail(path, "the planes differ in size");
        }
    }
    Pixels px{planes.width(), planes.height(), planes.channels(), {}, nullptr};
    if (planes.channels() == 1) {
        px.grey = &planes[0];
        return px;
    }
    const std::size_t n = planes[0].pixel_count();
    px.values.resize(n * 3);
    for (std::size_t k = 0; k < n; ++k) {
        for (int c = 0; c < 3; ++c) px.values[k * 3 + static_cast<std::size_t>(c)] = planes[c].data[k];
    }
    return px;
}

void write_exr(const std::string& path, const std::string& temp_path, const Pixels& px) {
    OIIO::ImageSpec spec(px.width, px.height, px.channels, OIIO::TypeDesc::FLOAT);
    if (px.channels == 1) {
        spec.channelnames = {"Y"};  // luminance-only EXR
    } else {
        spec.channelnames = {"R", "G", "B"};  // linear, Rec. 709 primaries
    }
    spec.attribute("compression", "zip");
    // The plugin comes from the real name, the bytes go to the temporary one.
    auto out = OIIO::ImageOutput::create(path);
    if (!out) fail(path, "cannot write: " + one_line(OIIO::geterror()));
    if (!out->open(temp_path, spec)) fail(path, "cannot write: " + one_line(out->geterror()));
    const bool written = out->write_image(OIIO::TypeDesc::FLOAT, px.data());
    // close() always, so the file handle goes; it also flushes, so its result counts.
    const bool closed = out->close();
    if (!written || !closed) fail(path, "cannot write: " + one_line(out->geterror()));
}

void write_png(const std::string& path, const std::string& temp_path, const Pixels& px) {
    const std::size_t n = static_cast<std::size_t>(px.width) * px.height;
    std::vector<std::uint16_t> codes(n * static_cast<std::size_t>(px.channels));
    for (std::size_t k = 0; k < n; ++k) {
        for (int c = 0; c < px.channels; ++c) {
            const double value = px.at(k, c);
            // `!(value > 0)` is true for NaN too: NaN is written as 0 rather than being undefined.
            const double clamped = !(value > 0.0) ? 0.0 : std::min(value, 1.0);
            codes[k * static_cast<std::size_t>(px.channels) + static_cast<std::size_t>(c)] =
                static_cast<std::uint16_t>(std::lround(clamped * kPngMaxCode));
        }
    }
    std::vector<std::uint8_t> bytes;
    try {
        // Linear codes, and the file says so (gAMA 1.0: harness/report/png_codec.h).
        bytes = encode_png(px.width, px.height, px.channels, 16, codes.data(),
                           PngTransfer::kLinear);
    } catch (const std::runtime_error& error) {
        fail(path, "cannot write: " + one_line(error.what()));
    }
    write_bytes(path, temp_path, bytes.data(), bytes.size());
}

// Portable Float Map, as defined (netpbm, Debevec): "Pf" (one channel) or "PF" (three, R G B
// per pixel), "width height", the scale whose sign gives the byte order (negative:
// little-endian), each line ending in a single newline, then rows of float32 from the BOTTOM
// row up.
void write_pfm(const std::string& path, const std::string& temp_path, const Pixels& px) {
    std::string bytes =
        fmt::format("{}\n{} {}\n-1.0\n", px.channels == 1 ? "Pf" : "PF", px.width, px.height);
    const std::size_t header_size = bytes.size();
    const std::size_t row_values = static_cast<std::size_t>(px.width) * px.channels;
    bytes.resize(header_size + sizeof(float) * row_values * px.height);
    char* out = bytes.data() + header_size;
    for (int j = px.height - 1; j >= 0; --j) {
        const std::size_t first = static_cast<std::size_t>(j) * px.width;
        for (int i = 0; i < px.width; ++i) {
            for (int c = 0; c < px.channels; ++c) {
                // Least significant byte first whatever the host's order, as the scale -1 says.
                const std::uint32_t bits =
                    std::bit_cast<std::uint32_t>(px.at(first + static_cast<std::size_t>(i), c));
                for (int shift = 0; shift < 32; shift += 8) *out++ = static_cast<char>(bits >> shift);
            }
        }
    }
    write_bytes(path, temp_path, bytes.data(), bytes.size());
}

}  // namespace

namespace {

void write_pixels(const std::string& path, ImageFormat format, const Pixels& px) {
    TempFile temp(path);
    switch (format) {
        case ImageFormat::kExr:
            write_exr(path, temp.path(), px);
            break;
        case ImageFormat::kPfm:
            write_pfm(path, temp.path(), px);
            break;
        case ImageFormat::kPng:
            write_png(path, temp.path(), px);
            break;
    }
    temp.commit();
}

}  // namespace

void write_image(const std::string& path, const ImagePlanes& planes) {
    // Every check before the temporary exists: an unknown extension leaves nothing behind.
    const ImageFormat format = format_for(path);
    write_pixels(path, format, pixels_of(path, planes));
}

void write_image(const std::string& path, const Image& image) {
    const ImageFormat format = format_for(path);
    check_writable_plane(path, image);
    write_pixels(path, format, Pixels{image.width, image.height, 1, {}, &image});
}

void write_display_png(const std::string& path, int width, int height, int channels,
                       const std::uint8_t* pixels) {
    if (format_for(path) != ImageFormat::kPng) fail(path, "a display image is written as .png");
    if (width < 1 || height < 1) {
        fail(path, fmt::format("cannot write an empty image ({}x{})", width, height));
    }
    if (channels != 1 && channels != 3 && channels != 4) {
        fail(path, fmt::format("cannot write {} channels (expected 1, 3 or 4)", channels));
    }
    std::vector<std::uint8_t> bytes;
    try {
        // The views are sRGB-encoded for display, and the file says so (the sRGB chunk).
        bytes = encode_png(width, height, channels, 8, pixels, PngTransfer::kSrgb);
    } catch (const std::runtime_error& error) {
        fail(path, "cannot write: " + one_line(error.what()));
    }
    TempFile temp(path);
    write_bytes(path, temp.path(), bytes.data(), bytes.size());
    temp.commit();
}

void write_text_file(const std::string& path, const std::string& contents) {
    TempFile temp(path);
    write_bytes(path, temp.path(), contents.data(), contents.size());
    temp.commit();
}

namespace {

// The first `channels` channels of the image at `path` (check_channels(spec) says how many),
// converted to float by OpenImageIO (integers normalised to [0, 1]), as planes.
template <class ChannelCount>
ImagePlanes read_channels(const std::string& path, const ChannelCount& check_channels) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status)) fail(path, "cannot read: no such file");
    if (fs::is_directory(status)) fail(path, "cannot read: is a directory");

    auto in = OIIO::ImageInput::open(path);
    if (!in) fail(path, "cannot read image: " + one_line(OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep) fail(path, "cannot read image: deep images are not supported");
    if (spec.depth > 1) fail(path, "cannot read image: volume images are not supported");
    if (spec.nchannels < 1) fail(path, "cannot read image: it has no channels");
    // Before allocating: the header's size is whatever the file claims.
    check_image_size(spec.width, spec.height, path);
    const int channels = check_channels(spec.nchannels);

    std::vector<float> values(static_cast<std::size_t>(spec.width) * spec.height * channels);
    const bool read = in->read_image(/*subimage=*/0, /*miplevel=*/0, /*chbegin=*/0,
                                     /*chend=*/channels, OIIO::TypeDesc::FLOAT, values.data());
    if (!read) fail(path, "cannot read image: " + one_line(in->geterror()));
    in->close();
    ImagePlanes planes(channels, spec.width, spec.height);
    const std::size_t n = planes[0].pixel_count();
    for (std::size_t k = 0; k < n; ++k) {
        for (int c = 0; c < channels; ++c) {
            planes[c].data[k] = values[k * static_cast<std::size_t>(channels) +
                                       static_cast<std::size_t>(c)];
        }
    }
    return planes;
}

}  // namespace

Image read_image(const std::string& path) {
    // Channel 0 only.
    return std::move(read_channels(path, [](int) { return 1; })[0]);
}

ImagePlanes read_image_planes(const std::string& path) {
    return read_channels(path, [&path](int n) {
        if (n == 1 || n == 2) return 1;  // grey, or grey and alpha
        if (n == 3 || n == 4) return 3;  // R, G, B, or with alpha
        fail(path, fmt::format("cannot read image: {} channels (expected 1 to 4: grey or RGB, "
                               "with or without alpha)",
                               n));
    });
}

}  // namespace aabench
