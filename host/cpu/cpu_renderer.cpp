#include "cpu/cpu_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cfloat>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "accel/bvh.h"
#include "camera/camera.h"
#include "cpu/cpu_intersect.h"
#include "cpu/cpu_margins.h"
#include "cpu/cpu_shading.h"
#include "scene/scene_contents.h"
#include "util/out_of_memory.h"
#include "unit_roundoff.h"

namespace hexray::inline cpu {

Ray cameraRay(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t x, std::uint32_t y,
              std::uint32_t sample) {
    // Camera rays start at t = 0 exactly: no offset, so nothing right in front of the eye is lost.
    return Ray{sheet.origin, sampleDirection(sheet, image, x, y, sample)};
}

namespace {

constexpr double kNoEnd = std::numeric_limits<double>::infinity();  // a camera ray's range

// What the renderer reports for one ray.
struct TracedPixel {
    Color color{0.0};
    PixelClass pixelClass;
    RayDecisions decisions;
    std::optional<Hit> hit;  // the nearest, for the AOVs
};

// The parts of a pixel's class that camera-ray decisions leave undecided.
constexpr PixelAmbiguity kNodePart{true, 0, false};
constexpr PixelAmbiguity kCheckerPart{false, PixelClass::kOddCheckerBit, false};
constexpr PixelAmbiguity kColourPart{false, 0, true};

// ---------------------------------------------------------------- margins through the BVH
//
// The margin pass must give exactly the margins of the loop over every node. They are combined
// by a minimum, so a sphere may be left out when its margins provably cannot be below the
// smallest one already found. A BVH node is skipped when
// - the ray's line (both directions) passes clear of the ball around the node's box, widened
//   against rounding, so no sphere inside can be hit (no nearest-node margin to measure, and
//   every crossing margin takes the line-misses branch of sphereCrossingMargin), and
// - a lower bound on those crossing margins is at least the smallest margin so far.
// For a sphere (c, r) inside the ball (B, R): the line's clearance |l_c| - r >= |l_B| - R, and
// the scale base + |c - eye| + r <= base + |B - eye| + R, so every such margin is at least
// (|l_B| - R) / (base + |B - eye| + R). The computed margins and bound are both within a few
// units of double roundoff of their exact values (every distance in them is divided by a scale
// at least as large), so the bound is lowered by 1e-9 before the comparison. Margins are never
// negative or -0, so the order in which they are met cannot change the minimum.

// Calls visit(sceneNodeIndex) for every sphere that may have a margin below margins.smallest
// for the line through `ray`, and for every sphere the ray may hit; `scaleBase` is what
// sphereCrossingMargin's scale adds to sphereScale(sphere, eye) (0 for a camera ray).
template <class Visit>
void forEachSphereThatMayMatter(const Bvh& bvh, const Ray& ray, const glm::dvec3& eye, double scaleBase,
                                const MarginAccumulator& margins, Visit&& visit) {
    if (bvh.nodes.empty()) {
        return;
    }
    // The lower bound on the margins of the spheres in a node; 0 when the line may meet one.
    const auto marginBound = [&](const BvhNode& node) {
        const glm::dvec3 centre = 0.5 * (node.boundsMin + node.boundsMax);
        // The ball's radius from the rounded centre, so that it contains the box regardless.
        const double radius = glm::length(glm::max(node.boundsMax - centre, centre - node.boundsMin)) * (1.0 + 1e-12);
        const glm::dvec3 f = ray.origin - centre;
        const double lengthL = glm::length(f - glm::dot(f, ray.direction) * ray.direction);
        // intersectSphere reports hits up to a few units of roundoff of |o - c| outside a sphere.
        const double hitPad = 1e-9 * (glm::length(f) + radius);
        if (!(lengthL > radius + hitPad)) {
            return 0.0;
        }
        return (lengthL - radius) / (scaleBase + glm::length(centre - eye) + radius) - 1e-9;
    };
    const auto mayMatter = [&](double bound) { return !(bound >= margins.smallest); };

    struct Pending {
        std::uint32_t node;
        double bound;
    };
    std::vector<Pending> stack{{0, marginBound(bvh.nodes[0])}};
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        if (!mayMatter(pending.bound)) {
            continue;
        }
        const BvhNode& node = bvh.nodes[pending.node];
        if (node.isLeaf()) {
            for (std::uint32_t i = 0; i < node.count; ++i) {
                visit(bvh.sphereNodes[node.firstOrSecondChild + i]);
            }
            continue;
        }
        // The child with the smaller bound first: its spheres are likelier to lower the minimum.
        Pending first{pending.node + 1, marginBound(bvh.nodes[pending.node + 1])};
        Pending second{node.firstOrSecondChild, marginBound(bvh.nodes[node.firstOrSecondChild])};
        if (second.bound < first.bound) {
            std::swap(first, second);
        }
        stack.push_back(second);
        stack.push_back(first);
    }
}

// What every ray of a render reads.
struct RenderContext {
    const Scene& scene;  // in the eye's frame (eye_frame.h)
    const glm::dvec3& frameOrigin;
    const Bvh* bvh;
    const PixelSheet& sheet;
    DecisionRoundoff roundoff;
};

// The camera ray's margins: hit or miss of each node and which hit is nearest (`node`), and
// the eye lying within roundoff of a sphere (`eye`, see sphereCrossingMargins).
struct CameraRayMargins {
    MarginAccumulator node;
    MarginAccumulator eye;

