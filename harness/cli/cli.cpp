// The aabench command line: the table of subcommands (one file each, cmd_*.cpp) and the
// dispatch. Parsing happens in this room and nowhere else; each subcommand calls library
// stages in the order pattern/scene -> method -> image -> reference, metrics, timing ->
// results -> report.
#include "harness/cli/cli.h"

#include <algorithm>
#include <regex>

#include <fmt/format.h>

#include "harness/cli/command.h"

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

// The closest of `candidates` to `word`, if close enough to be a slip of the keyboard: at most
// a third of the word's letters apart (two for short words), else empty.
std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
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
    const std::string guess = closest(word, names);
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
        const std::string guess = closest(arg, valid);
        return fmt::format("{}: unknown option of {}{}", arg, sub->get_name(),
                           guess.empty() ? "" : fmt::format("; did you mean {}?", guess));
    }
    return {};
}

}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"aabench: image-quality evaluation and benchmark suite for antialiasing"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    const std::vector<std::unique_ptr<Command>> commands = all_commands();
    std::vector<CLI::App*> subs;
    for (const auto& c : commands) subs.push_back(c->add_to(app));
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
