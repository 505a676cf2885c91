// PNG files through libpng (harness/report/png_codec.h).
//
// libpng reports errors by longjmp to the setjmp point of the call (png_jmpbuf). A longjmp
// past a C++ object with a destructor is undefined, so the functions that set the jump point
// hold only plain pointers and PODs, and everything with a destructor lives in their callers.
#include "harness/report/png_codec.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>

namespace aabench {
namespace {

struct WriteTarget {
    std::vector<std::uint8_t>* bytes;
    char error[256];
};

void on_write(png_structp png, png_bytep data, png_size_t length) {
    auto* target = static_cast<WriteTarget*>(png_get_io_ptr(png));
    // No C++ exception may cross libpng's C frames: a failed allocation becomes libpng's error.
    bool grown = true;
    try {
        target->bytes->insert(target->bytes->end(), data, data + length);
    } catch (const std::bad_alloc&) {
        grown = false;
    }
    if (!grown) png_error(png, "out of memory");
}

void on_flush(png_structp) {}

void on_error(png_structp png, png_const_charp message) {
    auto* target = static_cast<WriteTarget*>(png_get_error_ptr(png));
    std::snprintf(target->error, sizeof target->error, "%s", message);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // warnings are not failures

// Returns false (and target->error) when libpng failed. `rows`: one pointer per row.
bool encode(int width, int height, int color_type, int bit_depth, png_bytepp rows,
            PngTransfer transfer, WriteTarget* target) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, target, on_error, on_warning);
    if (!png) {
        std::snprintf(target->error, sizeof target->error, "libpng: out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(target->error, sizeof target->error, "libpng: out of memory");
        return false;
    }
    // setjmp stands alone in the condition: the only use C allows besides comparisons.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (!target->error[0]) std::snprintf(target->error, sizeof target->error, "libpng failed");
        return false;
    }
    png_set_write_fn(png, target, on_write, on_flush);
    png_set_compression_level(png, 6);  // zlib's default: reports carry many of these
    png_set_IHDR(png, info, width, height, bit_depth, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (transfer == PngTransfer::kSrgb) {
        // The sRGB chunk, and the gAMA and cHRM values a decoder without sRGB support uses.
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    } else {
        png_set_gAMA(png, info, 1.0);  // code = light
    }
    png_write_info(png, info);
    if (bit_depth == 16) png_set_swap(png);  // host order (little-endian) to PNG's big-endian
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

struct ReadResult {
    int bit_depth;
    int has_srgb;
    int has_gamma;
    double gamma;
    int has_icc;
    char icc_name[128];
    char error[256];
};

bool read_tags(std::FILE* file, ReadResult* out) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, out, nullptr, on_warning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    out->bit_depth = png_get_bit_depth(png, info);
    int intent = 0;
    out->has_srgb = png_get_sRGB(png, info, &intent) != 0;
    out->has_gamma = png_get_gAMA(png, info, &out->gamma) != 0;
    png_charp name = nullptr;
    int compression = 0;
    png_bytep profile = nullptr;
    png_uint_32 length = 0;
    out->has_icc = png_get_iCCP(png, info, &name, &compression, &profile, &length) != 0;
    if (out->has_icc && name) std::snprintf(out->icc_name, sizeof out->icc_name, "%s", name);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(int width, int height, int channels, int bit_depth,
                                     const void* samples, PngTransfer transfer) {
    if (bit_depth != 8 && bit_depth != 16) throw std::invalid_argument("encode_png: bit depth");
    const int color_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : channels == 3 ? PNG_COLOR_TYPE_RGB
                           : channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA
                                           : -1;
    if (color_type < 0) throw std::invalid_argument("encode_png: channels");
    const std::size_t row_bytes = static_cast<std::size_t>(width) * channels * (bit_depth / 8);
    std::vector<png_bytep> rows(height);
    auto* base = static_cast<png_bytep>(const_cast<void*>(samples));
    for (int j = 0; j < height; ++j) rows[j] = base + j * row_bytes;
    std::vector<std::uint8_t> bytes;
    WriteTarget target{&bytes, {}};
    if (!encode(width, height, color_type, bit_depth, rows.data(), transfer, &target)) {
        throw std::runtime_error(std::string("PNG encoding failed: ") + target.error);
    }
    return bytes;
}

std::optional<PngTags> read_png_tags(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return std::nullopt;
    unsigned char signature[8] = {};
    const bool is_png = std::fread(signature, 1, 8, file) == 8 && png_sig_cmp(signature, 0, 8) == 0;
    ReadResult result{};
    bool ok = false;
    if (is_png) {
        std::rewind(file);
        ok = read_tags(file, &result);
    }
    std::fclose(file);
    if (!ok) return std::nullopt;
    PngTags tags;
    tags.bit_depth = result.bit_depth;
    tags.srgb = result.has_srgb != 0;
    if (result.has_gamma) tags.gamma = result.gamma;
    if (result.has_icc) tags.icc = std::string(result.icc_name);
    return tags;
}

}  // namespace aabench