    void addSphere(const Ray& ray, const Sphere& sphere) {
        const SphereCrossingMargins crossing =
            sphereCrossingMargins(ray, sphere, kNoEnd, sphereScale(sphere, ray.origin));
        node.add(crossing.line);
        eye.add(crossing.ends);
    }
};

// addIntersectionMargins with a BVH: planes in a loop, spheres through forEachSphereThatMayMatter
// (pruned by the node margins: a sphere whose line misses has no eye margin).
void addIntersectionMarginsBvh(const Scene& scene, const Bvh& bvh, const Ray& ray,
                               const std::optional<SceneHit>& nearest, CameraRayMargins& margins) {
    const glm::dvec3& eye = ray.origin;
    const double nearestScale =
        nearest ? hitPointScale(scene.nodes[nearest->nodeIndex].geometry, nearest->hit, ray) : 0.0;
    const auto addNearestNodeMargin = [&](std::size_t index, const std::optional<Hit>& other) {
        if (nearest && other && index != nearest->nodeIndex) {
            const double scale = nearestScale + hitPointScale(scene.nodes[index].geometry, *other, ray);
            margins.node.add(nearestNodeMargin(nearest->hit.t, other->t, scale));
        }
    };
    forEachPlane(scene, &bvh, [&](std::size_t index, const Plane& plane) {
        margins.node.add(cameraRayPlaneMargin(ray.direction.y, plane.height - eye.y));
        addNearestNodeMargin(index, intersectPlane(ray, plane));
    });
    forEachSphereThatMayMatter(bvh, ray, eye, 0.0, margins.node, [&](std::uint32_t index) {
        const Sphere& sphere = std::get<Sphere>(scene.nodes[index].geometry);
        margins.addSphere(ray, sphere);
        addNearestNodeMargin(index, intersectSphere(ray, sphere));
    });
}

// ---------------------------------------------------------------- margins, every node

// addIntersectionMargins without a BVH: every node.
void addIntersectionMarginsLoop(const Scene& scene, const Ray& ray, const std::optional<SceneHit>& nearest,
                                CameraRayMargins& margins) {
    for (const Node& node : scene.nodes) {
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            margins.node.add(cameraRayPlaneMargin(ray.direction.y, plane->height - ray.origin.y));
        } else {
            margins.addSphere(ray, std::get<Sphere>(node.geometry));
        }
    }
    if (!nearest) {
        return;
    }
    const double nearestScale = hitPointScale(scene.nodes[nearest->nodeIndex].geometry, nearest->hit, ray);
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (index == nearest->nodeIndex) {
            continue;
        }
        const Geometry& geometry = scene.nodes[index].geometry;
        if (const std::optional<Hit> other = intersectGeometry(ray, geometry)) {
            const double scale = nearestScale + hitPointScale(geometry, *other, ray);
            margins.node.add(nearestNodeMargin(nearest->hit.t, other->t, scale));
        }
    }
}

