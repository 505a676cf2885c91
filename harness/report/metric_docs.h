// The metric registry (harness/measure/metric_registry.h) as a Markdown table: the block
// docs/metrics.md holds between kRegistryBeginMarker and kRegistryEndMarker, checked against
// the registry by tests/metric_registry_test.cpp (which prints the block when they differ).
#pragma once

#include <string>

namespace aabench {

inline constexpr const char* kRegistryBeginMarker = "<!-- metric registry: begin -->";
inline constexpr const char* kRegistryEndMarker = "<!-- metric registry: end -->";

// One line per metric, in registry order: key, table header, unit, which way is better, the
// gate's rule, where it applies, definition.
std::string metric_registry_markdown();

}  // namespace aabench
