// Image and text files: exact EXR and PFM round trips with the row order checked on bytes or by
// a second decoder (OpenCV), 16-bit PNG codes, and the failure paths: unknown extension,
// missing directory, truncated or mistyped files, a write failing mid-way (file size limit)
// leaving the previous file and no temporary behind.
#include "harness/report/image_io.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// One float32 step at 1.0 (2^-23): reading a 16-bit code back as float divides by 65535 in
// float, which may round differently from the double quotient by up to that.
constexpr float kFloatStepAtOne = 1.0f / (1 << 23);

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_raw(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// Every value distinct, so any row or column swap shows; awkward floats in the mix.
Image gradient(int width, int height) {
    Image image(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) image.at(i, j) = 100.0f * j + i + 1.0f / 3.0f;
    }
    image.at(0, 0) = -0.0f;
    image.at(1, 0) = std::numeric_limits<float>::denorm_min();
    image.at(2, 0) = std::numeric_limits<float>::max();
    image.at(0, 1) = -1e-30f;
    return image;
}

bool same_bits(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.data.size() != b.data.size()) {
        return false;
    }
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        if (std::bit_cast<std::uint32_t>(a.data[k]) != std::bit_cast<std::uint32_t>(b.data[k])) {
            return false;
        }
    }
    return true;
}

class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / fmt::format("aabench_image_io_test_{}", ::getpid());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string file(const std::string& name) const { return (dir_ / name).string(); }

    // Names in the directory, so a test can say nothing else (no temporary) is there.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path dir_;
};

void expect_input_error(const std::function<void()>& action, const std::string& path,
                        const std::string& fragment = "") {
    try {
        action();
        ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST_F(ImageIo, ExrRoundTripIsExactWithRowZeroAtTheTop) {
    const Image image = gradient(7, 5);
    const std::string path = file("gradient.exr");
    write_image(path, image);
    EXPECT_TRUE(same_bits(read_image(path), image));
    EXPECT_EQ(listing(), std::vector<std::string>{"gradient.exr"});

    // A second decoder, so the row order is not just our reader agreeing with our writer.
    // OpenCV reads EXR only when this is set before its first use.
    ::setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1);
    const cv::Mat mat = cv::imread(path, cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(mat.empty());
    ASSERT_EQ(mat.type(), CV_32FC1);
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            EXPECT_EQ(std::bit_cast<std::uint32_t>(mat.at<float>(j, i)),
                      std::bit_cast<std::uint32_t>(image.at(i, j)))
                << i << "," << j;
        }
    }
}

TEST_F(ImageIo, PfmStoresBottomRowFirst) {
    const Image image = gradient(4, 3);
    const std::string path = file("gradient.pfm");
    write_image(path, image);

    // Header: "Pf", width height, scale (negative: little-endian), each on its own line.
    const std::string bytes = read_bytes(path);
    std::istringstream header(bytes);
    std::string magic;
    int width = 0, height = 0;
    double scale = 0.0;
    header >> magic >> width >> height >> scale;
    ASSERT_TRUE(header);
    EXPECT_EQ(magic, "Pf");
    EXPECT_EQ(width, 4);
    EXPECT_EQ(height, 3);
    EXPECT_EQ(scale, -1.0);
    ASSERT_EQ(std::endian::native, std::endian::little);  // the raw compare below assumes it
    const std::size_t data_bytes = sizeof(float) * image.pixel_count();
    ASSERT_GE(bytes.size(), data_bytes);
    const std::size_t offset = bytes.size() - data_bytes;
    EXPECT_EQ(bytes[offset - 1], '\n');  // one whitespace byte after the scale
    for (int stored_row = 0; stored_row < height; ++stored_row) {
        const int image_row = height - 1 - stored_row;  // bottom row first
        for (int i = 0; i < width; ++i) {
            float value;
            std::memcpy(&value, bytes.data() + offset + sizeof(float) * (stored_row * width + i),
                        sizeof value);
            EXPECT_EQ(std::bit_cast<std::uint32_t>(value),
                      std::bit_cast<std::uint32_t>(image.at(i, image_row)))
                << "stored row " << stored_row << ", column " << i;
        }
    }
    EXPECT_TRUE(same_bits(read_image(path), image));
}