// The camera ray against every node: hit or miss for each, then which hit is nearest. A near-tie
// leaves the node undecided; the eye within roundoff of a sphere leaves everything undecided (it
// decides which of the sphere's surfaces, if any, the ray sees).
void addIntersectionMargins(const RenderContext& context, const DecisionBounds& bounds, const Ray& ray,
                            const std::optional<SceneHit>& nearest, RayDecisions& decisions) {
    CameraRayMargins margins;
    if (context.bvh) {
        addIntersectionMarginsBvh(context.scene, *context.bvh, ray, nearest, margins);
    } else {
        addIntersectionMarginsLoop(context.scene, ray, nearest, margins);
    }
    decisions.add(margins.node.smallest / bounds.general, kNodePart);
    decisions.add(margins.eye.smallest / bounds.general, PixelAmbiguity::everything());
}

// The shadow ray from the hit toward a light that it faces, against every node that could
// block it. A plane cannot block the rays that leave it, nor a sphere seen from outside those
// from its lit side (convexity); a sphere seen from inside can (ownSphereShadowMargin).
// With a BVH, the spheres that may matter (see forEachSphereThatMayMatter) stand for all of them.
void addShadowMargins(const RenderContext& context, std::size_t shadedNode, const Hit& hit, double hitScale,
                      const glm::dvec3& eye, const PointLight& light, MarginAccumulator& margins) {
    const Scene& scene = context.scene;
    const glm::dvec3 toLight = light.position - hit.point;
    const double distance = glm::length(toLight);
    const Ray shadowRay{hit.point, toLight / distance};
    const double segmentScale = hitScale + glm::length(light.position - eye);
    const auto addSphereMargin = [&](std::size_t index) {
        const Sphere& sphere = std::get<Sphere>(scene.nodes[index].geometry);
        margins.add(sphereCrossingMargin(shadowRay, sphere, distance, segmentScale + sphereScale(sphere, eye)));
    };
    forEachPlane(scene, context.bvh, [&](std::size_t index, const Plane& plane) {
        if (index != shadedNode) {
            margins.add(planeSegmentMargin(hit.point.y - plane.height, light.position.y - plane.height,
                                           segmentScale + std::abs(plane.height - eye.y)));
        }
    });
    const auto* shadedSphere = std::get_if<Sphere>(&scene.nodes[shadedNode].geometry);
    if (shadedSphere && glm::dot(hit.facingNormal, hit.geometricNormal) < 0.0) {  // seen from inside
        const double scale = segmentScale + sphereScale(*shadedSphere, eye);
        margins.add(ownSphereShadowMargin(shadowRay, *shadedSphere, distance, scale));
        margins.add(lightSideMargin(light.position, *shadedSphere, scale));
    }
    if (!context.bvh) {
        for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
            if (index != shadedNode && std::holds_alternative<Sphere>(scene.nodes[index].geometry)) {
                addSphereMargin(index);
            }
        }
    } else {
        forEachSphereThatMayMatter(*context.bvh, shadowRay, eye, segmentScale, margins, [&](std::uint32_t index) {
            if (index != shadedNode) {
                addSphereMargin(index);
            }
        });
    }
}

// How far the eye's place among a plane's cells is rounded, per axis, in units of the compared
// arithmetic's roundoff: the cells are fixed in the world, and both renderers find the eye among
// them in double (the reference adds the eye back, the shader's host divides its coordinates by the
// cell size), so to 2^-53 of the eye's world coordinates whatever the shader's precision.
glm::dvec2 eyePlaceRoundoff(const RenderContext& context) {
    return glm::dvec2(std::abs(context.frameOrigin.x), std::abs(context.frameOrigin.z)) *
           (FLOAT64_UNIT_ROUNDOFF / context.roundoff.general);
}

