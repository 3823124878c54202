// `hexray pixel SCENE X Y`: why a pixel has its colour, as each backend computed it.
// The GPU column comes from the shader's trace mode (shaders/inspect*.glsl), the CPU column
// from the reference's own functions (cpu/cpu_explain.h); both are in world units.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>

#include "cli/command_support.h"
#include "cli/json_document.h"
#include "cli/pixel_record.h"
#include "cpu/cpu_explain.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"
#include "io/output_plan.h"
#include "scene/scene_loader.h"
#include "util/formatted.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

std::string vec(const glm::dvec3& v) {
    return formatted("(%.7g, %.7g, %.7g)", v.x, v.y, v.z);
}

std::string distance(double t) {
    return std::isinf(t) ? std::string("miss") : formatted("t = %.9g", t);
}

std::string levels(const glm::dvec3& linear, Encoding encoding) {
    return formatted("(%u, %u, %u)", unsigned(encodeChannel(float(linear.x), encoding)),
                     unsigned(encodeChannel(float(linear.y), encoding)),
                     unsigned(encodeChannel(float(linear.z), encoding)));
}

// Whether two values computed in different precisions disagree beyond float32 rounding noise.
bool differs(double a, double b, double scale) {
    if (std::isinf(a) || std::isinf(b)) {
        return a != b;
    }
    return std::abs(a - b) > 1e-4 * std::max({std::abs(a), std::abs(b), scale});
}

bool differs(const glm::dvec3& a, const glm::dvec3& b, double scale) {
    return differs(a.x, b.x, scale) || differs(a.y, b.y, scale) || differs(a.z, b.z, scale);
}

bool levelsDiffer(const glm::dvec3& a, const glm::dvec3& b, Encoding encoding) {
    for (int c = 0; c < 3; ++c) {
        if (std::abs(int(encodeChannel(float(a[c]), encoding)) - int(encodeChannel(float(b[c]), encoding))) > 1) {
            return true;
        }
    }
    return false;
}

const char* lightStatus(std::uint32_t status) {
    switch (status) {
        case gpu::TRACE_LIGHT_LIT:
            return "lit";
        case gpu::TRACE_LIGHT_FACING_AWAY:
            return "facing away";
        case gpu::TRACE_LIGHT_SHADOWED:
            return "shadowed";
        case gpu::TRACE_LIGHT_AT_POINT:
            return "at the point";
        default:
            return "not evaluated";
    }
}

std::uint32_t statusOf(LightReach reach) {
    switch (reach) {
        case LightReach::Lit:
            return gpu::TRACE_LIGHT_LIT;
        case LightReach::FacingAway:
            return gpu::TRACE_LIGHT_FACING_AWAY;
        case LightReach::Shadowed:
            return gpu::TRACE_LIGHT_SHADOWED;
        case LightReach::AtPoint:
            return gpu::TRACE_LIGHT_AT_POINT;
    }
    return gpu::TRACE_LIGHT_NOT_EVALUATED;
}

// Prints label | gpu | cpu rows, one column when only one backend ran, and "<- differs" where
// both ran and disagree.
class Table {
public:
    Table(bool gpu, bool cpu) : gpu_(gpu), cpu_(cpu) {}
    void header() const {
        std::printf("%-22s", "");
        if (gpu_) {
            std::printf(cpu_ ? " %-44s" : " %s", "gpu (shader trace)");
        }
        if (cpu_) {
            std::printf(" %s", "cpu (reference)");
        }
        std::printf("\n");
    }
    // A line that names the rows below it (indented); their labels in differingRows() start with it.
    void heading(const std::string& label) {
        std::printf("%s\n", label.c_str());
        group_ = label;
    }
    void row(const std::string& label, const std::string& gpuText, const std::string& cpuText, bool differ = false) {
        std::string text = formatted("%-22s", label.c_str());
        if (gpu_) {
            text += formatted(" %-44s", gpuText.c_str());
        }
        if (cpu_) {
            text += formatted(" %-44s", cpuText.c_str());
        }
        const bool flagged = gpu_ && cpu_ && differ;
        const bool indented = label.rfind("  ", 0) == 0;
        if (!indented) {
            group_ = label;
        }
        if (flagged) {
            text += " <- differs";
            differingRows_.push_back(indented ? group_ + " " + label.substr(2) : label);
        }
        text.erase(text.find_last_not_of(' ') + 1);
        std::printf("%s\n", text.c_str());
    }
    int differences() const { return int(differingRows_.size()); }
    const std::vector<std::string>& differingRows() const { return differingRows_; }

private:
    bool gpu_;
    bool cpu_;
    std::string group_;  // the last heading or unindented row
    std::vector<std::string> differingRows_;
};

