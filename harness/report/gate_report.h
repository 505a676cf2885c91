// The regression gate's outcome as text (aabench check): what changed, figure by figure, the
// timing summary, and the verdict line. Pure formatting.
#pragma once

#include <string>

#include "harness/measure/gate.h"

namespace aabench {

// The summary counts every gated figure compared: unchanged, moved within the tolerance (better
// or worse), appeared, and beyond the tolerance. The table lists only the figures beyond the
// tolerance and the missing rows; with `list_moved` also those that moved within it, except
// where old and new print the same (a change past the printed digits says nothing to a reader).
std::string format_gate(const GateResult& result, const GateTolerance& tolerance,
                        const std::string& baseline_path, bool list_moved = false);

}  // namespace aabench
