// What several subcommands share: where a scene comes from, sizes, output paths, progress.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "harness/cli/command.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {

std::pair<int, int> parse_size(const std::string& text, const std::string& where) {
    const auto x = text.find('x');
    long long w = -1, h = -1;
    try {
        std::size_t used_w = 0, used_h = 0;
        if (x == std::string::npos) throw std::invalid_argument("no x");
        w = std::stoll(text.substr(0, x), &used_w);
        h = std::stoll(text.substr(x + 1), &used_h);
        if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("junk");
    } catch (const std::exception&) {
        throw InputError(fmt::format("{}: '{}' is not a size of the form WxH (e.g. 256x256)",
                                     where, text));
    }
    check_image_size(w, h, where);
    return {static_cast<int>(w), static_cast<int>(h)};
}

void add_scene_options(CLI::App* cmd, SceneSource& src) {
    auto* scene =
        cmd->add_option("--scene", src.scene_file, "scene file (JSON, docs/scene-format.md)");
    auto* pattern =
        cmd->add_option("--pattern", src.pattern, "built-in pattern ID[:key=value,...]");
    auto* size = cmd->add_option("--size", src.size, "image size WxH, with --pattern");
    scene->excludes(pattern)->excludes(size);
    pattern->needs(size);
    size->needs(pattern);
}

Scene load_scene(const SceneSource& src) {
    if (!src.scene_file.empty()) return read_scene_file(src.scene_file);
    if (src.pattern.empty()) throw InputError("give --scene FILE.json or --pattern ID --size WxH");
    const auto [w, h] = parse_size(src.size, "--size");
    return make_pattern(src.pattern, w, h);
}

void check_image_output_path(const std::string& path) {
    for (const char* ext : {".exr", ".pfm", ".png"}) {
        const std::string e(ext);
        if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0) {
            return;
        }
    }
    throw InputError(
        fmt::format("--out: {}: unsupported image format (use .exr, .pfm or .png)", path));
}

std::string default_results_dir(const std::string& kind) {
    const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    return fmt::format("results/{}-{:%Y%m%d-%H%M%S}", kind, fmt::gmtime(now));
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("{}: cannot open ({})", path, std::strerror(errno)));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(fmt::format("{}: cannot read", path));
    return text;
}

std::vector<std::string> split_path_list(const std::string& text, const std::string& where) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const auto comma = text.find(',', start);
        items.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
        if (items.back().empty()) {
            throw InputError(fmt::format("{}: empty item in the list '{}'", where, text));
        }
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

std::vector<SceneFileInput> read_scene_files(const std::vector<std::string>& paths) {
    std::vector<SceneFileInput> files;
    for (const std::string& path : paths) files.push_back({path, read_scene_file(path)});
    return files;
}

namespace {
double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
}  // namespace

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), start_s_(now_s()) {}

void ProgressBar::operator()(std::size_t done, std::size_t total, const std::string& what) {
    if (!enabled_ || total == 0) return;
    constexpr int kWidth = 30;
    const double elapsed = now_s() - start_s_;
    const double left = elapsed / done * (total - done);
    const int filled = static_cast<int>(kWidth * done / total);
    // Nothing done yet: the bar is drawn, the time left is not known.
    const std::string time_left =
        done == 0 ? std::string("--:--")
                  : fmt::format("{:.0f}:{:02.0f}", std::floor(left / 60), std::fmod(left, 60.0));
    fmt::print(stderr, "\r\033[K[{}{}] {}/{}  {} left  {}", std::string(filled, '#'),
               std::string(kWidth - filled, '.'), done, total, time_left, what);
    if (done == total) fmt::print(stderr, "\r\033[K");
}

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

}  // namespace aabench
