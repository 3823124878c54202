#include "cli/comparison_junit.h"

#include <cstdio>

#include "cli/xml_writer.h"
#include "io/output_file.h"
#include "util/build_version.h"
#include "util/formatted.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

double seconds(const ComparisonRecord& record) {
    return (record.gpuMilliseconds + record.cpuMilliseconds) / 1000.0;
}

void writeTestCase(XmlWriter& out, const ComparisonRecord& record) {
    out.start("testcase");
    out.attribute("classname", "hexray.compare." + record.name);
    out.attribute("name", record.loadError.empty() ? std::string(precisionName(record.precision)) : "load");
    out.attribute("file", record.scenePath);
    out.attribute("time", formatted("%.6f", seconds(record)));
    const std::string metrics = record.loadError.empty() ? metricsLine(record) : "";
    switch (record.outcome.outcome) {
        case Outcome::Failed:
            out.start(record.loadError.empty() ? "failure" : "error");
            out.attribute("message", record.outcome.reason);
            out.attribute("type", record.loadError.empty() ? "tolerance_exceeded" : "bad_input");
            out.text(record.loadError.empty() ? metrics : record.loadError);
            out.end();
            break;
        case Outcome::Expected:
        case Outcome::NotJudged:
            out.start("skipped");
            out.attribute("message", record.outcome.reason);
            out.end();
            break;
        default:
            break;
    }
    if (!metrics.empty()) {
        out.start("system-out");
        out.text(metrics);
        out.end();
    }
    out.end();
}

}  // namespace

std::string metricsLine(const ComparisonRecord& record) {
    const RenderComparison& c = record.comparison;
    const Tolerance& limit = record.expectation.tolerance;
    return "ambiguous " + formatted("%.4f%%", 100.0 * c.topology.ambiguousShare()) + " (max " +
           formatted("%g%%", limit.maxAmbiguousPercent) + "), excused " +
           formatted("%.4f%%", 100.0 * c.topology.excusedShare()) + ", topology mismatches " +
           std::to_string(c.topology.mismatches) + " (max " + std::to_string(limit.maxTopologyMismatches) +
           "), pixels > 1 level " + formatted("%.4f%%", 100.0 * c.encoded.shareOverOneLevel) + " (max " +
           formatted("%g%%", limit.maxSharePercent) + "), 8-bit RMSE " + formatted("%.4f", c.encoded.rmse) +
           " levels (max " + formatted("%g", limit.maxRmseLevels) + "), max abs " +
           formatted("%.0f", c.encoded.maxAbs) + " levels, mean FLIP " +
           (record.flipMean ? formatted("%.5f", *record.flipMean) : std::string("not measured")) +
           ", invalid colours " + std::to_string(c.invalidColours);
}

void writeJunit(const std::string& path, const std::vector<ComparisonRecord>& records, const std::string& device) {
    const OutcomeCounts counts = countOutcomes(records);
    std::uint64_t errors = 0;
    double totalSeconds = 0;
    for (const ComparisonRecord& record : records) {
        errors += record.loadError.empty() ? 0 : 1;
        totalSeconds += seconds(record);
    }
    const auto writeCounts = [&](XmlWriter& out) {
        out.attribute("name", "hexray compare");
        out.attribute("tests", std::to_string(records.size()));
        out.attribute("failures", std::to_string(counts.failed - errors));
        out.attribute("errors", std::to_string(errors));
        out.attribute("skipped", std::to_string(counts.expected + counts.notJudged));
        out.attribute("time", formatted("%.6f", totalSeconds));
    };
    XmlWriter out;
    out.start("testsuites");
    writeCounts(out);
    out.start("testsuite");
    writeCounts(out);
    out.start("properties");
    for (const auto& [name, value] :
         {std::pair<const char*, std::string>{"hexray", buildVersion()}, {"device", device}}) {
        out.start("property");
        out.attribute("name", name);
        out.attribute("value", value);
        out.end();
    }
    out.end();
    for (const ComparisonRecord& record : records) {
        writeTestCase(out, record);
    }
    out.end();
    out.end();
    const std::string text = out.finish();
    OutputFile file(path);
    if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
        file.fail("cannot write", "short write");
    }
    file.commit();
}

}  // namespace hexray::cli