void requireInRange(const char* what, std::int64_t value, std::uint32_t limit, const char* of) {
    if (value < 0 || value >= std::int64_t(limit)) {
        throw SceneError(formatted("%s = %lld is outside the image: %s is %u, so %s must be in 0..%u", what,
                                   static_cast<long long>(value), of, limit, what, limit - 1));
    }
}

// The shader's own account of the sample, after a line saying how to read it.
GpuPixelTrace traceOnGpu(const PixelOptions& options, const Scene& scene, ValidationLog& log, std::uint32_t x,
                         std::uint32_t y, std::uint32_t sample, PixelRecord& record) {
    const auto startup = std::chrono::steady_clock::now();
    const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
    record.startupMilliseconds = millisecondsSince(startup);
    record.device = context.selected();
    GpuRenderer renderer(context);
    const auto traceStart = std::chrono::steady_clock::now();
    const GpuPixelTrace trace = renderer.tracePixel(scene, options.precision, x, y, sample);
    record.gpuTraceMilliseconds = millisecondsSince(traceStart);
    std::printf("gpu: %s%s on %s; %s\n", std::string(precisionName(trace.precision)).c_str(),
                trace.tracedAgainInF64 ? " (a decision was in doubt: this is the f64 pass's trace)" : "",
                context.selected().name.c_str(),
                trace.cameraRelative
                    ? formatted("the shader works camera-relative, lengths divided by %g; printed here in "
                                "world units (eye added back, lengths multiplied by %g)",
                                trace.scale, trace.scale)
                          .c_str()
                    : "the shader works in world coordinates");
    return trace;
}

// One sample of a pixel as the shader traced it and as the CPU reference explains it, printed
// section by section: the ray, the candidates, the hit and its surface, each light, the colour.
class PixelReport {
public:
    PixelReport(const Scene& scene, bool useGpu, bool useCpu, const GpuPixelTrace& shader,
                const CpuPixelExplanation& reference)
        : scene_(scene),
          useGpu_(useGpu),
          useCpu_(useCpu),
          shader_(shader),
          reference_(reference),
          table_(useGpu, useCpu),
          sceneScale_(glm::length(reference.ray.origin) + glm::length(shader.rayOrigin)),
          shaderHit_(shader.node != PixelClass::kBackground),
          referenceHit_(reference.nearest.has_value()),
          referenceNode_(referenceHit_ ? std::uint32_t(reference.nearest->nodeIndex) : PixelClass::kBackground) {}

    void print() {
        table_.header();
        printRay();
        printCandidates();
        printHit();
        if (shaderHit_ || referenceHit_) {
            printSurface();
            for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
                printLight(i);
            }
        }
        printColour();
    }

    // Where the backends disagree, for --json.
    PixelComparison comparison() const { return {table_.differingRows(), !sameClass()}; }

    // Whether the backends agree: no row differs and the pixel's class is the same.
    void printVerdict() const {
        const bool sameClass = this->sameClass();
        if (table_.differences() == 0 && sameClass) {
            std::printf("gpu and cpu agree\n");
        } else {
            std::printf("DIFFERENCE: %d row%s differ (marked)%s\n", table_.differences(),
                        table_.differences() == 1 ? "" : "s", sameClass ? "" : "; the pixel's class differs");
        }
    }

