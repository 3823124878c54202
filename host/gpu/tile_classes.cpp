#include "gpu/tile_classes.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "shader_interface.h"

namespace hexray::inline gpu {
namespace {

// ---------------------------------------------------------------- tunables
// Every angle a test is left out by must exceed kAnglePad radians plus kAnglePadPerRatio times the
// distance-to-radius ratio of the sphere involved: the shader's ray directions carry float
// rounding of about 1e-7 rad, and its fast sphere tests err by about 6e-8 times that ratio (their
// discriminants are rounded against the squared distance), so the pads are a hundred times both.
constexpr double kAnglePad = 1e-5;
constexpr double kAnglePadPerRatio = 1e-5;
// A plane is left out of a tile when every ray of it points away from the plane by more than this
// fraction of its length.
constexpr double kPlaneSlopePad = 1e-5;

constexpr std::uint32_t kTile = gpu::WORKGROUP_SIZE;

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

// The camera rays of one tile: the sheet's aim points at the four corners of the footprint of
// every sample of its pixels (samples lie within a pixel of their pixel's corner), padded by a
// pixel, and a cone around them. The aim point is affine in the image position, so what holds at
// the four corners bounds the whole tile.
struct TileRays {
    std::array<glm::dvec3, 4> aims;
    glm::dvec3 axis{0.0};
    double halfAngle = 0.0;
};

TileRays tileRays(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t tileX, std::uint32_t tileY) {
    const double x0 = double(tileX * kTile) - 1.0;
    const double x1 = double(tileX * kTile + kTile) + 1.0;
    const double y0 = double(tileY * kTile) - 1.0;
    const double y1 = double(tileY * kTile + kTile) + 1.0;
    TileRays rays;
    std::size_t corner = 0;
    for (const double sy : {y0, y1}) {
        for (const double sx : {x0, x1}) {
            rays.aims[corner++] =
                sheet.topLeft + sheet.right * (sx / double(image.width)) + sheet.down * (sy / double(image.height));
        }
    }
    for (const glm::dvec3& aim : rays.aims) {
        rays.axis += glm::normalize(aim);
    }
    rays.axis = glm::normalize(rays.axis);
    for (const glm::dvec3& aim : rays.aims) {
        rays.halfAngle = std::max(rays.halfAngle, angleBetween(rays.axis, aim));
    }
    return rays;
}

double anglePad(double distance, double radius) {
    return kAnglePad + kAnglePadPerRatio * distance / radius;
}

// Whether some camera ray of the tile may meet the sphere.
bool mayHitSphere(const TileRays& rays, const glm::dvec3& eye, const Sphere& sphere) {
    const glm::dvec3 toCenter = sphere.center - eye;
    const double distance = glm::length(toCenter);
    if (distance <= sphere.radius * (1.0 + 1e-6)) {
        return true;  // the eye is inside, or on the surface
    }
    const double angularRadius = std::asin(std::min(1.0, sphere.radius / distance));
    return angleBetween(rays.axis, toCenter) <= rays.halfAngle + angularRadius + anglePad(distance, sphere.radius);
}

// Whether every camera ray of the tile points toward the plane (away from it: none can hit it).
bool allAimAt(const TileRays& rays, double heightAboveEye, bool toward) {
    return std::all_of(rays.aims.begin(), rays.aims.end(), [&](const glm::dvec3& aim) {
        const double slope = (heightAboveEye > 0 ? aim.y : -aim.y) / glm::length(aim);
        return toward ? slope > kPlaneSlopePad : slope < -kPlaneSlopePad;
    });
}

// A ball holding every point of a node the tile's camera rays can see; unbounded when the tile
// reaches a plane's horizon.
struct Ball {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    bool unbounded = false;
};

Ball visiblePart(const TileRays& rays, const glm::dvec3& eye, const Geometry& geometry) {
    if (const auto* sphere = std::get_if<Sphere>(&geometry)) {
        return Ball{sphere->center, sphere->radius * (1.0 + 1e-6), false};
    }
    const double heightAboveEye = std::get<Plane>(geometry).height - eye.y;
    if (!allAimAt(rays, heightAboveEye, true)) {
        return Ball{{}, 0.0, true};
    }
    // The rays through the four corners meet the plane at the corners of what the tile sees of it.
    std::array<glm::dvec3, 4> corners;
    glm::dvec3 center(0.0);
    for (std::size_t i = 0; i < 4; ++i) {
        corners[i] = eye + rays.aims[i] * (heightAboveEye / rays.aims[i].y);
        center += 0.25 * corners[i];
    }
    double radius = 0.0;
    double reach = 0.0;
    for (const glm::dvec3& corner : corners) {
        radius = std::max(radius, glm::length(corner - center));
        reach = std::max(reach, glm::length(corner - eye));
    }
    return Ball{center, radius + 1e-6 * reach, false};
}

// Whether the sphere may come between a point of the ball and the light: the segments from the
// light to the ball's points lie in the cone from the light around the ball, up to its far side.
bool mayShadow(const Ball& seen, const glm::dvec3& light, const Sphere& blocker) {
    if (seen.unbounded) {
        return true;
    }
    const glm::dvec3 toBlocker = blocker.center - light;
    const glm::dvec3 toSeen = seen.center - light;
    const double blockerDistance = glm::length(toBlocker);
    const double seenDistance = glm::length(toSeen);
    if (blockerDistance <= blocker.radius * (1.0 + 1e-6) || seenDistance <= seen.radius) {
        return true;  // the light is inside the blocker, or among the points seen
    }
    if (blockerDistance - blocker.radius > (seenDistance + seen.radius) * (1.0 + 1e-6)) {
        return false;  // wholly beyond the points seen
    }
    const double seenAngle = std::asin(seen.radius / seenDistance);
    const double blockerAngle = std::asin(std::min(1.0, blocker.radius / blockerDistance));
    return angleBetween(toBlocker, toSeen) <= seenAngle + blockerAngle + anglePad(blockerDistance, blocker.radius);
}

TileWork tileWork(const Scene& scene, const SceneCode& code, const TileRays& rays) {
    const glm::dvec3 eye = scene.camera.position;
    TileWork work;
    std::vector<Ball> seen;
    std::vector<std::uint32_t> seenNodes;
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        const Geometry& geometry = scene.nodes[i].geometry;
        const bool mayHit = std::holds_alternative<Sphere>(geometry)
                                ? mayHitSphere(rays, eye, std::get<Sphere>(geometry))
                                : !allAimAt(rays, std::get<Plane>(geometry).height - eye.y, false) &&
                                      std::get<Plane>(geometry).height != eye.y;
        if (mayHit) {
            work.primary |= 1u << i;
            seen.push_back(visiblePart(rays, eye, geometry));
            seenNodes.push_back(i);
        }
    }
    for (std::size_t light = 0; light < code.shadowTests.size(); ++light) {
        std::uint32_t shadow = 0;
        for (const ShadowTest& test : code.shadowTests[light]) {
            const auto* blocker = std::get_if<Sphere>(&scene.nodes[test.node].geometry);
            if (!blocker) {
                continue;  // planes are always tested
            }
            for (std::size_t k = 0; k < seen.size(); ++k) {
                // A sphere the camera sees from outside cannot shadow its own visible points.
                const bool itself = seenNodes[k] == test.node && code.nodes[test.node].cameraOutside;
                if (!itself && mayShadow(seen[k], scene.lights[light].position, *blocker)) {
                    shadow |= 1u << test.node;
                    break;
                }
            }
        }
        work.shadow.push_back(shadow);
    }
    return work;
}

std::size_t cost(const TileWork& work) {
    std::size_t tests = std::size_t(std::popcount(work.primary));
    for (const std::uint32_t shadow : work.shadow) {
        tests += std::size_t(std::popcount(shadow));
    }
    return tests;
}

TileWork joined(const TileWork& a, const TileWork& b) {
    TileWork work = a;
    work.primary |= b.primary;
    for (std::size_t light = 0; light < work.shadow.size(); ++light) {
        work.shadow[light] |= b.shadow[light];
    }
    return work;
}

// Merges the class of fewest tiles into the one whose work grows least, until at most `maxClasses`.
void mergeClasses(TileClassification& classification, std::size_t maxClasses) {
    while (classification.classes.size() > std::max<std::size_t>(maxClasses, 1)) {
        std::vector<std::size_t> tiles(classification.classes.size(), 0);
        for (const std::uint32_t c : classification.classOfTile) {
            ++tiles[c];
        }
        const std::size_t smallest = std::size_t(std::min_element(tiles.begin(), tiles.end()) - tiles.begin());
        std::size_t target = smallest == 0 ? 1 : 0;
        std::size_t growth = std::numeric_limits<std::size_t>::max();
        for (std::size_t c = 0; c < classification.classes.size(); ++c) {
            const TileWork merged = joined(classification.classes[c], classification.classes[smallest]);
            const std::size_t added = (cost(merged) - cost(classification.classes[c])) * tiles[c] +
                                      (cost(merged) - cost(classification.classes[smallest])) * tiles[smallest];
            if (c != smallest && added < growth) {
                growth = added;
                target = c;
            }
        }
        classification.classes[target] = joined(classification.classes[target], classification.classes[smallest]);
        classification.classes.erase(classification.classes.begin() + std::ptrdiff_t(smallest));
        for (std::uint32_t& c : classification.classOfTile) {
            c = c == smallest ? std::uint32_t(target > smallest ? target - 1 : target) : c > smallest ? c - 1 : c;
        }
    }
}

}  // namespace

