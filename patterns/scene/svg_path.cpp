// SVG path data (svg_path.h).
#include "patterns/scene/svg_path.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>

namespace aabench {
namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class PathReader {
public:
    PathReader(std::string_view d, double max_coordinate) : d_(d), max_(max_coordinate) {}

    std::vector<SegmentContour> read() {
        skip_wsp();
        if (at_end()) throw SvgPathError(pos_, "empty path data (expected a moveto, M or m)");
        if (d_[pos_] != 'M' && d_[pos_] != 'm') {
            throw SvgPathError(pos_, fmt::format("path data must start with a moveto (M or m), "
                                                 "found '{}'",
                                                 shown(d_[pos_])));
        }
        char command = 0;
        while (true) {
            skip_wsp();
            if (at_end()) break;
            const char c = d_[pos_];
            if (is_command(c)) {
                command = c;
                ++pos_;
                if (c == 'Z' || c == 'z') {
                    close_subpath();
                    continue;
                }
            } else if (!starts_number()) {
                throw SvgPathError(pos_, fmt::format("unknown path command '{}' (expected one of "
                                                     "M L H V Q T C S Z, or a number)",
                                                     shown(c)));
            } else if (command == 0 || command == 'Z' || command == 'z') {
                throw SvgPathError(pos_,
                                   "a number with no command before it (after Z a path "
                                   "continues with a command)");
            }
            command = segment(command);
        }
        finish_subpath();
        return std::move(contours_);
    }

private:
    bool at_end() const { return pos_ >= d_.size(); }
    static std::string shown(char c) {
        if (c >= 0x20 && c < 0x7f) return std::string(1, c);
        return fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
    }
    static bool is_command(char c) {
        switch (c) {
            case 'M':
            case 'm':
            case 'L':
            case 'l':
            case 'H':
            case 'h':
            case 'V':
            case 'v':
            case 'Q':
            case 'q':
            case 'T':
            case 't':
            case 'C':
            case 'c':
            case 'S':
            case 's':
            case 'Z':
            case 'z':
                return true;
            default:
                return false;
        }
    }
    void skip_wsp() {
        while (!at_end() && is_wsp(d_[pos_])) ++pos_;
    }
    void skip_comma_wsp() {
        skip_wsp();
        if (!at_end() && d_[pos_] == ',') {
            ++pos_;
            skip_wsp();
        }
    }
    bool starts_number() const {
        if (at_end()) return false;
        const char c = d_[pos_];
        return is_digit(c) || c == '.' || c == '-' || c == '+';
    }

    // One number of the SVG grammar: sign? (digits ('.' digits?)? | '.' digits) exponent?,
    // exponent = ('e' | 'E') sign? digits. `what` names it in messages.
    double number(const char* what) {
        skip_wsp();
        const std::size_t start = pos_;
        std::size_t p = pos_;
        if (p < d_.size() && (d_[p] == '+' || d_[p] == '-')) ++p;
        const std::size_t mantissa = p;
        while (p < d_.size() && is_digit(d_[p])) ++p;
        bool digits = p > mantissa;
        if (p < d_.size() && d_[p] == '.') {
            const std::size_t fraction = ++p;
            while (p < d_.size() && is_digit(d_[p])) ++p;
            digits = digits || p > fraction;
        }
        if (!digits) {
            throw SvgPathError(start, at_end()
                                          ? fmt::format("missing number ({}) at the end of the "
                                                        "path data",
                                                        what)
                                          : fmt::format("expected a number ({}), found '{}'", what,
                                                        shown(d_[start])));
        }
        if (p < d_.size() && (d_[p] == 'e' || d_[p] == 'E')) {
            std::size_t q = p + 1;
            if (q < d_.size() && (d_[q] == '+' || d_[q] == '-')) ++q;
            const std::size_t exponent = q;
            while (q < d_.size() && is_digit(d_[q])) ++q;
            if (q > exponent) p = q;  // else the 'e' is not part of the number
        }
        std::string_view text = d_.substr(start, p - start);
        if (text.front() == '+') text.remove_prefix(1);
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc::result_out_of_range || !std::isfinite(value)) {
            throw SvgPathError(
                start, fmt::format("number {} is out of range", d_.substr(start, p - start)));
        }
        pos_ = p;
        skip_comma_wsp();
        return value;
    }

