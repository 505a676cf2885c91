// aabench list: the registered methods, patterns and reference filters with their parameters,
// and the built-in sequences.
#include <fmt/format.h>

#include <type_traits>

#include "harness/cli/command.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/sequence.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

std::string param_line(const ParamSpec& p) {
    return fmt::format("      {:<14} default {:<10} range {:<16} {}", p.name, p.default_string(),
                       p.range_string(), p.doc);
}

template <class Row>
void print_rows(const std::vector<Row>& rows) {
    for (const Row& r : rows) {
        fmt::print("  {:<18} {}\n", r.id, r.summary);
        if constexpr (std::is_same_v<Row, MethodInfo>) {
            fmt::print("      curves: {}\n", r.traits->curves);  // how it draws Bezier curves
        }
        for (const ParamSpec& p : r.params) fmt::print("{}\n", param_line(p));
    }
}

class ListCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        return app.add_subcommand("list",
                                  "methods, patterns and reference filters with their parameters, "
                                  "and the built-in sequences");
    }
    int run(const Invocation&) override {
        fmt::print("methods (--method ID[:key=value,...]):\n");
        print_rows(method_registry());
        fmt::print("\npatterns (--pattern ID[:key=value,...]):\n");
        print_rows(pattern_registry());
        fmt::print("\nreference filters (aabench reference --filter ID[:key=value,...]):\n");
        print_rows(filter_registry());
        fmt::print("\nsequences (compare --sequences NAME,...; docs/sequences.md):\n");
        for (const SequenceSpec& s : sequence_registry()) {
            fmt::print("  {:<18} {}\n", s.name, s.summary);
        }
        return 0;
    }
};

}  // namespace

std::unique_ptr<Command> make_list_command() { return std::make_unique<ListCommand>(); }

}  // namespace aabench
