#include "precision/decision_roundoff.h"

namespace hexray::inline precision {

DecisionRoundoff decisionRoundoff(Precision precision) {
    if (precision == Precision::F64) {
        return {FLOAT64_UNIT_ROUNDOFF, FLOAT32_UNIT_ROUNDOFF};
    }
    return {};
}

}  // namespace hexray::precision