// The decisions of a lit shader: the checker cell, and for each light whether the surface faces
// it and, if so, whether anything blocks it. A constant shader makes none.
void addShadingMargins(const RenderContext& context, const DecisionBounds& bounds, const Ray& ray,
                       const SceneHit& nearest, RayDecisions& decisions) {
    const Scene& scene = context.scene;
    const Node& node = scene.nodes[nearest.nodeIndex];
    const Shader& shader = scene.shaders[node.shaderIndex];
    if (std::holds_alternative<ConstantShader>(shader)) {
        return;
    }
    const Hit& hit = nearest.hit;
    const glm::dvec3& eye = ray.origin;
    const double hitScale = hitPointScale(node.geometry, hit, ray);
    const auto* sphere = std::get_if<Sphere>(&node.geometry);
    const double normalRoundoff = sphere ? hitScale / std::abs(sphere->radius) : 0.0;  // a plane's is exact

    if (const auto* checker = std::get_if<CheckerShader>(&shader)) {
        const double margin =
            sphere ? sphereCheckerMargin(hit.geometricNormal, checker->size, normalRoundoff) / bounds.sphereChecker
                   : planeCheckerMargin(textureCoordinates(node.geometry, hit, context.frameOrigin), checker->size,
                                        planeTextureScales(hit, ray) + eyePlaceRoundoff(context)) /
                         bounds.general;
        decisions.add(margin, kCheckerPart);
    }
    // Which side of a sphere faces the ray is decided from the normal too (surface.glsl's facing):
    // near a grazing hit it is within the normal's rounding, and turning it turns every light's
    // cos theta. The camera ray's direction errs by about a unit of roundoff.
    const double rayFacingMargin =
        sphere ? facingMargin(glm::dot(hit.geometricNormal, ray.direction), normalRoundoff, 1.0) : kInfinity;
    for (std::size_t index = 0; index < scene.lights.size(); ++index) {
        const PointLight& light = scene.lights[index];
        MarginAccumulator margins;
        margins.add(rayFacingMargin);
        const glm::dvec3 toLight = light.position - hit.point;
        const double distance = glm::length(toLight);
        if (distance == 0.0) {
            margins.add(0.0);  // a light on the point: no direction to face, nothing to decide by
        } else {
            const double cosTheta = glm::dot(hit.facingNormal, toLight / distance);
            const double directionRoundoff = (hitScale + glm::length(light.position - eye)) / distance;
            margins.add(facingMargin(cosTheta, normalRoundoff, directionRoundoff));
            if (cosTheta > 0.0) {
                addShadowMargins(context, nearest.nodeIndex, hit, hitScale, eye, light, margins);
                decisions.add(lightTermMargin(normalRoundoff, directionRoundoff, context.roundoff.general),
                              kColourPart);
            }
        }
        decisions.add(margins.smallest / bounds.general, lightPart(index));
    }
}

// Sample `sample` of pixel (x, y), its decisions measured against their bounds.
TracedPixel tracePixel(const RenderContext& context, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    const Scene& scene = context.scene;
    const Ray ray = cameraRay(context.sheet, scene.image, x, y, sample);
    const DecisionBounds bounds = decisionBounds(
        context.roundoff, cameraDirectionRoundoff(context.sheet, sheetPosition(scene.image, x, y, sample)));
    const std::optional<SceneHit> nearest = findNearestHit(ray, scene, context.bvh);
    RayDecisions decisions;
    addIntersectionMargins(context, bounds, ray, nearest, decisions);
    if (!nearest) {
        return {scene.background, PixelClass{}, decisions, std::nullopt};
    }
    addShadingMargins(context, bounds, ray, *nearest, decisions);
    // The classification comes from the decisions that made the colour, not a second look.
    const ShadedHit shaded =
        shadeHit(scene, scene.nodes[nearest->nodeIndex], nearest->hit, context.bvh, nullptr, context.frameOrigin);
    return {shaded.color, PixelClass{std::uint32_t(nearest->nodeIndex), shaded.flags}, decisions, nearest->hit};
}

// One pixel: the average of its samples, classified by its first.
struct RenderedPixel {
    Color color;
    PixelClass pixelClass;
    float margin;
    PixelAmbiguity ambiguity;
    std::optional<Hit> firstHit;
};