TileClassification classifyTiles(const Scene& scene, const SceneCode& code, std::size_t maxClasses) {
    const ImageSettings& image = scene.image;
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    TileClassification classification;
    classification.tilesX = (image.width + kTile - 1) / kTile;
    classification.tilesY = (image.height + kTile - 1) / kTile;
    std::map<TileWork, std::uint32_t> classes;
    for (std::uint32_t y = 0; y < classification.tilesY; ++y) {
        for (std::uint32_t x = 0; x < classification.tilesX; ++x) {
            const TileWork work = tileWork(scene, code, tileRays(sheet, image, x, y));
            const auto [found, added] = classes.emplace(work, std::uint32_t(classification.classes.size()));
            if (added) {
                classification.classes.push_back(work);
            }
            classification.classOfTile.push_back(found->second);
        }
    }
    mergeClasses(classification, maxClasses);
    return classification;
}

SceneCode codeForClass(const SceneCode& code, const TileWork& work) {
    SceneCode culled = code;
    for (std::uint32_t i = 0; i < culled.nodes.size(); ++i) {
        culled.nodes[i].cameraTested = (work.primary >> i) & 1u;
    }
    for (std::size_t light = 0; light < culled.shadowTests.size(); ++light) {
        for (ShadowTest& test : culled.shadowTests[light]) {
            const bool sphere = culled.nodes[test.node].geometry == gpu::GEOMETRY_SPHERE;
            test.tested = !sphere || test.hidesLight || ((work.shadow[light] >> test.node) & 1u);
        }
    }
    return culled;
}

