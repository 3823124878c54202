#include "precision/decision_roundoff.h"

namespace hexray {

DecisionRoundoff decisionRoundoff(Precision precision) {
    if (precision == Precision::F64) {
        return {0x1p-53, 0x1p-24};
    }
    return {};
}

}  // namespace hexray
