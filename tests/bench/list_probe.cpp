// TEMPORARY probe (not for commit): A/B of render.comp variants on random-sphere scenes.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <chrono>
#include <cmath>

#include <CLI/CLI.hpp>

#include "bench/median.h"
#include "camera/camera.h"
#include "gpu/candidate_lists.h"
#include <glm/geometric.hpp>
#include "gpu/gpu_renderer.h"
#include "gpu/shader_compiler.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "util/milliseconds_since.h"

using namespace hexray;

int main(int argc, char** argv) {
    CLI::App app{"probe"};
    std::vector<std::uint32_t> counts{100, 1000, 10000, 100000, 1000000};
    std::vector<std::string> variants;
    int rounds = 3;
    std::uint32_t width = 1920, height = 1080;
    std::string precision = "f32";
    app.add_option("--spheres", counts)->delimiter(',');
    app.add_option("--rounds", rounds);
    app.add_option("--width", width);
    app.add_option("--height", height);
    app.add_option("--precision", precision);
    app.add_option("variants", variants);
    bool morton = false;
    app.add_flag("--morton", morton);
    CLI11_PARSE(app, argc, argv);

    std::vector<std::vector<std::uint32_t>> spirvs;
    for (const std::string& file : variants) {
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        spirvs.push_back(compileComputeShader(text.str(), file));
    }
    VulkanContext context({nullptr, ""});
    GpuRenderer renderer(context);
    const Precision p = precision == "f64" ? Precision::F64 : precision == "f32-naive" ? Precision::F32Naive : Precision::F32;
    for (const std::uint32_t n : counts) {
        Scene scene = makeRandomSpheresScene(n, 1);
        overrideImageSize(scene, width, height, "probe");
        if (morton) {
            glm::dvec3 lo(1e300), hi(-1e300);
            for (const Node& node : scene.nodes) if (auto* sp = std::get_if<Sphere>(&node.geometry)) { lo = glm::min(lo, sp->center); hi = glm::max(hi, sp->center); }
            auto code = [&](const Node& node) -> std::uint64_t {
                auto* sp = std::get_if<Sphere>(&node.geometry);
                if (!sp) return 0;
                glm::dvec3 q = (sp->center - lo) / (hi - lo + 1e-9) * 1023.0;
                std::uint64_t c = 0;
                for (int b = 9; b >= 0; --b) for (int a = 0; a < 3; ++a) c = (c << 1) | ((std::uint64_t(q[a]) >> b) & 1);
                return c + 1;
            };
            std::stable_sort(scene.nodes.begin(), scene.nodes.end(), [&](const Node& a, const Node& b) { return code(a) < code(b); });
        }
        const auto start = std::chrono::steady_clock::now();
        const RenderPlan plan = renderer.plan(scene, {p, Acceleration::Auto});
        const double planMs = millisecondsSince(start);
        std::vector<RenderPlan> plans{plan};
        for (std::size_t v = 0; v < spirvs.size(); ++v) {
            RenderPlan variant = plan;
            variant.kernel = Kernel{variants[v], nullptr, spirvs[v]};
            plans.push_back(variant);
        }
        std::vector<std::vector<double>> ms(plans.size());
        std::vector<std::size_t> hashes(plans.size());
        for (int round = -1; round < rounds; ++round) {
            for (std::size_t v = 0; v < plans.size(); ++v) {
                GpuRenderResult r = renderer.render(scene, plans[v], GpuOutput::Encoded8);
                if (round < 0) {
                    hashes[v] = std::hash<std::string>()(std::string(r.encoded.bytes.begin(), r.encoded.bytes.end()));
                } else {
                    ms[v].push_back(r.timing.renderMilliseconds);
                }
            }
        }
        if (plan.candidates) {
            const CandidateLists& l = *plan.candidates;
            const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
            double sum = 0, sumMax = 0, maxAll = 0;
            std::size_t inRegion = 0;
            for (std::uint32_t y = 0; y < height; ++y) {
                for (std::uint32_t x0 = 0; x0 < width; x0 += 8) {
                    double groupMax = 0;
                    for (std::uint32_t x = x0; x < x0 + 8 && x < width; ++x) {
                        const glm::dvec3 d = sampleDirection(sheet, scene.image, x, y, 0);
                        const glm::vec3 f(d);
                        const auto& g = l.grids[0];
                        const float tu = glm::dot(f, glm::vec3(l.cameraAxes.right)) / glm::dot(f, glm::vec3(l.cameraAxes.forward));
                        const float tv = glm::dot(f, glm::vec3(l.cameraAxes.down)) / glm::dot(f, glm::vec3(l.cameraAxes.forward));
                        const float pu = (tu - g.window.x) * g.window.z, pv = (tv - g.window.y) * g.window.w;
                        double len = 0;
                        if (pu >= 0 && pv >= 0 && pu < g.cells.x && pv < g.cells.y) {
                            const std::size_t cell = g.cells.z + std::uint32_t(pv) * g.cells.x + std::uint32_t(pu);
                            len = l.cellStarts[cell + 1] - l.cellStarts[cell];
                            ++inRegion;
                        }
                        sum += len;
                        groupMax = std::max(groupMax, len);
                    }
                    sumMax += groupMax * 8;
                    maxAll = std::max(maxAll, groupMax);
                }
            }
            {
                const GpuRenderResult aov = renderer.render(scene, plan, GpuOutput::LinearClassesAndAov);
                const Placement& pl = plan.placement;
                for (std::size_t li = 0; li < scene.lights.size(); ++li) {
                    const glm::dvec3 L = scene.lights[li].position;
                    double lsum = 0, lmax = 0;
                    for (std::uint32_t y = 0; y < height; ++y) {
                        for (std::uint32_t x0 = 0; x0 < width; x0 += 8) {
                            double gm = 0;
                            for (std::uint32_t x = x0; x < x0 + 8; ++x) {
                                const std::size_t i = std::size_t(y) * width + x;
                                if (std::isinf(aov.depth[i])) continue;
                                const glm::dvec3 d = sampleDirection(sheet, scene.image, x, y, 0);
                                const glm::dvec3 pnt = scene.camera.position + double(aov.depth[i]) * d;
                                const glm::vec3 f((pnt - L) / pl.scale);
                                const glm::vec3 a = glm::abs(f);
                                const bool bx = a.x >= a.y && a.x >= a.z;
                                const bool by = !bx && a.y >= a.z;
                                const float major = bx ? f.x : (by ? f.y : f.z);
                                const glm::vec2 across = bx ? glm::vec2(f.y, f.z) : (by ? glm::vec2(f.z, f.x) : glm::vec2(f.x, f.y));
                                const unsigned face = (bx ? 0u : (by ? 2u : 4u)) + (major < 0 ? 1u : 0u);
                                const auto& g = l.grids[1 + 6 * li + face];
                                const glm::vec2 t = across / std::abs(major);
                                const float pu = (t.x - g.window.x) * g.window.z, pv = (t.y - g.window.y) * g.window.w;
                                double len = 0;
                                if (pu >= 0 && pv >= 0 && pu < g.cells.x && pv < g.cells.y) {
                                    const std::size_t cell = g.cells.z + std::uint32_t(pv) * g.cells.x + std::uint32_t(pu);
                                    len = l.cellStarts[cell + 1] - l.cellStarts[cell];
                                }
                                lsum += len;
                                gm = std::max(gm, len);
                            }
                            lmax += gm * 8;
                        }
                    }
                    const double px = double(width) * height;
                    std::printf("  light %zu lists per pixel: mean %.2f, mean of 8-lane max %.2f\n", li, lsum / px, lmax / px);
                }
            }
            const double px = double(width) * height;
            std::printf("  camera lists per pixel: mean %.2f, mean of 8-lane max %.2f, max %.0f, pixels in grid %.2f\n",
                        sum / px, sumMax / px, maxAll, inRegion / px);
        }
        std::printf("N=%u plan %.1f ms entries %zu (camera %zu)\n", n, planMs,
                    plan.candidates ? plan.candidates->entries.size() : 0,
                    plan.candidates ? plan.candidates->cameraEntries() : 0);
        for (std::size_t v = 0; v < plans.size(); ++v) {
            const double m = bench::median(ms[v]);
            std::printf("  %-40s %8.1f ms %6.2f Mpix/s %6.0f core-ns/px %s\n", plans[v].kernel.name.c_str(), m,
                        double(width) * height / m / 1e3, 2e6 * m / (double(width) * height),
                        hashes[v] == hashes[0] ? "same" : "DIFFERENT");
        }
        std::fflush(stdout);
    }
}
