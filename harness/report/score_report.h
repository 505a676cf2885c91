// How `aabench score` shows one scored image (harness/measure/score.h): a short text table for
// people and a JSON object for machines. Pure formatting; the figures are the metric registry's
// that need only one image (ShownIn kInScore) and the JSON fields are results.json's columns
// (report.h: column_value), so names and encodings (NaN as null, infinities as "inf") are the
// same.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

// The results.json columns `score` reports, in order.
std::vector<std::string> score_fields();

// {"image": PATH, <score_fields()...>}
std::string score_json(const ResultRow& row, const std::string& image_path);

// One line per figure: name, value, what it is against.
std::string format_score(const ResultRow& row, const std::string& image_path);

}  // namespace aabench