private:
    bool sameClass() const { return shader_.node == referenceNode_ && shader_.flags == reference_.pixelClass.flags; }

    void printRay() {
        table_.row("ray origin", vec(shader_.rayOrigin), vec(reference_.ray.origin),
                   differs(shader_.rayOrigin, reference_.ray.origin, sceneScale_));
        table_.row("ray direction", vec(shader_.rayDirection), vec(reference_.ray.direction),
                   differs(shader_.rayDirection, reference_.ray.direction, 1.0));
    }

    // Nodes that every backend shown misses are only counted: a scene may have thousands.
    void printCandidates() {
        table_.heading("candidates");
        std::size_t missedByAll = 0;
        for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
            const double miss = std::numeric_limits<double>::infinity();
            const double shaderT = useGpu_ ? shader_.candidates[i] : miss;
            const double referenceT = useCpu_ && reference_.candidates[i] ? reference_.candidates[i]->t : miss;
            if (std::isinf(shaderT) && std::isinf(referenceT)) {
                ++missedByAll;
                continue;
            }
            table_.row(formatted("  node %zu %s", i, geometryName(scene_.nodes[i].geometry)), distance(shaderT),
                       distance(referenceT), differs(shaderT, referenceT, 0.0));
        }
        if (missedByAll > 0) {
            std::printf("  %zu other node%s: miss\n", missedByAll, missedByAll == 1 ? "" : "s");
        }
    }

    void printHit() {
        const auto hitText = [](bool hit, std::uint32_t node, double t) {
            return hit ? formatted("node %u, %s", node, distance(t).c_str()) : std::string("background");
        };
        const double referenceT = referenceHit_ ? reference_.nearest->hit.t : 0.0;
        table_.row(
            "hit", hitText(shaderHit_, shader_.node, shader_.t), hitText(referenceHit_, referenceNode_, referenceT),
            shader_.node != referenceNode_ || (shaderHit_ && referenceHit_ && differs(shader_.t, referenceT, 0.0)));
    }

    void printSurface() {
        const glm::dvec3 referencePosition = referenceHit_ ? reference_.nearest->hit.point : glm::dvec3(0);
        const glm::dvec3 referenceNormal = referenceHit_ ? reference_.nearest->hit.facingNormal : glm::dvec3(0);
        table_.row("position", shaderHit_ ? vec(shader_.position) : "", referenceHit_ ? vec(referencePosition) : "",
                   differs(shader_.position, referencePosition, sceneScale_));
        table_.row("normal (facing ray)", shaderHit_ ? vec(shader_.normal) : "",
                   referenceHit_ ? vec(referenceNormal) : "", differs(shader_.normal, referenceNormal, 1.0));
        const auto shaderText = [&](bool hit, std::uint32_t node) {
            return hit ? std::string(shaderTypeName(scene_.shaders.at(scene_.nodes[node].shaderIndex))) : std::string();
        };
        table_.row("shader", shaderText(shaderHit_, shader_.node), shaderText(referenceHit_, referenceNode_));
        const bool shaderOdd = (shader_.flags & PixelClass::kOddCheckerBit) != 0;
        const bool referenceOdd = (reference_.pixelClass.flags & PixelClass::kOddCheckerBit) != 0;
        std::string shaderAlbedo = shaderHit_ ? vec(glm::dvec3(shader_.albedo)) : "";
        std::string referenceAlbedo = referenceHit_ ? vec(reference_.albedo) : "";
        if (reference_.checkerCell) {
            referenceAlbedo += formatted(" cell (%.0f, %.0f) %s", reference_.checkerCell->x, reference_.checkerCell->y,
                                         referenceOdd ? "odd" : "even");
        }
        if (shaderHit_ &&
            std::holds_alternative<CheckerShader>(scene_.shaders.at(scene_.nodes[shader_.node].shaderIndex))) {
            shaderAlbedo += shaderOdd ? " odd cell" : " even cell";
        }
        table_.row("albedo", shaderAlbedo, referenceAlbedo,
                   shaderOdd != referenceOdd || differs(glm::dvec3(shader_.albedo), reference_.albedo, 0.0));
    }

    void printLight(std::size_t i) {
        const GpuTraceLight shaderLight = useGpu_ ? shader_.lights[i] : GpuTraceLight{};
        const bool explained = i < reference_.lights.size();
        const LightTerm referenceLight =
            explained ? reference_.lights[i] : LightTerm{{LightReach::AtPoint, 0, 0}, Color(0)};
        const std::uint32_t referenceStatus = explained ? statusOf(referenceLight.decision.reach) : 0;
        const bool shaderEvaluated = shaderLight.status != gpu::TRACE_LIGHT_NOT_EVALUATED;
        const bool referenceEvaluated = referenceStatus != gpu::TRACE_LIGHT_NOT_EVALUATED;
        table_.row(formatted("light %zu", i), lightStatus(shaderLight.status), lightStatus(referenceStatus),
                   shaderLight.status != referenceStatus);
        if (!shaderEvaluated && !referenceEvaluated) {
            return;
        }
        const LightDecision& decision = referenceLight.decision;
        table_.row("  cos theta", shaderEvaluated ? formatted("%.7g", shaderLight.cosTheta) : "",
                   referenceEvaluated ? formatted("%.7g", decision.cosTheta) : "",
                   differs(shaderLight.cosTheta, decision.cosTheta, 1.0));
        table_.row("  r^2", shaderEvaluated ? formatted("%.9g", shaderLight.distanceSquared) : "",
                   referenceEvaluated ? formatted("%.9g", decision.distanceSquared) : "",
                   differs(shaderLight.distanceSquared, decision.distanceSquared, 0.0));
        table_.row("  contribution", shaderEvaluated ? vec(glm::dvec3(shaderLight.contribution)) : "",
                   referenceEvaluated ? vec(referenceLight.contribution) : "",
                   differs(glm::dvec3(shaderLight.contribution), referenceLight.contribution, 1e-3));
    }

    void printColour() {
        const Encoding encoding = scene_.image.encoding;
        const glm::dvec3 shaderSample(shader_.sampleColor);
        const glm::dvec3 shaderPixel(shader_.pixelColor);
        table_.row("sample colour", vec(shaderSample), vec(reference_.sampleColor),
                   differs(shaderSample, reference_.sampleColor, 1e-3));
        table_.row("pixel colour (linear)", vec(shaderPixel), vec(reference_.pixelColor),
                   differs(shaderPixel, reference_.pixelColor, 1e-3));
        table_.row(encoding == Encoding::Srgb ? "pixel 8-bit (sRGB)" : "pixel 8-bit (linear)",
                   levels(shaderPixel, encoding), levels(reference_.pixelColor, encoding),
                   levelsDiffer(shaderPixel, reference_.pixelColor, encoding));
    }

    const Scene& scene_;
    bool useGpu_;
    bool useCpu_;
    const GpuPixelTrace& shader_;
    const CpuPixelExplanation& reference_;
    Table table_;
    double sceneScale_;
    bool shaderHit_;
    bool referenceHit_;
    std::uint32_t referenceNode_;
};

