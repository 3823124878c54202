// `hexray pixel SCENE X Y`: why a pixel has its colour, as each backend computed it.
// The GPU column comes from the shader's trace mode (shaders/inspect*.glsl), the CPU column
// from the reference's own functions (cpu/cpu_explain.h); both are in world units.

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>

#include "cli/command_support.h"
#include "cpu/cpu_explain.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"

namespace hexray::cli {
namespace {

std::string format(const char* pattern, auto... values) {
    char text[512];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

std::string vec(const glm::dvec3& v) {
    return format("(%.7g, %.7g, %.7g)", v.x, v.y, v.z);
}

std::string distance(double t) {
    return std::isinf(t) ? std::string("miss") : format("t = %.9g", t);
}

std::string levels(const glm::dvec3& linear, Encoding encoding) {
    return format("(%u, %u, %u)", unsigned(encodeChannel(float(linear.x), encoding)),
                  unsigned(encodeChannel(float(linear.y), encoding)), unsigned(encodeChannel(float(linear.z), encoding)));
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
        case gpu::TRACE_LIGHT_LIT: return "lit";
        case gpu::TRACE_LIGHT_FACING_AWAY: return "facing away";
        case gpu::TRACE_LIGHT_SHADOWED: return "shadowed";
        case gpu::TRACE_LIGHT_AT_POINT: return "at the point";
        default: return "not evaluated";
    }
}

std::uint32_t statusOf(LightReach reach) {
    switch (reach) {
        case LightReach::Lit: return gpu::TRACE_LIGHT_LIT;
        case LightReach::FacingAway: return gpu::TRACE_LIGHT_FACING_AWAY;
        case LightReach::Shadowed: return gpu::TRACE_LIGHT_SHADOWED;
        case LightReach::AtPoint: return gpu::TRACE_LIGHT_AT_POINT;
    }
    return gpu::TRACE_LIGHT_NOT_EVALUATED;
}

const char* kindName(const Geometry& geometry) {
    return std::holds_alternative<Plane>(geometry) ? "plane" : "sphere";
}

const char* shaderName(const Shader& shader) {
    return std::holds_alternative<ConstantShader>(shader) ? "constant"
           : std::holds_alternative<LambertShader>(shader) ? "lambert"
                                                            : "checker";
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
    void row(const std::string& label, const std::string& gpuText, const std::string& cpuText, bool differ = false) {
        std::string text = format("%-22s", label.c_str());
        if (gpu_) {
            text += format(" %-44s", gpuText.c_str());
        }
        if (cpu_) {
            text += format(" %-44s", cpuText.c_str());
        }
        const bool flagged = gpu_ && cpu_ && differ;
        differences_ += flagged ? 1 : 0;
        if (flagged) {
            text += " <- differs";
        }
        text.erase(text.find_last_not_of(' ') + 1);
        std::printf("%s\n", text.c_str());
    }
    int differences() const { return differences_; }

private:
    bool gpu_;
    bool cpu_;
    int differences_ = 0;
};

void requireInRange(const char* what, std::int64_t value, std::uint32_t limit, const char* of) {
    if (value < 0 || value >= std::int64_t(limit)) {
        throw SceneError(format("%s = %lld is outside the image: %s is %u, so %s must be in 0..%u", what,
                                static_cast<long long>(value), of, limit, what, limit - 1));
    }
}

}  // namespace

int runPixel(const PixelOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const Scene scene = loadScene(options.scenePath, options.image);
        requireInRange("X", options.x, scene.image.width, "the width");
        requireInRange("Y", options.y, scene.image.height, "the height");
        requireInRange("--sample", options.sample, scene.image.samplesPerPixel, "the sample count");
        const auto x = std::uint32_t(options.x);
        const auto y = std::uint32_t(options.y);
        const auto sample = std::uint32_t(options.sample);
        const bool useGpu = options.backend != PixelBackend::Cpu;
        const bool useCpu = options.backend != PixelBackend::Gpu;

        std::printf("pixel (%u, %u) of %s (%ux%u), sample %u of %u\n", x, y, options.scenePath.c_str(),
                    scene.image.width, scene.image.height, sample, scene.image.samplesPerPixel);
        GpuPixelTrace g;
        if (useGpu) {
            const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
            GpuRenderer renderer(context);
            g = renderer.tracePixel(scene, options.precision, x, y, sample);
            std::printf("gpu: %s on %s; %s\n", std::string(precisionName(g.precision)).c_str(),
                        context.selected().name.c_str(),
                        g.cameraRelative
                            ? format("the shader works camera-relative, lengths divided by %g; printed here in "
                                     "world units (eye added back, lengths multiplied by %g)",
                                     g.scale, g.scale)
                                  .c_str()
                            : "the shader works in world coordinates");
        }
        CpuPixelExplanation c;
        float margin = 0.0f;
        if (useCpu) {
            c = explainPixel(scene, x, y, sample);
            margin = pixelMargin(scene, x, y);
            std::printf("cpu: double-precision reference, world units\n");
        }
        std::printf("\n");

        const double sceneScale = glm::length(c.ray.origin) + glm::length(g.rayOrigin);
        Table table(useGpu, useCpu);
        table.header();
        table.row("ray origin", vec(g.rayOrigin), vec(c.ray.origin), differs(g.rayOrigin, c.ray.origin, sceneScale));
        table.row("ray direction", vec(g.rayDirection), vec(c.ray.direction),
                  differs(g.rayDirection, c.ray.direction, 1.0));
        std::printf("candidates\n");
        // Nodes that every backend shown misses are only counted: a scene may have thousands.
        std::size_t missedByAll = 0;
        for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
            const double miss = std::numeric_limits<double>::infinity();
            const double gt = useGpu ? g.candidates[i] : miss;
            const double ct = useCpu && c.candidates[i] ? c.candidates[i]->t : miss;
            if (std::isinf(gt) && std::isinf(ct)) {
                ++missedByAll;
                continue;
            }
            table.row(format("  node %zu %s", i, kindName(scene.nodes[i].geometry)), distance(gt), distance(ct),
                      differs(gt, ct, 0.0));
        }
        if (missedByAll > 0) {
            std::printf("  %zu other node%s: miss\n", missedByAll, missedByAll == 1 ? "" : "s");
        }
        const bool gpuHit = g.node != PixelClass::kBackground;
        const bool cpuHit = c.nearest.has_value();
        const std::uint32_t cpuNode = cpuHit ? std::uint32_t(c.nearest->nodeIndex) : PixelClass::kBackground;
        const auto hitText = [](bool hit, std::uint32_t node, double t) {
            return hit ? format("node %u, %s", node, distance(t).c_str()) : std::string("background");
        };
        table.row("hit", hitText(gpuHit, g.node, g.t), hitText(cpuHit, cpuNode, cpuHit ? c.nearest->hit.t : 0.0),
                  g.node != cpuNode || (gpuHit && cpuHit && differs(g.t, c.nearest->hit.t, 0.0)));
        if (gpuHit || cpuHit) {
            const glm::dvec3 cpuPosition = cpuHit ? c.nearest->hit.point : glm::dvec3(0);
            const glm::dvec3 cpuNormal = cpuHit ? c.nearest->hit.facingNormal : glm::dvec3(0);
            table.row("position", gpuHit ? vec(g.position) : "", cpuHit ? vec(cpuPosition) : "",
                      differs(g.position, cpuPosition, sceneScale));
            table.row("normal (facing ray)", gpuHit ? vec(g.normal) : "", cpuHit ? vec(cpuNormal) : "",
                      differs(g.normal, cpuNormal, 1.0));
            const auto shaderText = [&](bool hit, std::uint32_t node) {
                return hit ? std::string(shaderName(scene.shaders.at(scene.nodes[node].shaderIndex))) : std::string();
            };
            table.row("shader", shaderText(gpuHit, g.node), shaderText(cpuHit, cpuNode));
            const bool gpuOdd = (g.flags & PixelClass::kOddCheckerBit) != 0;
            const bool cpuOdd = (c.pixelClass.flags & PixelClass::kOddCheckerBit) != 0;
            std::string gpuAlbedo = gpuHit ? vec(glm::dvec3(g.albedo)) : "";
            std::string cpuAlbedo = cpuHit ? vec(c.albedo) : "";
            if (c.checkerCell) {
                cpuAlbedo += format(" cell (%.0f, %.0f) %s", c.checkerCell->x, c.checkerCell->y, cpuOdd ? "odd" : "even");
            }
            if (gpuHit && std::holds_alternative<CheckerShader>(scene.shaders.at(scene.nodes[g.node].shaderIndex))) {
                gpuAlbedo += gpuOdd ? " odd cell" : " even cell";
            }
            table.row("albedo", gpuAlbedo, cpuAlbedo, gpuOdd != cpuOdd || differs(glm::dvec3(g.albedo), c.albedo, 0.0));
            for (std::size_t i = 0; i < scene.lights.size(); ++i) {
                const GpuTraceLight gl = useGpu ? g.lights[i] : GpuTraceLight{};
                const LightTerm cl =
                    i < c.lights.size() ? c.lights[i] : LightTerm{{LightReach::AtPoint, 0, 0}, Color(0)};
                const std::uint32_t cpuStatus = i < c.lights.size() ? statusOf(cl.decision.reach) : 0;
                const bool gpuEvaluated = gl.status != gpu::TRACE_LIGHT_NOT_EVALUATED;
                const bool cpuEvaluated = cpuStatus != gpu::TRACE_LIGHT_NOT_EVALUATED;
                table.row(format("light %zu", i), lightStatus(gl.status), lightStatus(cpuStatus), gl.status != cpuStatus);
                if (!gpuEvaluated && !cpuEvaluated) {
                    continue;
                }
                table.row("  cos theta", gpuEvaluated ? format("%.7g", gl.cosTheta) : "",
                          cpuEvaluated ? format("%.7g", cl.decision.cosTheta) : "",
                          differs(gl.cosTheta, cl.decision.cosTheta, 1.0));
                table.row("  r^2", gpuEvaluated ? format("%.9g", gl.distanceSquared) : "",
                          cpuEvaluated ? format("%.9g", cl.decision.distanceSquared) : "",
                          differs(gl.distanceSquared, cl.decision.distanceSquared, 0.0));
                table.row("  contribution", gpuEvaluated ? vec(glm::dvec3(gl.contribution)) : "",
                          cpuEvaluated ? vec(cl.contribution) : "",
                          differs(glm::dvec3(gl.contribution), cl.contribution, 1e-3));
            }
        }
        const Encoding encoding = scene.image.encoding;
        table.row("sample colour", vec(glm::dvec3(g.sampleColor)), vec(c.sampleColor),
                  differs(glm::dvec3(g.sampleColor), c.sampleColor, 1e-3));
        table.row("pixel colour (linear)", vec(glm::dvec3(g.pixelColor)), vec(c.pixelColor),
                  differs(glm::dvec3(g.pixelColor), c.pixelColor, 1e-3));
        table.row(encoding == Encoding::Srgb ? "pixel 8-bit (sRGB)" : "pixel 8-bit (linear)",
                  levels(glm::dvec3(g.pixelColor), encoding), levels(c.pixelColor, encoding),
                  levelsDiffer(glm::dvec3(g.pixelColor), c.pixelColor, encoding));
        if (useCpu) {
            std::printf("cpu decision margin: %.3g (%s)\n", double(margin),
                        margin < kAmbiguityMargin ? "ambiguous: the backends may honestly differ here"
                                                  : "unambiguous: the backends must agree");
        }
        if (useGpu && useCpu) {
            const bool sameClass = g.node == cpuNode && g.flags == c.pixelClass.flags;
            if (table.differences() == 0 && sameClass) {
                std::printf("gpu and cpu agree\n");
            } else {
                std::printf("DIFFERENCE: %d row%s differ (marked)%s\n", table.differences(),
                            table.differences() == 1 ? "" : "s", sameClass ? "" : "; the pixel's class differs");
            }
        }
        return int(kSuccess);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
