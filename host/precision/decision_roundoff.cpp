#include "precision/decision_roundoff.h"

namespace hexray::inline precision {

DecisionRoundoff decisionRoundoff(Precision precision) {
    if (precision == Precision::F64 || precision == Precision::F32Certified) {
        return {unitRoundoff(FloatWidth::F64), unitRoundoff(FloatWidth::F32)};
    }
    return {};
}

}  // namespace hexray::precision