WorkPerPixel workPerPixel(const SceneCode& code) {
    WorkPerPixel work;
    work.primaryTests = double(
        std::count_if(code.nodes.begin(), code.nodes.end(), [](const NodeCode& node) { return node.cameraTested; }));
    for (const std::vector<ShadowTest>& tests : code.shadowTests) {
        const auto tested = std::count_if(tests.begin(), tests.end(), [](const ShadowTest& t) { return t.tested; });
        work.shadowRays += tested > 0 ? 1.0 : 0.0;
        work.shadowTests += double(tested);
    }
    return work;
}

WorkPerPixel workPerPixel(const SceneCode& code, const TileClassification& classification, const ImageSettings& image) {
    std::vector<WorkPerPixel> perClass;
    for (const TileWork& work : classification.classes) {
        perClass.push_back(workPerPixel(codeForClass(code, work)));
    }
    WorkPerPixel total;
    for (std::uint32_t tile = 0; tile < classification.classOfTile.size(); ++tile) {
        const std::uint32_t x = tile % classification.tilesX;
        const std::uint32_t y = tile / classification.tilesX;
        const double pixels =
            double(std::min(kTile, image.width - x * kTile)) * std::min(kTile, image.height - y * kTile);
        const WorkPerPixel& work = perClass[classification.classOfTile[tile]];
        total.primaryTests += work.primaryTests * pixels;
        total.shadowRays += work.shadowRays * pixels;
        total.shadowTests += work.shadowTests * pixels;
    }
    const double pixels = double(image.width) * image.height;
    return {total.primaryTests / pixels, total.shadowRays / pixels, total.shadowTests / pixels};
}

}  // namespace hexray::gpu
