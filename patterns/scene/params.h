// Parameters of methods, patterns and filters, declared once as a table and parsed from spec
// strings of the form `ID[:key=value,...]` (docs/architecture.md, "Method spec").
//
// A ParamSpec row gives the name, the kind, the default, the range (or the choices) and a
// one-line reason. resolve() checks a parsed spec against the table: an unknown key, a value
// of the wrong kind or out of range is an InputError that names the valid keys or the range.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace aabench {

enum class ParamKind { kInt, kReal, kChoice };

struct ParamSpec {
    std::string name;
    ParamKind kind = ParamKind::kReal;
    double default_value = 0.0;  // kInt and kReal
    double min_value = 0.0;      // inclusive range, kInt and kReal
    double max_value = 0.0;
    // kChoice: the choices, the first one the default. kReal: words accepted besides
    // a number (taa's alpha=running), read with ParamValues::get_choice; usually none.
    std::vector<std::string> choices;
    std::string doc;                   // what it is and why the default

    std::string default_string() const;
    std::string range_string() const;  // "1..256", "box|gaussian" or "0.001..1|running"
};

// `ID[:key=value,...]` split into its parts; no validation beyond the syntax.
struct SpecString {
    std::string id;
    std::vector<std::pair<std::string, std::string>> assignments;
};
SpecString parse_spec_string(const std::string& text);

// The one of `candidates` closest to `word` (Levenshtein distance), when close enough to be a
// slip of the keyboard: at most a third of the word's letters apart (two for short words).
// Empty when none is. Every "unknown ..." message of a name or value uses it.
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);
// "; did you mean 'X'?" for closest_name's answer (quoted as `quote` + X + `quote`), or "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates,
                         const std::string& quote = "'");

// Resolved values: every parameter of the table present, defaults filled in, in table order.
class ParamValues {
public:
    int get_int(const std::string& name) const;
    double get_real(const std::string& name) const;
    // A kChoice parameter's choice; for a kReal one, the word given in place of a
    // number (ParamSpec::choices), or "" when it is a number (get_real is NaN for a word).
    const std::string& get_choice(const std::string& name) const;

    // Canonical `key=value,...` in table order; reals printed shortest-round-trip.
    std::string to_string() const;
    // The same pairs, for a Scene's metadata or a result row.
    std::vector<std::pair<std::string, std::string>> items() const;

    void set(const std::string& name, ParamKind kind, double number, std::string choice);

private:
    struct Value {
        std::string name;
        ParamKind kind;
        double number;
        std::string choice;
    };
    const Value& find(const std::string& name) const;
    std::vector<Value> values_;
};

// Checks `assignments` against `table`. `what` names the owner for messages, e.g.
// "method 'ssaa'". Throws InputError.
ParamValues resolve_params(const std::string& what, const std::vector<ParamSpec>& table,
                           const std::vector<std::pair<std::string, std::string>>& assignments);

// Shortest text that reads back as the same double.
std::string format_real(double value);

}  // namespace aabench