TEST_F(ImageIo, ReadsBigEndianPfmTopDown) {
    // Made by hand: scale +1 means big-endian; rows bottom first. Values 1..6, top row 1 2 3.
    std::string bytes = "Pf\n3 2\n1.0\n";
    for (float value : {4.0f, 5.0f, 6.0f, 1.0f, 2.0f, 3.0f}) {
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>(bits >> shift);
    }
    const std::string path = file("big.pfm");
    write_raw(path, bytes);
    const Image image = read_image(path);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.data, (std::vector<float>{1, 2, 3, 4, 5, 6}));
}

TEST_F(ImageIo, PngIs16BitLinearCodes) {
    const std::vector<float> values = {0.0f,   1.0f,   0.5f,         1.0f / 65535.0f,
                                       0.25f,  -0.5f,  2.0f,         std::nanf(""),
                                       0.001f, 0.999f, 0.2f / 65535, 0.7f / 65535};
    Image image(4, 3);
    image.data = values;
    const std::string path = file("codes.png");
    write_image(path, image);

    // OpenCV as the independent decoder: 16-bit single channel, codes as computed.
    const cv::Mat mat = cv::imread(path, cv::IMREAD_UNCHANGED);
    ASSERT_EQ(mat.type(), CV_16UC1);
    const Image back = read_image(path);
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            const double v = image.at(i, j);
            const double clamped = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
            const long expected = std::lround(clamped * 65535.0);
            EXPECT_EQ(mat.at<std::uint16_t>(j, i), expected) << "value " << v;
            EXPECT_NEAR(back.at(i, j), expected / 65535.0, kFloatStepAtOne) << "value " << v;
        }
    }

    // Linear, and the file says so: one gAMA chunk of 1.0 (100000 in the file's units of 1e-5),
    // no sRGB or iCCP chunk; an independent read of the chunk list, not libpng's.
    const std::string bytes = read_bytes(path);
    ASSERT_EQ(bytes.substr(1, 3), "PNG");
    std::vector<std::string> chunks;
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
        const std::size_t length =
            (byte(at) << 24) | (byte(at + 1) << 16) | (byte(at + 2) << 8) | byte(at + 3);
        chunks.push_back(bytes.substr(at + 4, 4));
        at += 12 + length;
    }
    ASSERT_EQ(std::count(chunks.begin(), chunks.end(), "gAMA"), 1);
    const std::size_t gama = bytes.find("gAMA");
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    EXPECT_EQ((byte(gama + 4) << 24) | (byte(gama + 5) << 16) | (byte(gama + 6) << 8) |
                  byte(gama + 7),
              100000);
    EXPECT_EQ(std::count(chunks.begin(), chunks.end(), "sRGB"), 0);
    EXPECT_EQ(std::count(chunks.begin(), chunks.end(), "iCCP"), 0);
    EXPECT_EQ(chunks.back(), "IEND");
}

TEST_F(ImageIo, UnknownExtensionIsAnErrorAndWritesNothing) {
    const Image image = gradient(3, 3);
    for (const std::string name : {"out.tiff", "out", "out.exr.bak", "out.jpg"}) {
        expect_input_error([&] { write_image(file(name), image); }, file(name), ".exr|.pfm|.png");
    }
    EXPECT_TRUE(listing().empty());
    // Upper case is the same format.
    write_image(file("upper.EXR"), image);
    EXPECT_TRUE(same_bits(read_image(file("upper.EXR")), image));
}

