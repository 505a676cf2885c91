// The canonical text of a filter (methods/filter_spec.h).
#include "methods/filter_spec.h"

#include <fmt/format.h>

#include "patterns/scene/params.h"

namespace aabench {

std::string FilterSpec::text() const {
    switch (kind) {
        case FilterKind::kBox:
            return "box";
        case FilterKind::kGaussian:
            return fmt::format("gaussian:sigma={},radius={}", format_real(sigma_px),
                               format_real(radius_px));
        case FilterKind::kCone:
            return fmt::format("cone:radius={}", format_real(radius_px));
    }
    return "box";
}

}  // namespace aabench
