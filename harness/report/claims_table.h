// The claims table (harness/measure/claims.h) as text: the page docs/claims.md (`aabench claims
// --page`), its JSON, and the section the HTML report shows. Pure text; the caller writes it.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/claims.h"

namespace aabench {

// The page: title, how it was made (`command`), the verdict rule (kVerdictRule), the summary
// table (claim, source, verdict, checks holding, command) and one section per claim with what
// was measured, the numbers and the checks that do not hold.
std::string format_claims_page(const std::vector<ClaimResult>& claims, const std::string& command);

// Every claim with its checks, verdict and tables.
std::string format_claims_json(const std::vector<ClaimResult>& claims, const std::string& command);

// One line per claim: verdict, checks holding, id, finding (what `aabench claims` prints).
std::string format_claims_summary(const std::vector<ClaimResult>& claims);

// The summary table as an HTML section (<h2>, rule, table), for the report's page.
std::string claims_html_section(const std::vector<ClaimResult>& claims);

}  // namespace aabench