TEST_F(ImageIo, MissingDirectoryIsAnError) {
    const std::string path = file("no/such/dir/out.exr");
    expect_input_error([&] { write_image(path, gradient(3, 3)); }, path, "does not exist");
    expect_input_error([&] { write_text_file(file("nope/out.csv"), "a,b\n"); },
                       file("nope/out.csv"), "does not exist");
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIo, BadImagesAreErrors) {
    expect_input_error([&] { write_image(file("empty.exr"), Image()); }, file("empty.exr"),
                       "empty image");
    Image inconsistent(4, 4);
    inconsistent.data.resize(3);
    expect_input_error([&] { write_image(file("bad.png"), inconsistent); }, file("bad.png"));
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIo, TruncatedAndMistypedFilesAreInputErrors) {
    // Every truncation of a small file, at every byte: reading either fails with InputError or
    // gives exactly what the whole file gives (a PNG cut inside its final IEND chunk still holds
    // every pixel, and OpenImageIO reads it). Never a crash, never silently different pixels.
    const Image image = gradient(16, 12);
    for (const std::string extension : {".exr", ".png", ".pfm"}) {
        const std::string whole = file("whole" + extension);
        write_image(whole, image);
        const Image expected = read_image(whole);
        const std::string bytes = read_bytes(whole);
        const std::string cut = file("cut" + extension);
        int failures = 0;
        for (std::size_t keep = 0; keep < bytes.size(); ++keep) {
            write_raw(cut, bytes.substr(0, keep));
            try {
                const Image back = read_image(cut);
                EXPECT_TRUE(same_bits(back, expected)) << extension << " cut to " << keep;
            } catch (const InputError& error) {
                ++failures;
                const std::string message = error.what();
                EXPECT_EQ(message.rfind(cut + ": ", 0), 0u) << message;
                EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            }
        }
        // Cuts that lose pixel data must all fail: all but the PNG's IEND tail (12 bytes).
        constexpr int kPngEndChunkBytes = 12;
        EXPECT_GE(failures, static_cast<int>(bytes.size()) - kPngEndChunkBytes) << extension;
    }
    const std::string text = file("text.png");
    write_raw(text, "this is not a picture\n");
    expect_input_error([&] { read_image(text); }, text);
    // A header claiming 60000 x 60000 is refused before anything is allocated for it.
    const std::string huge = file("huge.pfm");
    write_raw(huge, "Pf\n60000 60000\n-1\n" + std::string(64, '\0'));
    expect_input_error([&] { read_image(huge); }, huge, "more than the limit");
    expect_input_error([&] { read_image(file("missing.exr")); }, file("missing.exr"),
                       "no such file");
    expect_input_error([&] { read_image(dir_.string()); }, dir_.string(), "directory");
}

TEST_F(ImageIo, LongFileNamesStillGetATemporary) {
    // 250 characters: legal (NAME_MAX is 255), but too long to have ".tmp-<pid>-<n>" appended.
    const std::string name = std::string(246, 'n') + ".pfm";
    write_image(file(name), gradient(3, 2));
    EXPECT_EQ(listing(), std::vector<std::string>{name});
}

TEST_F(ImageIo, TextFilesAreReplacedWhole) {
    const std::string path = file("rows.csv");
    write_text_file(path, "old\n");
    write_text_file(path, "a,b\n1,2\n");
    EXPECT_EQ(read_bytes(path), "a,b\n1,2\n");
    write_text_file(path, "");
    EXPECT_EQ(read_bytes(path), "");
    EXPECT_EQ(listing(), std::vector<std::string>{"rows.csv"});
}

// Makes writes beyond `bytes` fail with EFBIG (as a full disk would), for this scope.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        // Exceeding the limit also raises SIGXFSZ, which would kill the test: ignore it so the
        // write returns EFBIG instead.
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        ::getrlimit(RLIMIT_FSIZE, &old_);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, old_handler_);
    }

private:
    rlimit old_{};
    void (*old_handler_)(int) = nullptr;
};

TEST_F(ImageIo, FailedWriteLeavesThePreviousFileAndNoTemporary) {
    constexpr rlim_t kLimitBytes = 4096;  // far below a 256 x 256 float image
    Image big(256, 256);
    for (std::size_t k = 0; k < big.data.size(); ++k) big.data[k] = std::sin(0.37f * k);
    for (const std::string name : {"keep.exr", "keep.pfm", "keep.png", "keep.csv"}) {
        SCOPED_TRACE(name);
        const std::string path = file(name);
        write_raw(path, "previous contents");
        {
            FileSizeLimit limit(kLimitBytes);
            if (name.ends_with(".csv")) {
                expect_input_error([&] { write_text_file(path, std::string(100000, 'x')); }, path);
            } else {
                expect_input_error([&] { write_image(path, big); }, path);
            }
        }
        EXPECT_EQ(read_bytes(path), "previous contents");
        EXPECT_EQ(listing(), std::vector<std::string>{name});
        fs::remove(path);
    }
}

TEST_F(ImageIo, TargetThatIsADirectoryIsLeftAlone) {
    // The rename is the step that fails here, after the temporary was written in full.
    fs::create_directory(dir_ / "taken.exr");
    expect_input_error([&] { write_image(file("taken.exr"), gradient(3, 3)); }, file("taken.exr"),
                       "cannot replace");
    EXPECT_TRUE(fs::is_directory(dir_ / "taken.exr"));
    EXPECT_EQ(listing(), std::vector<std::string>{"taken.exr"});
}

}  // namespace
}  // namespace aabench
