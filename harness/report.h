// The report stage: the only place that turns results into files. Formatting functions are
// pure (they return text); write_compare_results() writes them atomically.
#pragma once

#include <string>
#include <vector>

#include "harness/compare.h"
#include "harness/context.h"

namespace aabench {

// A fixed-width text table per pattern, methods in run order.
std::string format_compare_tables(const std::vector<ResultRow>& rows);
// One row per method x pattern; the header names every column with its unit.
std::string compare_rows_csv(const std::vector<ResultRow>& rows);
// {"context": {...}, "definitions": {...}, "rows": [...]}
std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context);

// Writes table.txt, results.csv and results.json into `dir` (created if missing).
void write_compare_results(const std::string& dir, const std::vector<ResultRow>& rows,
                           const RunContext& context);

}  // namespace aabench