// --json's path, checked before any work; no document is written when it fails, since its own path
// may be the one that would destroy a file.
int checkDocumentPath(const PixelOptions& options) {
    return guarded([&] {
        OutputPlan plan;
        plan.addInput("the scene", options.scenePath);
        plan.addFile("--json", options.jsonPath);
        plan.check();
        return int(kSuccess);
    });
}

}  // namespace

int runPixel(const PixelOptions& options) {
    if (!options.jsonPath.empty()) {
        if (const int checked = checkDocumentPath(options); checked != kSuccess) {
            return checked;
        }
    }
    ValidationLog log;
    PixelRecord record;
    const int code = guarded([&] {
        const Scene& scene = record.scene.emplace(loadScene(options.scenePath, options.image));
        requireInRange("X", options.x, scene.image.width, "the width");
        requireInRange("Y", options.y, scene.image.height, "the height");
        requireInRange("--sample", options.sample, scene.image.samplesPerPixel, "the sample count");
        const auto x = std::uint32_t(options.x);
        const auto y = std::uint32_t(options.y);
        const auto sample = std::uint32_t(options.sample);
        const bool useGpu = options.backend != PixelBackend::Cpu;
        const bool useCpu = options.backend != PixelBackend::Gpu;

        std::printf("pixel (%u, %u) of %s (%ux%u), sample %u of %u\n", x, y, printable(options.scenePath).c_str(),
                    scene.image.width, scene.image.height, sample, scene.image.samplesPerPixel);
        const GpuPixelTrace shader =
            useGpu ? record.shader.emplace(traceOnGpu(options, scene, log, x, y, sample, record)) : GpuPixelTrace{};
        const auto explainStart = std::chrono::steady_clock::now();
        const CpuPixelExplanation reference = useCpu ? explainPixel(scene, x, y, sample) : CpuPixelExplanation{};
        const float margin = useCpu ? pixelMargin(scene, x, y) : 0.0f;
        if (useCpu) {
            record.cpuExplainMilliseconds = millisecondsSince(explainStart);
            record.reference = reference;
            record.margin = margin;
            std::printf("cpu: double-precision reference, world units\n");
        }
        std::printf("\n");

        PixelReport report(scene, useGpu, useCpu, shader, reference);
        report.print();
        if (useCpu) {
            std::printf("cpu decision margin: %.3g (%s)\n", double(margin),
                        margin < kAmbiguityMargin ? "ambiguous: the backends may honestly differ here"
                                                  : "unambiguous: the backends must agree");
        }
        if (useGpu && useCpu) {
            report.printVerdict();
            record.comparison = report.comparison();
        }
        return int(kSuccess);
    });
    const int verdict = withValidationVerdict(code, log);
    if (options.jsonPath.empty()) {
        return verdict;
    }
    nlohmann::json document = pixelDocument(options, record);
    return finishJson(options.jsonPath, document, verdict);
}

}  // namespace hexray::cli
