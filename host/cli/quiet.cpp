#include "cli/quiet.h"

namespace hexray::cli {
namespace {

bool& quietSetting() {
    static bool quiet = false;
    return quiet;
}

}  // namespace

void setQuiet(bool quiet) {
    quietSetting() = quiet;
}

bool quiet() {
    return quietSetting();
}

}  // namespace hexray::cli
