// aabench hardcases: degenerate and enormous geometry against every method and reference,
// invariants checked; exit 1 if any fails.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "harness/cli/command.h"
#include "harness/measure/hardcases.h"
#include "harness/report/context.h"
#include "harness/report/image_io.h"

namespace aabench {
namespace {

class HardCasesCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "hardcases", "degenerate and enormous geometry against every method and reference: "
                         "invariants checked, exit 1 if any fails");
        cmd->add_option("--methods", methods_,
                        "method specs, comma-separated (default: every registered method at its "
                        "defaults, plus the sub-scanline settings the on-line cases are for and "
                        "n and k at their maxima)");
        cmd->add_option("--out", out_,
                        "also write hardcases.txt and hardcases.json into this directory");
        return cmd;
    }
    int run(const Invocation& inv) override {
        std::vector<std::string> specs =
            methods_.empty() ? default_hard_case_methods() : split_spec_list(methods_);
        ProgressBar bar(stderr_is_terminal());
        const std::vector<HardCaseRow> rows = run_hard_cases(specs, std::ref(bar));
        const std::string table = format_hard_case_table(rows);
        if (!out_.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(out_, ec);
            if (ec) throw InputError(fmt::format("--out: {}: {}", out_, ec.message()));
            write_text_file((std::filesystem::path(out_) / "hardcases.txt").string(),
                            "command: " + capture_context(inv.argc, inv.argv).command + "\n" +
                                table);
            write_text_file((std::filesystem::path(out_) / "hardcases.json").string(),
                            format_hard_case_json(rows));
        }
        fmt::print("{}", table);
        const bool failed = std::any_of(rows.begin(), rows.end(), [](const HardCaseRow& r) {
            return r.outcome == Outcome::kFail;
        });
        return failed ? 1 : 0;
    }

private:
    std::string methods_, out_;
};

}  // namespace

std::unique_ptr<Command> make_hardcases_command() { return std::make_unique<HardCasesCommand>(); }

}  // namespace aabench
