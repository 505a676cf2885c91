// aabench claims: every claim of the source papers measured, with its verdict
// (harness/measure/claims.h); --page writes docs/claims.md, --out the page and its JSON.
#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "harness/cli/command.h"
#include "harness/measure/claims.h"
#include "harness/report/claims_table.h"
#include "harness/report/image_io.h"

namespace aabench {
namespace {

class ClaimsCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "claims",
            "measure every claim of the source papers: the numbers and a verdict "
            "(holds, partly, does not hold) by the rule docs/claims.md states");
        cmd->add_option("--only", only_,
                        fmt::format("claim ids, comma-separated (default: all): {}",
                                    fmt::join(claim_ids(), ", ")));
        cmd->add_option("--size", options_.size, "side of the 2-D patterns and the torus (px)")
            ->capture_default_str()
            ->check(CLI::Range(32, 2048));
        cmd->add_option("--page", page_, "write the page (markdown: docs/claims.md) to this file");
        cmd->add_option("--out", out_, "write claims.md and claims.json into this directory");
        return cmd;
    }
    int run(const Invocation& inv) override {
        if (!only_.empty()) options_.only = split_path_list(only_, "--only");
        check_claim_ids(options_.only);  // before any work or file
        // The command as the page shows it: the program's name without its directory.
        std::string command = "aabench";
        for (int k = 1; k < inv.argc; ++k) command += std::string(" ") + inv.argv[k];
        if (!out_.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(out_, ec);
            if (ec) throw InputError(fmt::format("--out: {}: {}", out_, ec.message()));
        }
        const std::vector<ClaimResult> claims = measure_claims(options_);
        const std::string page = format_claims_page(claims, command);
        if (!page_.empty()) write_text_file(page_, page);
        if (!out_.empty()) {
            write_text_file((std::filesystem::path(out_) / "claims.md").string(), page);
            write_text_file((std::filesystem::path(out_) / "claims.json").string(),
                            format_claims_json(claims, command));
        }
        fmt::print("{}", format_claims_summary(claims));
        return 0;
    }

private:
    ClaimsOptions options_;
    std::string only_, page_, out_;
};

}  // namespace

std::unique_ptr<Command> make_claims_command() { return std::make_unique<ClaimsCommand>(); }

}  // namespace aabench
