// A SAX handler for tests that keeps every event as a line of text, numbers with their type
// and doubles with their bits: two parsers agree when their logs are equal
// (tests/plain_json_parser_test.cpp, tests/fuzz/scene_reader_fuzz.cpp).
#pragma once

#include <fmt/format.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace aabench {

// Every SAX event as a line of text; numbers with their type and, for doubles, their bits.
class JsonEventLog {
public:
    std::vector<std::string> events;

    bool null() { return add("null"); }
    bool boolean(bool value) { return add(value ? "true" : "false"); }
    bool number_integer(std::int64_t value) { return add(fmt::format("int {}", value)); }
    bool number_unsigned(std::uint64_t value) { return add(fmt::format("unsigned {}", value)); }
    bool number_float(double value, const std::string&) {
        return add(fmt::format("double {:016x}", std::bit_cast<std::uint64_t>(value)));
    }
    bool string(std::string& value) { return add("string " + value); }
    bool binary(nlohmann::json::binary_t&) { return add("binary"); }
    bool start_object(std::size_t) { return add("{"); }
    bool end_object() { return add("}"); }
    bool start_array(std::size_t) { return add("["); }
    bool end_array() { return add("]"); }
    bool key(std::string& value) { return add("key " + value); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception&) {
        return false;
    }

private:
    bool add(std::string event) {
        events.push_back(std::move(event));
        return true;
    }
};

}  // namespace aabench
