// The scene file reader's and writer's shared pieces (scene_io_detail.h): the one-line error
// with its JSON path, and how values and keys are shown in it.
#include "patterns/scene/scene_io_detail.h"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <string_view>

namespace aabench {
namespace scene_io_detail {

[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem) {
    if (path.empty()) throw InputError(fmt::format("{}: {}", source, problem));
    throw InputError(fmt::format("{}: {}: {}", source, path, problem));
}

bool is_plain_name(const std::string& key) {
    if (key.empty()) return false;
    for (char c : key) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '_' || c == '-';
        if (!ok) return false;
    }
    return true;
}

// Keeps a message to one line of printable ASCII: control and non-ASCII bytes (which may not
// even be valid UTF-8 when the error is about encoding) are shown as \xNN.
std::string printable(std::string_view text, bool escape_quotes, std::size_t max_chars) {
    std::string out;
    const bool cut = text.size() > max_chars;
    for (unsigned char c : text.substr(0, max_chars)) {
        if (escape_quotes && (c == '"' || c == '\\')) {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += fmt::format("\\x{:02x}", c);
        }
    }
    if (cut) out += "...";
    return out;
}

// `shapes[3].contours`: plain keys joined by dots, anything else quoted in brackets so the path
// stays unambiguous (`metadata["a.b"]`).
std::string child_path(const std::string& path, const std::string& key) {
    if (is_plain_name(key)) return path.empty() ? key : path + "." + key;
    return path + "[\"" + printable(key, /*escape_quotes=*/true) + "\"]";
}

std::string child_path(const std::string& path, std::size_t index) {
    return fmt::format("{}[{}]", path, index);
}

double read_image_value(const Json& value, const std::string& source, const LazyPath& path) {
    // Integers are numbers too (`"value": 1`); JSON text cannot hold inf or NaN, and the
    // builder rejected overflow, but a tree can: check anyway.
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
        fail(source, path.str(), "expected a finite number, found " + describe(value));
    }
    const double v = value.get<double>();
    static_assert(kMaxValue == 1e30);
    if (!(std::abs(v) <= kMaxValue)) {
        fail(source, path.str(),
             fmt::format("{} is beyond the values an image holds, +-1e30 (images are float32)",
                         Json(v).dump()));
    }
    return v;
}

Rgb read_rgb(const Json& value, const std::string& source, const LazyPath& path, int version) {
    if (version < kColourVersion) {
        fail(source, path.str(),
             fmt::format("expected a finite number, found {} (colours [r, g, b] need version {})",
                         describe(value), kColourVersion));
    }
    if (!value.is_array() || value.size() != 3) {
        fail(source, path.str(),
             fmt::format("expected a colour [r, g, b] of three finite numbers, found {}",
                         describe(value)));
    }
    Rgb rgb{};
    for (std::size_t c = 0; c < 3; ++c) {
        const LazyPath component(path, c);
        if (!value[c].is_number() || !std::isfinite(value[c].get<double>())) {
            fail(source, component.str(),
                 fmt::format("expected a finite number (a colour's {} component), found {}",
                             "RGB"[c], describe(value[c])));
        }
        rgb[c] = read_image_value(value[c], source, component);
    }
    return rgb;
}

std::string describe(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return value.get<bool>() ? "true" : "false";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float:
            return value.dump();
        case Json::value_t::string:
            return "the string \"" +
                   printable(value.get_ref<const std::string&>(), /*escape_quotes=*/true) + "\"";
        case Json::value_t::array: {
            // Small arrays are clearest shown as they are (`["1",2]`); big ones by their size.
            const std::string text = value.dump();
            if (text.size() <= kMaxQuotedChars) return printable(text);
            return fmt::format("an array of {} elements", value.size());
        }
        case Json::value_t::object:
            return "an object";
        default:
            return value.type_name();
    }
}

}  // namespace scene_io_detail

}  // namespace aabench
