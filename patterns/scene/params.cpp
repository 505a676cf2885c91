#include "patterns/scene/params.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "patterns/scene/scene.h"

namespace aabench {

std::string format_real(double value) { return fmt::format("{}", value); }

std::string ParamSpec::default_string() const {
    switch (kind) {
        case ParamKind::kInt:
            return fmt::format("{}", static_cast<long long>(default_value));
        case ParamKind::kReal:
            return format_real(default_value);
        case ParamKind::kChoice:
            return choices.empty() ? std::string() : choices.front();
    }
    return {};
}

std::string ParamSpec::range_string() const {
    switch (kind) {
        case ParamKind::kInt:
            return fmt::format("{}..{}", static_cast<long long>(min_value),
                               static_cast<long long>(max_value));
        case ParamKind::kReal:
            return fmt::format("{}..{}{}{}", format_real(min_value), format_real(max_value),
                               choices.empty() ? "" : "|", fmt::join(choices, "|"));
        case ParamKind::kChoice:
            // No choices: free text that its owner parses (resolve_params).
            return choices.empty() ? "text" : fmt::format("{}", fmt::join(choices, "|"));
    }
    return {};
}

SpecString parse_spec_string(const std::string& text) {
    SpecString spec;
    const auto colon = text.find(':');
    spec.id = text.substr(0, colon);
    if (spec.id.empty()) throw InputError(fmt::format("spec '{}': missing id before ':'", text));
    if (colon == std::string::npos) return spec;
    const std::string rest = text.substr(colon + 1);
    std::size_t start = 0;
    while (start <= rest.size()) {
        const auto comma = rest.find(',', start);
        const std::string item =
            rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
            throw InputError(
                fmt::format("spec '{}': '{}' is not of the form key=value", text, item));
        }
        spec.assignments.emplace_back(item.substr(0, eq), item.substr(eq + 1));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return spec;
}

namespace {

// Levenshtein distance (insert, delete, substitute one character each cost 1).
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates,
                         const std::string& quote) {
    const std::string guess = closest_name(word, candidates);
    return guess.empty() ? "" : fmt::format("; did you mean {}{}{}?", quote, guess, quote);
}

namespace {

bool parse_double(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && errno == 0 && std::isfinite(out);
}

}  // namespace

ParamValues resolve_params(const std::string& what, const std::vector<ParamSpec>& table,
                           const std::vector<std::pair<std::string, std::string>>& assignments) {
    std::vector<std::string> names;
    for (const ParamSpec& p : table) names.push_back(p.name);
    for (std::size_t i = 0; i < assignments.size(); ++i) {
        const auto& key = assignments[i].first;
        if (std::find(names.begin(), names.end(), key) == names.end()) {
            throw InputError(fmt::format(
                "{}: unknown parameter '{}'{} (valid: {})", what, key, did_you_mean(key, names),
                names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "))));
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (assignments[j].first == key) {
                throw InputError(fmt::format("{}: parameter '{}' given twice", what, key));
            }
        }
    }
    ParamValues values;
    for (const ParamSpec& p : table) {
        const std::string* given = nullptr;
        for (const auto& [key, value] : assignments) {
            if (key == p.name) given = &value;
        }
        if (p.kind == ParamKind::kChoice && p.choices.empty()) {
            // A choice without choices is free text that its owner parses and checks (ssaa's
            // list of sample positions): empty by default, and left out of the canonical spec
            // while empty (items()), so that specs recorded before it was added stay the same.
            values.set(p.name, p.kind, 0.0, given ? *given : std::string());
            continue;
        }
        if (p.kind == ParamKind::kChoice) {
            std::string choice = given ? *given : p.choices.front();
            if (std::find(p.choices.begin(), p.choices.end(), choice) == p.choices.end()) {
                throw InputError(fmt::format("{}: {}={} is not one of {}{}", what, p.name, choice,
                                             p.range_string(), did_you_mean(choice, p.choices)));
            }
            values.set(p.name, p.kind, 0.0, choice);
            continue;
        }
        if (given && std::find(p.choices.begin(), p.choices.end(), *given) != p.choices.end()) {
            values.set(p.name, p.kind, std::nan(""), *given);  // a word in place of a number
            continue;
        }
        double number = p.default_value;
        if (given) {
            if (!parse_double(*given, number)) {
                throw InputError(
                    fmt::format("{}: {}={} is not a finite number{}{}", what, p.name, *given,
                                p.choices.empty() ? "" : " nor ", fmt::join(p.choices, "|")));
            }
            if (p.kind == ParamKind::kInt && number != std::floor(number)) {
                throw InputError(
                    fmt::format("{}: {}={} is not an integer", what, p.name, *given));
            }
            // Written so that a NaN would fail too.
            if (!(number >= p.min_value && number <= p.max_value)) {
                throw InputError(fmt::format("{}: {}={} is out of range {}", what, p.name,
                                             *given, p.range_string()));
            }
        }
        values.set(p.name, p.kind, number, {});
    }
    return values;
}

void ParamValues::set(const std::string& name, ParamKind kind, double number,
                      std::string choice) {
    for (Value& v : values_) {
        if (v.name == name) {
            v = Value{name, kind, number, std::move(choice)};
            return;
        }
    }
    values_.push_back(Value{name, kind, number, std::move(choice)});
}

const ParamValues::Value& ParamValues::find(const std::string& name) const {
    for (const Value& v : values_) {
        if (v.name == name) return v;
    }
    // A programming error (a factory asking for a parameter its table does not declare).
    throw std::logic_error("ParamValues: no parameter named " + name);
}

int ParamValues::get_int(const std::string& name) const {
    return static_cast<int>(find(name).number);
}
double ParamValues::get_real(const std::string& name) const { return find(name).number; }
const std::string& ParamValues::get_choice(const std::string& name) const {
    return find(name).choice;
}

std::vector<std::pair<std::string, std::string>> ParamValues::items() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const Value& v : values_) {
        switch (v.kind) {
            case ParamKind::kInt:
                out.emplace_back(v.name, fmt::format("{}", static_cast<long long>(v.number)));
                break;
            case ParamKind::kReal:
                out.emplace_back(v.name, v.choice.empty() ? format_real(v.number) : v.choice);
                break;
            case ParamKind::kChoice:
                // Empty only for free text not given (resolve_params): `key=` would not parse.
                if (!v.choice.empty()) out.emplace_back(v.name, v.choice);
                break;
        }
    }
    return out;
}

std::string ParamValues::to_string() const {
    std::string out;
    for (const auto& [key, value] : items()) {
        if (!out.empty()) out += ',';
        out += key + '=' + value;
    }
    return out;
}

}  // namespace aabench
