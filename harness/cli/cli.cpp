// The aabench command line: the table of subcommands (one file each, cmd_*.cpp) and the
// dispatch. Parsing happens in this room and nowhere else; each subcommand calls library
// stages in the order pattern/scene -> method -> image -> reference, metrics, timing ->
// results -> report.
#include "harness/cli/cli.h"

#include <algorithm>
#include <regex>

#include <fmt/format.h>

#include "harness/cli/command.h"
#include "harness/report/interrupt.h"
#include "patterns/scene/params.h"

namespace aabench {
namespace {

std::vector<std::unique_ptr<Command>> all_commands() {
    std::vector<std::unique_ptr<Command>> commands;
    commands.push_back(make_list_command());
    commands.push_back(make_render_command());
    commands.push_back(make_reference_command());
    commands.push_back(make_export_command());
    commands.push_back(make_plan_command());
    commands.push_back(make_compare_command());
    commands.push_back(make_merge_command());
    commands.push_back(make_hardcases_command());
    commands.push_back(make_claims_command());
    commands.push_back(make_score_command());
    commands.push_back(make_check_command());
    return commands;
}

// CLI11 reports an unknown first word as "A subcommand is required"; name it instead.
bool check_command_word(int argc, char** argv, const std::vector<CLI::App*>& subs) {
    if (argc <= 1 || argv[1][0] == '-') return true;
    const std::string word = argv[1];
    std::string valid;
    std::vector<std::string> names;
    for (const CLI::App* sub : subs) {
        if (sub->get_name() == word) return true;
        valid += (valid.empty() ? "" : ", ") + sub->get_name();
        names.push_back(sub->get_name());
    }
    const std::string guess = closest_name(word, names);
    fmt::print(stderr, "aabench: unknown command '{}'{} (valid: {})\n", word,
               guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess), valid);
    return false;
}

// For arguments CLI11 did not expect: the first unknown --option of the subcommand, with the
// closest valid one ("--ouput: unknown option of render; did you mean --out?"). Empty when no
// unknown --option is among the arguments (a stray positional value, say).
std::string unknown_option_message(int argc, char** argv, const std::vector<CLI::App*>& subs) {
    const CLI::App* sub = nullptr;
    for (const CLI::App* s : subs) sub = argc > 1 && s->get_name() == argv[1] ? s : sub;
    if (!sub) return {};
    std::vector<std::string> valid;
    for (const CLI::Option* option : sub->get_options()) {
        for (const std::string& name : option->get_lnames()) valid.push_back("--" + name);
    }
    for (int k = 2; k < argc; ++k) {
        std::string arg = argv[k];
        if (arg.rfind("--", 0) != 0 || arg.size() == 2) continue;
        arg = arg.substr(0, arg.find('='));
        if (std::find(valid.begin(), valid.end(), arg) != valid.end()) continue;
        const std::string guess = closest_name(arg, valid);
        return fmt::format("{}: unknown option of {}{}", arg, sub->get_name(),
                           guess.empty() ? "" : fmt::format("; did you mean {}?", guess));
    }
    return {};
}

// Help without CLI11's bookkeeping: each option's value type, its default and REQUIRED, but not
// "Needs: --size Excludes: --scene" (the descriptions say it in words) nor the range checker's
// "INT:INT in [1 - 256]" type (the description or the error gives the range).
class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_opts(const CLI::Option* opt) const override {
        if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
        if (opt->get_type_size() == 0) return {};
        std::string out;
        std::string type = opt->get_type_name();
        type = type.substr(0, type.find(':'));
        if (!type.empty()) out += " " + type;
        if (!opt->get_default_str().empty()) out += "=" + opt->get_default_str();
        if (opt->get_expected_max() == CLI::detail::expected_max_vector_size) out += " ...";
        if (opt->get_required()) out += " REQUIRED";
        return out;
    }
};

}  // namespace

int run_cli(int argc, char** argv) {
    // Ctrl-C during a write leaves no temporary file behind (harness/report/interrupt.h).
    install_interrupt_cleanup();
    CLI::App app{"aabench: image-quality evaluation and benchmark suite for antialiasing"};
    app.require_subcommand(1);
    app.formatter(std::make_shared<HelpFormatter>());

    const std::vector<std::unique_ptr<Command>> commands = all_commands();
    std::vector<CLI::App*> subs;
    for (const auto& c : commands) subs.push_back(c->add_to(app));
    // Set after the subcommands exist, so that only `aabench --help-all` has it: a subcommand
    // inherits the help flags its parent has when it is added.
    app.set_help_all_flag("--help-all", "help for every subcommand");
    if (!check_command_word(argc, argv, subs)) return 2;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // A misspelt option is the cause of whatever else went wrong ("--ouput" leaves --out
        // missing): name it first, with the option meant.
        if (const std::string unknown = unknown_option_message(argc, argv, subs); !unknown.empty()) {
            fmt::print(stderr, "aabench: {} (see aabench {} --help)\n", unknown, argv[1]);
            return 2;
        }
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        // One style for ranges, the one the subcommands' own checks use.
        static const std::regex range(R"(^(\S+): Value (\S+) not in range (\S+) to (\S+)$)");
        message = std::regex_replace(message, range, "$1: $2 is out of range $3..$4");
        fmt::print(stderr, "aabench: {} (see aabench --help)\n", message);
        return 2;
    }

    try {
        for (std::size_t k = 0; k < commands.size(); ++k) {
            if (subs[k]->parsed()) return commands[k]->run(Invocation{argc, argv});
        }
    } catch (const InputError& e) {
        fmt::print(stderr, "aabench: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "aabench: internal error: {}\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace aabench
