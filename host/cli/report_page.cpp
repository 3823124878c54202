#include "cli/report_page.h"

#include <algorithm>
#include <cstdio>

#include "cli/comparison_junit.h"
#include "cli/report_layout.h"
#include "cli/xml_writer.h"
#include "util/formatted.h"

namespace hexray::cli {
namespace {

// Small renders are scaled up (by a whole factor, pixels kept square) to about this width.
constexpr std::uint32_t kShownWidth = 320;

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 1em 2em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
.failed { background: #fdd; } .expected { background: #ffd; } .passed { background: #dfd; }
.images { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; }
img { max-width: 100%; height: auto; display: block; }
img.pixelated { image-rendering: pixelated; }
img.flip { cursor: pointer; }
)";

// Hover over or click the GPU image to see the reference in its place; on load, count the images.
constexpr const char* kScript = R"(
for (const img of document.querySelectorAll('img.flip')) {
  const gpu = img.getAttribute('src'), reference = img.dataset.reference;
  const caption = img.parentElement.querySelector('figcaption');
  const gpuCaption = caption.textContent;
  let pinned = false, hovered = false;
  const show = () => {
    const flipped = pinned !== hovered;
    img.src = flipped ? reference : gpu;
    caption.textContent = flipped ? 'CPU reference (shown in place of the GPU render)' : gpuCaption;
  };
  img.addEventListener('mouseenter', () => { hovered = true; show(); });
  img.addEventListener('mouseleave', () => { hovered = false; show(); });
  img.addEventListener('click', () => { pinned = !pinned; show(); });
}
window.addEventListener('load', () => {
  let loaded = 0, failed = 0;
  for (const img of document.images) {
    if (img.complete && img.naturalWidth > 0) { loaded++; } else { failed++; }
  }
  const check = document.getElementById('image-check');
  check.dataset.loaded = loaded;
  check.dataset.failed = failed;
  check.textContent = failed ? failed + ' of ' + (loaded + failed) + ' images did not load'
                             : 'all ' + loaded + ' images loaded';
});
)";

std::string percent(double share) {
    return formatted("%.3f%%", 100.0 * share);
}

std::string anchor(std::size_t index) {
    return "comparison-" + std::to_string(index + 1);
}

std::string outcomeText(const ComparisonRecord& record) {
    const std::string name(outcomeName(record.outcome.outcome));
    return name == "not_judged" ? "not judged" : name;
}

std::string toleranceText(const Tolerance& t) {
    return "mismatches ≤ " + std::to_string(t.maxTopologyMismatches) + ", ambiguous ≤ " +
           formatted("%g%%", t.maxAmbiguousPercent) + ", > 1 level ≤ " + formatted("%g%%", t.maxSharePercent) +
           ", RMSE ≤ " + formatted("%g", t.maxRmseLevels);
}

void writeHead(XmlWriter& out, const nlohmann::json& document) {
    out.start("head");
    out.start("meta");
    out.attribute("charset", "utf-8");
    out.end();
    out.element("title", "hexray compare: " + document["summary"]["gate"].get<std::string>());
    out.start("style");
    out.raw(kStyle);
    out.fullEnd();
    out.fullEnd();
}

void writeIntroduction(XmlWriter& out, const nlohmann::json& document) {
    const nlohmann::json& summary = document["summary"];
    out.element("h1", "hexray compare");
    out.element("p", (summary["gate"] == "pass" ? "PASS: " : "FAIL: ") + summary["passed"].dump() + " passed, " +
                         summary["expected"].dump() + " expected, " + summary["failed"].dump() + " failed, " +
                         summary["not_judged"].dump() + " not judged; exit " + document["exit"]["code"].dump() + " (" +
                         document["exit"]["name"].get<std::string>() + ")");
    const std::string device = document["device"].is_null() ? "none" : document["device"]["name"].get<std::string>();
    out.element("p", "hexray " + document["hexray"]["version"].get<std::string>() + ", device " + device +
                         ". Hover over or click a GPU render to see the CPU reference in its place.");
    out.start("output");
    out.attribute("id", "image-check");
    out.attribute("data-loaded", "0");
    out.attribute("data-failed", "0");
    out.text("images not checked (the page's script did not run)");
    out.fullEnd();
}

void writeSummaryRow(XmlWriter& out, const ComparisonRecord& record, std::size_t index) {
    const bool loaded = record.loadError.empty();
    const std::string outcome(outcomeName(record.outcome.outcome));
    out.start("tr");
    out.attribute("class", outcome);
    out.attribute("data-scene", record.name);
    out.attribute("data-precision", loaded ? std::string(precisionName(record.precision)) : "");
    out.attribute("data-outcome", outcome);
    out.attribute("data-rmse", loaded ? formatted("%.17g", record.comparison.encoded.rmse) : "");
    out.attribute("data-ambiguous-share",
                  loaded ? formatted("%.17g", record.comparison.topology.ambiguousShare()) : "");
    out.start("td");
    out.start("a");
    out.attribute("href", "#" + anchor(index));
    out.text(record.name);
    out.fullEnd();
    out.fullEnd();
    if (!loaded) {
        out.element("td", "–");
        out.element("td", outcomeText(record));
        out.start("td");
        out.attribute("colspan", "7");
        out.text(record.outcome.reason);
        out.fullEnd();
        out.fullEnd();
        return;
    }
    const RenderComparison& c = record.comparison;
    out.element("td", std::string(precisionName(record.precision)) + (record.chosenByAuto ? " (auto)" : ""));
    out.element("td", outcomeText(record));
    out.element("td", std::to_string(c.topology.mismatches));
    out.element("td", percent(c.topology.ambiguousShare()));
    out.element("td", percent(c.topology.excusedShare()));
    out.element("td", formatted("%.3f", c.encoded.rmse));
    out.element("td", percent(c.encoded.shareOverOneLevel));
    out.element("td", formatted("%.0f", c.encoded.maxAbs));
    out.element("td", toleranceText(record.expectation.tolerance));
    out.fullEnd();
}

void writeSummary(XmlWriter& out, const std::vector<ComparisonRecord>& records) {
    out.start("table");
    out.attribute("id", "summary");
    out.start("thead");
    out.start("tr");
    for (const char* heading : {"scene", "precision", "outcome", "topology mismatches", "ambiguous", "excused",
                                "RMSE (levels)", "> 1 level", "max abs (levels)", "tolerance"}) {
        out.element("th", heading);
    }
    out.fullEnd();
    out.fullEnd();
    out.start("tbody");
    for (std::size_t i = 0; i < records.size(); ++i) {
        writeSummaryRow(out, records[i], i);
    }
    out.fullEnd();
    out.fullEnd();
}

void writeImage(XmlWriter& out, const ComparisonRecord& record, ReportImage image, const std::string& caption) {
    const std::uint32_t scale = std::max<std::uint32_t>(1, kShownWidth / std::max<std::uint32_t>(1, record.width));
    out.start("figure");
    out.start("img");
    out.attribute("src", std::string(kReportImages) + "/" + reportImageName(record.reportImages, image));
    if (image == ReportImage::Gpu) {
        out.attribute("data-reference",
                      std::string(kReportImages) + "/" + reportImageName(record.reportImages, ReportImage::Reference));
    }
    out.attribute("class", std::string(scale > 1 ? "pixelated" : "") + (image == ReportImage::Gpu ? " flip" : ""));
    out.attribute("width", std::to_string(record.width * scale));
    out.attribute("height", std::to_string(record.height * scale));
    out.attribute("alt", caption + ": " + record.name);
    out.end();
    out.element("figcaption", caption);
    out.fullEnd();
}

void writeSection(XmlWriter& out, const ComparisonRecord& record, std::size_t index) {
    const bool loaded = record.loadError.empty();
    out.start("section");
    out.attribute("id", anchor(index));
    out.element("h2", record.name + (loaded ? " · " + std::string(precisionName(record.precision)) : ""));
    out.start("p");
    out.attribute("class", std::string(outcomeName(record.outcome.outcome)));
    out.text(outcomeText(record) + ": " + record.outcome.reason);
    out.fullEnd();
    if (loaded) {
        out.element("p", metricsLine(record));
    }
    if (!record.reportImages.empty()) {
        out.start("div");
        out.attribute("class", "images");
        writeImage(out, record, ReportImage::Gpu, "GPU render (" + std::string(precisionName(record.precision)) + ")");
        writeImage(out, record, ReportImage::Reference, "CPU reference");
        writeImage(out, record, ReportImage::Diff, "difference heat map (8-bit levels, log scale)");
        writeImage(out, record, ReportImage::Mask,
                   "mask: magenta invalid colour, red topology, blue excused, yellow colour > 1 level, navy "
                   "near-tied but agreeing");
        out.fullEnd();
    }
    out.fullEnd();
}

}  // namespace

std::string reportPage(const std::vector<ComparisonRecord>& records, const nlohmann::json& document) {
    XmlWriter out(XmlWriter::Kind::Html);
    out.raw("<!DOCTYPE html>\n");
    out.start("html");
    out.attribute("lang", "en");
    writeHead(out, document);
    out.start("body");
    writeIntroduction(out, document);
    writeSummary(out, records);
    for (std::size_t i = 0; i < records.size(); ++i) {
        writeSection(out, records[i], i);
    }
    out.start("script");
    out.raw(kScript);
    out.fullEnd();
    out.fullEnd();
    out.fullEnd();
    return out.finish();
}

}  // namespace hexray::cli
