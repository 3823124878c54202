#include "fuzz/differential_check.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "precision/decision_roundoff.h"
#include "cpu/cpu_renderer.h"
#include "fuzz/near_tie_reasons.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

namespace hexray::test {
namespace {

std::string format(const char* pattern, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

std::string topologyDetail(const TopologyComparison& t) {
    return format("%llu topology mismatches (node %llu, checker cell %llu, lights %llu) of %llu pixels",
                  static_cast<unsigned long long>(t.mismatches), static_cast<unsigned long long>(t.nodeMismatches),
                  static_cast<unsigned long long>(t.checkerMismatches),
                  static_cast<unsigned long long>(t.lightMismatches), static_cast<unsigned long long>(t.pixels));
}

// The CPU reference at one sample count, for each arithmetic its margins are read against.
class References {
public:
    explicit References(const Scene& scene) : scene_(scene) {}

    const CpuRender& at(Precision precision) {
        const DecisionRoundoff roundoff = decisionRoundoff(precision);
        auto found = renders_.find(roundoff.general);
        if (found == renders_.end()) {
            found =
                renders_.emplace(roundoff.general, renderOnCpu(scene_, 1, Acceleration::Auto, false, roundoff)).first;
        }
        return found->second;
    }

private:
    const Scene& scene_;
    std::map<double, CpuRender> renders_;
};

// A precision asked for float32 on a scene it cannot hold must come back as f64, with a warning.
std::optional<Finding> checkPlanPrecision(const Scene& scene, Precision requested, const RenderPlan& plan,
                                          bool deviceHasFloat64, const std::string& where) {
    const bool overruled = requested == Precision::F32 && deviceHasFloat64 && float32RangeProblem(scene);
    const Precision expected = overruled ? Precision::F64 : requested;
    const bool warned = !plan.warnings.empty() && plan.warnings[0].find("float32 cannot hold") != std::string::npos;
    if (plan.precision != expected || warned != overruled) {
        return Finding{"precision warning", where,
                       format("rendered in %s with %zu warnings; expected %s%s", precisionName(plan.precision).data(),
                              plan.warnings.size(), precisionName(expected).data(), overruled ? " and a warning" : "")};
    }
    return std::nullopt;
}

// What compare's verdict says of one render, as findings.
void judgeComparison(const RenderComparison& c, const Verdict& verdict, bool robust, bool judgeAmbiguity,
                     const std::string& where, std::vector<Finding>& findings) {
    if (!verdict.valuesOk) {
        findings.push_back({"invalid colour", where,
                            format("%llu pixels with a NaN, infinite or negative colour",
                                   static_cast<unsigned long long>(c.invalidColours))});
    }
    if (robust && !verdict.topologyOk) {
        findings.push_back({"topology", where, topologyDetail(c.topology)});
    }
    if (robust && (!verdict.shareOk || !verdict.rmseOk)) {
        findings.push_back(
            {"colour", where,
             format("8-bit max %.0f levels, RMSE %.3f, %llu pixels > 1 level of %llu compared", c.encoded.maxAbs,
                    c.encoded.rmse, static_cast<unsigned long long>(c.encoded.pixelsOverOneLevel),
                    static_cast<unsigned long long>(c.encoded.pixels))});
    }
    if (judgeAmbiguity && !verdict.ambiguousOk) {
        findings.push_back(
            {"ambiguous", where, format("%.2f %% of the pixels near-tied", 100.0 * c.topology.ambiguousShare())});
    }
}

// The precision whose comparison the ambiguity limit holds (see checkRenders).
Precision mostPrecise(Precision automatic, const std::vector<Precision>& rendered) {
    return std::ranges::find(rendered, Precision::F64) != rendered.end() ? Precision::F64 : automatic;
}

}  // namespace

std::string describe(const Finding& finding) {
    return finding.kind + " (" + finding.where + "): " + finding.detail;
}

std::vector<Finding> checkRenders(GpuRenderer& renderer, const Scene& scene, const DifferentialOptions& options,
                                  const GpuRenderFunction& render) {
    const bool float64 = renderer.abilities().float64;
    std::vector<Precision> precisions = options.precisions;
    std::erase_if(precisions, [&](Precision p) { return p == Precision::F64 && !float64; });
    const PlanRequest dataDriven{.acceleration = options.dataDrivenAcceleration, .generatedKernel = false};
    const bool judgeAmbiguity = nearTieReasons(scene).empty();
    std::vector<Finding> findings;
    for (const std::uint32_t samples : options.samplesPerPixel) {
        Scene sized = scene;
        sized.image.width = options.width;
        sized.image.height = options.height;
        sized.image.samplesPerPixel = samples;
        const Precision judgedForAmbiguity = mostPrecise(renderer.resolve(sized, Precision::Auto), precisions);
        References references(sized);
        std::vector<PlanRequest> requests = {dataDriven};
        if (options.generatedKernels && options.generatedKernelSamples.value_or(samples) == samples) {
            requests.push_back({});  // the plan's own choice
        }
        for (const Precision requested : precisions) {
            std::string previousKernel;
            for (PlanRequest request : requests) {
                request.precision = requested;
                const RenderPlan plan = renderer.plan(sized, request);
                if (plan.kernel.name == previousKernel) {
                    continue;  // the default plan's kernel is the data-driven one: rendered already
                }
                previousKernel = plan.kernel.name;
                const std::string where = format("%s, %u spp, %s kernel", precisionName(requested).data(), samples,
                                                 plan.kernel.code ? "generated" : "data-driven");
                const std::size_t before = findings.size();
                if (const auto finding = checkPlanPrecision(sized, requested, plan, float64, where)) {
                    findings.push_back(*finding);
                }
                const GpuRenderResult gpu =
                    render ? render(sized, plan) : renderer.render(sized, plan, GpuOutput::LinearAndClasses);
                const CpuRender& cpu = references.at(plan.precision);
                const RenderComparison comparison =
                    compareRenders(cpu.image, cpu.classes, cpu.ambiguity, gpu.image, gpu.classes, sized.image.encoding);
                judgeComparison(comparison, judge(comparison, options.tolerance),
                                plan.formulation == Formulation::Robust,
                                judgeAmbiguity && samples == options.samplesPerPixel.front() &&
                                    requested == judgedForAmbiguity && !request.generatedKernel,
                                where, findings);
                for (std::size_t i = before; i < findings.size(); ++i) {
                    findings[i].precision = requested;
                    findings[i].samplesPerPixel = samples;
                    findings[i].generatedKernel = plan.kernel.code != nullptr;
                }
            }
        }
    }
    return findings;
}

DifferentialOptions optionsFor(const Finding& finding, DifferentialOptions options) {
    if (finding.precision) {
        options.precisions = {*finding.precision};
        options.samplesPerPixel = {finding.samplesPerPixel};
        options.generatedKernels = finding.generatedKernel;
        options.generatedKernelSamples.reset();
    }
    return options;
}

std::optional<Finding> checkLoad(const Scene& scene, bool outOfRange) {
    const std::string text = sceneToJson(scene);
    try {
        const Scene loaded = parseScene(text, "generated.json");
        if (outOfRange) {
            return Finding{"load", "loader", "a value beyond the supported range was accepted"};
        }
        if (sceneToJson(loaded) != text) {
            return Finding{"load", "loader", "the scene file does not load back as the same scene"};
        }
    } catch (const SceneError& error) {
        const std::string message = error.what();
        if (!outOfRange || message.find("the supported range") == std::string::npos) {
            return Finding{"load", "loader", "rejected: " + message};
        }
    }
    return std::nullopt;
}

}  // namespace hexray::test
