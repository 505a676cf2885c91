// Internal to the scene file reader (scene_io.cpp): a fast first try at pass 1 for the plain
// JSON that scene files are made of.
//
// nlohmann's parser spends most of its time in its lexer (a virtual-free but byte-at-a-time
// reader that copies every token into a buffer, then strtod): three quarters of a second for a
// 28 MB, 200,000-triangle file. parse_plain_json reads the same text in place and sends the
// same SAX events to the same handler (JsonBuilder), in the same order with the same values:
// integers as number_integer (negative) or number_unsigned, anything with a fraction or an
// exponent as number_float, every double correctly rounded (Clinger's exact case, or else
// std::from_chars) as glibc's strtod rounds it, so every value has the same bits.
//
// It handles only a subset and gives up (returns false) on anything else: a string with an
// escape, a control byte or a byte outside ASCII, an integer beyond 64 bits, a double that
// overflows or underflows, a byte-order mark, and every syntax error. The caller then parses
// the text again from the start with nlohmann, whose errors and values are the reference; so
// the fast path never decides what is accepted, only how fast the common case goes.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace aabench::scene_io_detail {

template <typename Sax>
class PlainJsonParser {
public:
    // A std::string, for the '\0' that follows its last byte: every loop below stops there
    // (it is neither a digit, nor whitespace, nor allowed in a string) without checking for
    // the end at every byte. A '\0' inside the text stops them too, and the parse gives up.
    PlainJsonParser(const std::string& text, Sax& sax)
        : at_(text.c_str()), end_(text.c_str() + text.size()), sax_(sax) {}

