// Internal to the scene file reader and writer (scene_io.cpp, scene_io_world.cpp,
// world_check.cpp): the one-line error with its JSON path, and how values are shown in it.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "patterns/scene/scene.h"

namespace aabench::scene_io_detail {

using Json = nlohmann::ordered_json;

// Long tokens and strings are cut in messages so the message stays one readable line.
inline constexpr std::size_t kMaxQuotedChars = 40;

// Throws InputError "<source>: <path>: <problem>" (or "<source>: <problem>" at the top).
[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem);
bool is_plain_name(const std::string& key);
// One line of printable ASCII; other bytes as \xNN; cut at max_chars with "...".
std::string printable(std::string_view text, bool escape_quotes = false,
                      std::size_t max_chars = kMaxQuotedChars);
// `shapes[3].contours`: plain keys joined by dots, anything else quoted in brackets.
std::string child_path(const std::string& path, const std::string& key);
std::string child_path(const std::string& path, std::size_t index);
// A JSON value as a message shows it: `null`, `"text"`, `[1,2]`, `an object`.
std::string describe(const Json& value);

// ---- The version-2 world (scene_io_world.cpp) ----

// Reads camera, ambient, lights, objects, edges and effects from a version-2 root object
// whose other keys the caller has checked; then check_world(). Throws InputError.
World read_world(const Json& root, const std::string& source);
// The world's keys as lines of a scene file (each line ends with ",\n" except the last).
std::string world_to_json(const World& world);

}  // namespace aabench::scene_io_detail
