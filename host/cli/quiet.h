#pragma once
// --quiet: no progress lines and no summary lines ("wrote …", compare's and diff's reports).
// Errors, warnings and notes are still printed, and the data a command was asked for (an image
// or document on standard output, bench's and pixel's tables, devices, cache) still comes out.

namespace hexray::cli {

void setQuiet(bool quiet);
bool quiet();

}  // namespace hexray::cli