    // True when the whole text was one JSON value of the subset and every event went to the
    // handler; false when it gave up (the handler then holds a partial document).
    bool parse() {
        // The open containers, innermost last (true: an object). A loop rather than recursion,
        // so that deep nesting costs no stack (the handler refuses it, at 32 levels).
        std::vector<bool> open_objects;
        skip_whitespace();
        for (;;) {
            // A value starts here.
            if (at_ == end_) return false;
            if (*at_ == '{' || *at_ == '[') {
                const bool object = *at_++ == '{';
                if (!(object ? sax_.start_object(kUnknownSize) : sax_.start_array(kUnknownSize))) {
                    return false;
                }
                skip_whitespace();
                if (*at_ == (object ? '}' : ']')) {
                    ++at_;
                    if (!(object ? sax_.end_object() : sax_.end_array())) return false;
                } else {
                    open_objects.push_back(object);
                    if (object && !key()) return false;
                    continue;
                }
            } else if (!scalar()) {
                return false;
            }
            // After a value: close what ends here, then the next element or the end of text.
            for (;;) {
                skip_whitespace();
                if (open_objects.empty()) return at_ == end_;
                if (at_ == end_) return false;
                const bool object = open_objects.back();
                const char c = *at_++;
                if (c == ',') {
                    skip_whitespace();
                    if (object && !key()) return false;
                    break;
                }
                if (c != (object ? '}' : ']')) return false;
                open_objects.pop_back();
                if (!(object ? sax_.end_object() : sax_.end_array())) return false;
            }
        }
    }

private:
    // What nlohmann passes as the element count of a container it has not read yet.
    static constexpr std::size_t kUnknownSize = static_cast<std::size_t>(-1);
    // The exact case of number(): at most 19 digits fit 64 bits, 2^53 is the largest of the
    // integers a double holds all of below it, and 1e22 the largest power of ten it holds.
    static constexpr int kMaxExactDigits = 19;
    static constexpr std::uint64_t kMaxExactMantissa = std::uint64_t{1} << 53;
    static constexpr int kMaxExactPower10 = 22;
    static constexpr std::uint64_t kMaxInt64 = 9223372036854775807;
    static constexpr double kPowers10[kMaxExactPower10 + 1] = {
        1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    inline static const std::string kNoText;

    static bool is_digit(char c) { return c >= '0' && c <= '9'; }

    void skip_whitespace() {
        while (*at_ == ' ' || *at_ == '\n' || *at_ == '\r' || *at_ == '\t') ++at_;
    }

    // `"name"`, whitespace, `:`, whitespace. The key goes to the handler before the colon is
    // checked, as nlohmann does it.
    bool key() {
        if (!string_into(text_)) return false;
        if (!sax_.key(text_)) return false;
        skip_whitespace();
        if (*at_ != ':') return false;
        ++at_;
        skip_whitespace();
        return true;
    }

    // A string of printable ASCII without escapes (DEL included, as JSON allows it).
    bool string_into(std::string& out) {
        if (*at_ != '"') return false;
        const char* const first = ++at_;
        for (; *at_ != '"'; ++at_) {
            const auto byte = static_cast<unsigned char>(*at_);
            if (byte < 0x20 || byte >= 0x80 || byte == '\\') return false;  // '\0' included
        }
        out.assign(first, at_);
        ++at_;  // the closing quote
        return true;
    }

    bool literal(std::string_view word) {
        if (static_cast<std::size_t>(end_ - at_) < word.size() ||
            std::string_view(at_, word.size()) != word) {
            return false;
        }
        at_ += word.size();
        return true;
    }

    bool scalar() {
        switch (*at_) {
            case '"':
                return string_into(text_) && sax_.string(text_);
            case 't':
                return literal("true") && sax_.boolean(true);
            case 'f':
                return literal("false") && sax_.boolean(false);
            case 'n':
                return literal("null") && sax_.null();
            default:
                return number();
        }
    }

    // JSON's number grammar exactly: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    bool number() {
        const char* const first = at_;
        const bool negative = *at_ == '-';
        if (negative) ++at_;
        if (!is_digit(*at_)) return false;
        // The digits as one integer, for the exact case below; `digits` counts them all
        // (leading zeros too), so that 19 of them cannot overflow 64 bits.
        std::uint64_t mantissa = 0;
        int digits = 0;
        const auto take_digits = [&] {
            for (; is_digit(*at_); ++at_, ++digits) {
                mantissa = mantissa * 10 + static_cast<std::uint64_t>(*at_ - '0');
            }
        };
        if (*at_ == '0') {
            ++at_;
            ++digits;
        } else {
            take_digits();
        }
        bool integral = true;
        int exponent10 = 0;
        if (*at_ == '.') {
            integral = false;
            if (!is_digit(*++at_)) return false;
            const int integer_digits = digits;
            take_digits();
            exponent10 = integer_digits - digits;
        }
        bool long_exponent = false;
        if (*at_ == 'e' || *at_ == 'E') {
            integral = false;
            bool exponent_negative = false;
            if (*++at_ == '+' || *at_ == '-') exponent_negative = *at_++ == '-';
            if (!is_digit(*at_)) return false;
            int written = 0;
            for (; is_digit(*at_); ++at_) {
                if (written > kMaxExactPower10 * 10) long_exponent = true;  // no overflow below
                if (!long_exponent) written = written * 10 + (*at_ - '0');
            }
            exponent10 += exponent_negative ? -written : written;
        }
        // An integer that does not fit nlohmann's 64-bit types becomes a double there, and a
        // double out of range is its error: both are left to it (from_chars says
        // result_out_of_range and leaves the value alone).
        // Up to 19 digits, `mantissa` holds the integer exactly.
        if (integral && negative) {
            nlohmann::json::number_integer_t value = 0;
            if (digits <= kMaxExactDigits && mantissa <= kMaxInt64) {
                value = -static_cast<nlohmann::json::number_integer_t>(mantissa);
            } else if (!parsed(std::from_chars(first, at_, value))) {
                return false;
            }
            return sax_.number_integer(value);
        }
        if (integral) {
            nlohmann::json::number_unsigned_t value = mantissa;
            if (digits > kMaxExactDigits && !parsed(std::from_chars(first, at_, value))) {
                return false;
            }
            return sax_.number_unsigned(value);
        }
        double value = 0.0;
        if (digits <= kMaxExactDigits && !long_exponent && mantissa <= kMaxExactMantissa &&
            exponent10 >= -kMaxExactPower10 && exponent10 <= kMaxExactPower10) {
            // Clinger's fast path (Clinger 1990): the mantissa and the power of ten are both
            // doubles exactly, so one multiplication or division rounds the exact value
            // correctly, as strtod and from_chars do. Most of a scene's numbers take it.
            value = static_cast<double>(mantissa);
            value = exponent10 < 0 ? value / kPowers10[-exponent10] : value * kPowers10[exponent10];
            if (negative) value = -value;
        } else if (!parsed(std::from_chars(first, at_, value)) || !std::isfinite(value)) {
            return false;
        }
        // nlohmann passes the number's text along; JsonBuilder ignores it, so it is not copied.
        return sax_.number_float(value, kNoText);
    }

    bool parsed(const std::from_chars_result& result) const {
        return result.ec == std::errc() && result.ptr == at_;
    }

    const char* at_;
    const char* const end_;
    Sax& sax_;
    std::string text_;  // the last key or string, reused to save allocations
};

// See the opening comment. Returns false when the caller must parse the text with nlohmann.
template <typename Sax>
bool parse_plain_json(const std::string& text, Sax& sax) {
    return PlainJsonParser<Sax>(text, sax).parse();
}

}  // namespace aabench::scene_io_detail
