// The scene file reader's and writer's shared pieces (scene_io_detail.h): the one-line error
// with its JSON path, and how values and keys are shown in it.
#include "patterns/scene/scene_io_detail.h"

#include <fmt/format.h>

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