RenderedPixel renderPixel(const RenderContext& context, std::uint32_t x, std::uint32_t y) {
    // With several samples the pixel is classified by its first, whose near-ties are the class's;
    // a near-tie in any other sample may change the colour alone.
    const ImageSettings& image = context.scene.image;
    const TracedPixel first = tracePixel(context, x, y, 0);
    Color sum = first.color;
    MarginAccumulator margin = first.decisions.all;
    PixelAmbiguity ambiguity = first.decisions.ambiguity;
    for (std::uint32_t sample = 1; sample < image.samplesPerPixel; ++sample) {
        const TracedPixel pixel = tracePixel(context, x, y, sample);
        sum += pixel.color;
        margin.add(pixel.decisions.all.smallest);
        ambiguity.colour = ambiguity.colour || pixel.decisions.ambiguity.any();
    }
    return {sum / double(image.samplesPerPixel), first.pixelClass, margin.stored(), ambiguity, first.hit};
}

// Row `y` of the image into row `y - firstRow` of `band`.
void renderRow(const RenderContext& context, std::uint32_t y, std::uint32_t firstRow, CpuRender& band) {
    const std::uint32_t width = band.image.width;
    for (std::uint32_t x = 0; x < width; ++x) {
        const RenderedPixel pixel = renderPixel(context, x, y);
        const std::size_t index = std::size_t(y - firstRow) * width + x;
        // Linear, not clamped (encoding happens later), but finite: a saturated colour beyond
        // float's range is float's largest.
        band.image.pixels[index] = glm::vec3(glm::min(pixel.color, Color(FLT_MAX)));
        band.classes[index] = pixel.pixelClass;
        band.margins[index] = pixel.margin;
        band.ambiguity[index] = pixel.ambiguity;
        if (!band.depth.empty() && pixel.firstHit) {
            band.depth[index] = float(pixel.firstHit->t);
            band.normals[index] = glm::vec3(pixel.firstHit->facingNormal);
        }
    }
}

// `band` sized for `rows` rows of `width`, reusing its storage; depth and normals reset to the
// background's.
void prepareBand(CpuRender& band, std::uint32_t width, std::uint32_t rows, bool withAovs) {
    const std::size_t pixels = std::size_t(width) * rows;
    band.image.width = width;
    band.image.height = rows;
    band.image.pixels.resize(pixels);
    band.classes.resize(pixels);
    band.margins.resize(pixels);
    band.ambiguity.resize(pixels);
    band.depth.assign(withAovs ? pixels : 0, std::numeric_limits<float>::infinity());
    band.normals.assign(withAovs ? pixels : 0, glm::vec3(0.0f));
}

std::optional<Bvh> bvhFor(const Scene& scene, Acceleration acceleration) {
    const bool useBvh = acceleration == Acceleration::Always || (acceleration == Acceleration::Auto && bvhPays(scene));
    return useBvh ? std::optional<Bvh>(buildBvh(scene)) : std::nullopt;
}

// A bad index would otherwise throw inside a worker thread, which ends the program.
void checkShaderIndices(const Scene& scene) {
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (scene.nodes[index].shaderIndex >= scene.shaders.size()) {
            throw std::out_of_range("renderOnCpu: nodes[" + std::to_string(index) + "] names shader " +
                                    std::to_string(scene.nodes[index].shaderIndex) + " but the scene has " +
                                    std::to_string(scene.shaders.size()));
        }
    }
}

}  // namespace

unsigned cpuThreadCount(unsigned requested) {
    return requested ? requested : std::max(1u, std::thread::hardware_concurrency());  // which may report 0
}

CpuRender renderOnCpu(const Scene& scene, unsigned threadCount) {
    return renderOnCpu(scene, threadCount, Acceleration::Auto);
}

CpuRender renderOnCpu(const Scene& scene, unsigned threadCount, Acceleration acceleration, bool withAovs,
                      DecisionRoundoff roundoff) {
    const CpuBandRenderer renderer(scene, threadCount, acceleration, withAovs, roundoff);
    CpuRender render;
    renderer.render(0, scene.image.height, render);
    return render;
}