    Point coordinate(Point relative_to, bool relative, std::size_t at) {
        const double x = number("x");
        const double y = number("y");
        return checked(relative ? Point{relative_to.x + x, relative_to.y + y} : Point{x, y}, at);
    }
    Point checked(Point p, std::size_t at) const {
        if (!(std::abs(p.x) <= max_ && std::abs(p.y) <= max_)) {
            throw SvgPathError(at, fmt::format("point ({}, {}) lies beyond {:g} px of the origin, "
                                               "the limit of curve coordinates",
                                               p.x, p.y, max_));
        }
        return p;
    }

    // One segment (or moveto) of `command` at pos_; returns the command implicit repeats use.
    char segment(char command) {
        skip_wsp();
        const std::size_t at = pos_;  // the segment's first number
        const bool rel = command >= 'a';
        const char upper = static_cast<char>(rel ? command - 'a' + 'A' : command);
        const Point cur = current_;
        Segment s;
        s.p[0] = cur;
        switch (upper) {
            case 'M':
                finish_subpath();
                current_ = start_ = coordinate(cur, rel, at);
                open_ = true;
                last_control_.reset();
                return rel ? 'l' : 'L';
            case 'L':
                s.p[1] = coordinate(cur, rel, at);
                break;
            case 'H': {
                const double x = number("x");
                s.p[1] = checked({rel ? cur.x + x : x, cur.y}, at);
                break;
            }
            case 'V': {
                const double y = number("y");
                s.p[1] = checked({cur.x, rel ? cur.y + y : y}, at);
                break;
            }
            case 'Q':
            case 'T':
                s.degree = 2;
                s.p[1] = upper == 'Q' ? coordinate(cur, rel, at) : checked(reflected('Q'), at);
                s.p[2] = coordinate(cur, rel, at);
                break;
            default:  // 'C', 'S'
                s.degree = 3;
                s.p[1] = upper == 'C' ? coordinate(cur, rel, at) : checked(reflected('C'), at);
                s.p[2] = coordinate(cur, rel, at);
                s.p[3] = coordinate(cur, rel, at);
                break;
        }
        reopen();
        segments_.push_back(s);
        current_ = s.end();
        last_kind_ = s.degree == 2 ? 'Q' : s.degree == 3 ? 'C' : 'L';
        last_control_ = s.degree >= 2 ? std::optional<Point>(s.p[s.degree - 1]) : std::nullopt;
        return command;
    }
    // The first control point of T or S: the previous segment's last control point reflected
    // about the current point when that segment was of the same kind, else the current point.
    Point reflected(char kind) const {
        if (last_control_ && last_kind_ == kind) {
            return {2.0 * current_.x - last_control_->x, 2.0 * current_.y - last_control_->y};
        }
        return current_;
    }
    // A drawing command after Z starts a new subpath at the last subpath's start point.
    void reopen() {
        if (open_) return;
        open_ = true;
        current_ = start_;
    }
    void close_subpath() {
        finish_subpath();
        current_ = start_;
        last_control_.reset();
        last_kind_ = 'Z';
    }
    void finish_subpath() {
        open_ = false;
        if (segments_.empty()) return;
        if (!(segments_.back().end() == start_)) {
            Segment closing;
            closing.p[0] = segments_.back().end();
            closing.p[1] = start_;
            segments_.push_back(closing);
        }
        if (encloses_something(segments_)) contours_.push_back(std::move(segments_));
        segments_.clear();
    }
    static bool encloses_something(const SegmentContour& c) {
        std::vector<Point> distinct;
        for (const Segment& s : c) {
            if (s.degree > 1) return true;
            bool seen = false;
            for (const Point& q : distinct) seen = seen || q == s.p[0];
            if (!seen) distinct.push_back(s.p[0]);
        }
        return distinct.size() >= 3;
    }

    std::string_view d_;
    double max_;
    std::size_t pos_ = 0;
    Point current_, start_;
    bool open_ = false;
    std::optional<Point> last_control_;
    char last_kind_ = 0;
    SegmentContour segments_;
    std::vector<SegmentContour> contours_;
};

}  // namespace

std::vector<SegmentContour> parse_svg_path(std::string_view d, double max_coordinate) {
    // An arc command anywhere is refused at its position, whatever precedes it.
    for (std::size_t k = 0; k < d.size(); ++k) {
        if (d[k] == 'A' || d[k] == 'a') {
            throw SvgPathError(k,
                               fmt::format("arc command '{}' is not supported: an elliptical arc "
                                           "is not a polynomial curve, and the exact references "
                                           "integrate lines and Bezier segments (write it as "
                                           "cubics)",
                                           d[k]));
        }
    }
    return PathReader(d, max_coordinate).read();
}

}  // namespace aabench
