// The aabench command line: the table of subcommands (one file each, cmd_*.cpp) and the
// dispatch. Parsing happens in this room and nowhere else; each subcommand calls library
// stages in the order pattern/scene -> method -> image -> reference, metrics, timing ->
// results -> report.
#include "harness/cli/cli.h"

#include <algorithm>

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
    commands.push_back(make_score_command());
    commands.push_back(make_check_command());
    return commands;
}

// CLI11 reports an unknown first word as "A subcommand is required"; name it instead.
bool check_command_word(int argc, char** argv, const std::vector<CLI::App*>& subs) {
    if (argc <= 1 || argv[1][0] == '-') return true;
    const std::string word = argv[1];
    std::string valid;
    for (const CLI::App* sub : subs) {
        if (sub->get_name() == word) return true;
        valid += (valid.empty() ? "" : ", ") + sub->get_name();
    }
    fmt::print(stderr, "aabench: unknown command '{}' (valid: {})\n", word, valid);
    return false;
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
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
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