namespace {

// What the reference holds for a scene, when it cannot: its own copy of the scene and its BVH.
std::string tooBigForTheCpuReference(const Scene& scene) {
    const std::uint64_t bytes = scene.nodes.size() * (sizeof(Node) + 2 * sizeof(BvhNode) + sizeof(std::uint32_t)) +
                                scene.lights.size() * sizeof(PointLight);
    const std::uint64_t mebibytes = (bytes + (std::uint64_t{1} << 20) - 1) >> 20;
    return "the scene's " + sceneContents(scene) + " need about " + std::to_string(mebibytes) +
           " MiB in the CPU reference (its copy of the scene and its BVH)";
}

}  // namespace

CpuBandRenderer::CpuBandRenderer(const Scene& scene, unsigned threadCount, Acceleration acceleration, bool withAovs,
                                 DecisionRoundoff roundoff)
    : frame_(holding([&] { return tooBigForTheCpuReference(scene); }, [&] { return inEyeFrame(scene); })),
      sheet_(makePixelSheet(frame_.scene.camera, sheetAspect(frame_.scene))),
      threads_(std::min({cpuThreadCount(threadCount), kMaxCpuThreads, std::max(scene.image.height, 1u)})),
      withAovs_(withAovs),
      roundoff_(roundoff) {
    checkShaderIndices(frame_.scene);
    // Built once and shared, read-only, by every worker.
    bvh_ = holding([&] { return tooBigForTheCpuReference(scene); }, [&] { return bvhFor(frame_.scene, acceleration); });
}

std::uint32_t CpuBandRenderer::rowsPerBand(std::size_t bandBytes) const {
    const std::size_t pixelBytes = sizeof(glm::vec3) + sizeof(PixelClass) + sizeof(float) + sizeof(PixelAmbiguity) +
                                   (withAovs_ ? sizeof(float) + sizeof(glm::vec3) : 0);
    const std::size_t rowBytes = pixelBytes * std::max(frame_.scene.image.width, 1u);
    return std::uint32_t(std::clamp<std::size_t>(bandBytes / rowBytes, 1, std::max(frame_.scene.image.height, 1u)));
}

void CpuBandRenderer::render(std::uint32_t firstRow, std::uint32_t rows, CpuRender& band,
                             const std::function<void(std::uint32_t)>& rowsDone) const {
    prepareBand(band, frame_.scene.image.width, rows, withAovs_);
    if (frame_.scene.image.width == 0 || rows == 0) {
        return;
    }
    const RenderContext context{frame_.scene, frame_.eye, bvh_ ? &*bvh_ : nullptr, sheet_, roundoff_};
    const unsigned workers = std::min(threads_, rows);
    // On a cache line of its own: the workers read `sheet_` and `band` for every pixel.
    struct alignas(64) RowCount {
        std::atomic<std::uint32_t> finished{0};
    } count;
    // Rows are interleaved (worker w takes rows w, w + n, ...) so that expensive regions of
    // the image are shared out; each row is written by exactly one worker, so no locking.
    const auto renderRows = [&](unsigned worker) {
        for (std::uint32_t y = firstRow + worker; y < firstRow + rows; y += workers) {
            renderRow(context, y, firstRow, band);
            count.finished.fetch_add(1, std::memory_order_relaxed);
        }
    };
    {
        // jthread joins on destruction, also if starting a later worker throws. The calling
        // thread only waits (or reports the rows done): as a worker it would write its stack
        // right beside `sheet_` and `band`, which every worker reads for every pixel (that false
        // sharing cost up to half again the CPU time on two cores).
        std::vector<std::jthread> threads;
        threads.reserve(workers);
        for (unsigned worker = 0; worker < workers; ++worker) {
            threads.emplace_back(renderRows, worker);
        }
        while (rowsDone && count.finished.load(std::memory_order_relaxed) < rows) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            rowsDone(count.finished.load(std::memory_order_relaxed));
        }
    }
    if (rowsDone) {
        rowsDone(rows);
    }
}

float pixelMargin(const Scene& world, std::uint32_t x, std::uint32_t y) {
    const EyeFrameScene frame = inEyeFrame(world);
    const Scene& scene = frame.scene;
    checkShaderIndices(scene);
    const std::optional<Bvh> bvh = bvhFor(scene, Acceleration::Auto);
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    return renderPixel({scene, frame.eye, bvh ? &*bvh : nullptr, sheet, DecisionRoundoff{}}, x, y).margin;
}

}  // namespace hexray::cpu
