#pragma once
// What `hexray compare --report DIR` puts in DIR, and the names it owns there (so that the
// output plan can refuse a DIR that holds an input, and a later report can replace an earlier
// one's files without touching anything else):
//
//   DIR/index.html        the page
//   DIR/results.json      the document --json writes
//   DIR/images/NNN-<name>-<precision>-{gpu,cpu,diff,mask}.png
//                         per comparison, NNN its place in the results (from 001), <name> the
//                         scene's name with every byte but letters, digits, '.', '_' and '-'
//                         replaced, so that any scene name gives a safe, unique file name

#include <array>
#include <cstddef>
#include <string>

#include "precision/precision.h"

namespace hexray::cli {

inline constexpr const char* kReportPage = "index.html";
inline constexpr const char* kReportResults = "results.json";
inline constexpr const char* kReportImages = "images";

enum class ReportImage { Gpu, Reference, Diff, Mask };
inline constexpr std::array<ReportImage, 4> kReportImageKinds = {ReportImage::Gpu, ReportImage::Reference,
                                                                 ReportImage::Diff, ReportImage::Mask};

// "003-hard-grazing-f32": the part of a comparison's image names before the kind. `number`
// counts from 1.
std::string reportImageStem(std::size_t number, const std::string& sceneName, Precision precision);

// "003-hard-grazing-f32-gpu.png".
std::string reportImageName(const std::string& stem, ReportImage image);

// Whether a name in DIR/images is one a report writes (and a later report may replace or remove).
bool isReportImageName(const std::string& name);

// Whether a name in DIR is one a report writes.
bool isReportFileName(const std::string& name);

}  // namespace hexray::cli
