#pragma once
// Ground truth for the hard-case suite that does not come from hexray: every pixel's ray is
// rebuilt from the shared camera sheet (makePixelSheet + samplingOffset, as both renderers do)
// and everything after that is computed here in long double (64-bit mantissa, ~5e-20
// relative) from closed forms:
//   - sphere hit or miss by the angle test: the angle between the ray and the direction to the
//     centre against the silhouette's half-angle asin(r / D);
//   - plane hits by t = (h - o.y) / d.y;
//   - the visible node by comparing those analytic distances;
//   - checker parity from the analytic hit point;
//   - lit or shadowed from cos(theta) and the analytic clearance of the segment to the light
//     against every sphere and plane.
// Nothing here calls hexray's intersection or shading code (host/cpu, host/gpu); only the scene
// model, the loader and the camera sheet are shared.
//
// Every discrete decision also gets a verdict "ambiguous" when the exact answer lies within an
// explicit margin of its boundary; the margins are in Margins below, each with its reason.
// The checks at the end count violations on the unambiguous pixels only and report how many
// pixels they looked at, so that a caller can insist that a check was not vacuous.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "camera/camera.h"
#include "image/image.h"
#include "image/pixel_class.h"
#include "scene/scene.h"

namespace hexray::analytic {

using Real = long double;

// ---------------------------------------------------------------- vectors in long double

struct V3 {
    Real x = 0, y = 0, z = 0;
};
inline V3 toV3(const glm::dvec3& v) {
    return {Real(v.x), Real(v.y), Real(v.z)};
}
inline V3 operator+(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V3 operator-(V3 a, V3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V3 operator-(V3 a) {
    return {-a.x, -a.y, -a.z};
}
inline V3 operator*(V3 a, Real s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline V3 operator*(Real s, V3 a) {
    return a * s;
}
inline Real dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real length(V3 a) {
    return std::sqrt(dot(a, a));
}
inline V3 normalize(V3 a) {
    return a * (Real(1) / length(a));
}
// The angle between two vectors, accurate at any angle (acos of a dot product is not near 0).
inline Real angleBetween(V3 a, V3 b) {
    return std::atan2(length(cross(a, b)), dot(a, b));
}

// ---------------------------------------------------------------- margins

struct Margins {
    // Sphere silhouettes (hit or miss of a camera ray): excluded within this many pixels of
    // the silhouette, measured as the angle between the ray and the silhouette cone against
    // the pixel's own angular size. A pixel that close straddles the silhouette, so which side
    // its one sample lands on is an accident of sampling rather than something to demand of
    // the arithmetic; beyond it a hit/miss error is a real one (float32 Hearn-Baker resolves
    // the silhouette to ~1e-6 of the sphere's distance, far below half a pixel here).
    Real silhouettePixels = 0.5;

    // Plane hit or miss of a camera ray is the sign of d.y (camera off the plane). Excluded
    // within this many pixels of the horizon d.y = 0, for the same reason as the silhouette.
    // A scene whose camera is not rotated may set 0: then d.y = TL.y + down.y * s with no other
    // terms, float32 keeps its sign exactly, and a row with d.y == 0 exactly must be a miss.
    Real horizonPixels = 0.5;

    // Relative margin for decisions whose float32 error is proportional to a length: which of
    // two hits is nearer, which checker cell, whether a segment to a light clears a surface.
    // 1e-5 is ~170 float32 units of roundoff (2^-24 = 6e-8): room for a chain of a dozen
    // operations, yet below a pixel wherever a ray does not graze a surface. The lengths it multiplies are
    // given where it is used; all are measured from the camera, as the renderers rebase there.
    Real relative = 1e-5L;

    // Whether a sphere point faces a light: excluded when |cos| is below this. The shader's
    // normal comes from a hit point good to ~6e-8 * t, i.e. ~6e-8 * t / r in the normal, and
    // the light direction is good to ~6e-8 * |L - eye| / |L - p|; in these scenes t / r and
    // |L - eye| / |L - p| stay below ~20, except the far tiny spheres, whose checked cap has
    // cos >= 0.2 anyway. So the float32 error is below ~1.2e-6; 1e-4 leaves ~80x.
    Real sphereCos = 1e-4L;
};

// ---------------------------------------------------------------- rays

struct PixelRay {
    V3 origin;
    V3 direction;         // unit
    Real pixelAngle = 0;  // the angular size of the pixel at its sample point (the smaller side)
};

// The rays of a scene's image, built as both renderers build them:
// direction = normalize(TL + right * sx / W + down * sy / H), sx = x + samplingOffset.
class RayGrid {
public:
    explicit RayGrid(const Scene& scene)
        : sheet_(makePixelSheet(scene.camera, sheetAspect(scene))),
          width_(scene.image.width),
          height_(scene.image.height),
          offset_(samplingOffset(scene.image.sampling)) {}

    V3 direction(Real sx, Real sy) const {
        const V3 target =
            toV3(sheet_.topLeft) + toV3(sheet_.right) * (sx / Real(width_)) + toV3(sheet_.down) * (sy / Real(height_));
        return normalize(target);
    }

    PixelRay at(std::uint32_t x, std::uint32_t y) const {
        const Real sx = Real(x) + offset_;
        const Real sy = Real(y) + offset_;
        PixelRay ray;
        ray.origin = toV3(sheet_.origin);
        ray.direction = direction(sx, sy);
        const Real acrossX = angleBetween(ray.direction, direction(sx + 1, sy));
        const Real acrossY = angleBetween(ray.direction, direction(sx, sy + 1));
        ray.pixelAngle = std::min(acrossX, acrossY);
        return ray;
    }

private:
    PixelSheet sheet_;
    std::uint32_t width_, height_;
    Real offset_;
};

// ---------------------------------------------------------------- the truth for one pixel

inline constexpr std::uint32_t kNoNode = PixelClass::kBackground;

struct LightTruth {
    bool lit = false;
    bool ambiguous = false;
    Real cosTheta = 0;
    Real distanceSquared = 0;
};

struct PixelTruth {
    std::uint32_t node = kNoNode;
    bool nodeAmbiguous = false;
    Real t = 0;
    V3 point;
    V3 facingNormal;
    Real incidence = 0;  // |d . n| at the hit
    bool isPlaneChecker = false;
    bool checkerOdd = false;
    bool checkerAmbiguous = false;
    Real checkerEdgeDistance = 0;  // world units to the nearest cell edge (plane checkers)
    std::vector<LightTruth> lights;
    glm::dvec3 color{0.0};  // the model's linear colour, from the decisions above
    bool anyAmbiguous() const {
        if (nodeAmbiguous || checkerAmbiguous)
            return true;
        for (const LightTruth& l : lights) {
            if (l.ambiguous)
                return true;
        }
        return false;
    }
};

// Hit or miss of one node along a camera ray, with the distance it would have.
struct NodeHit {
    bool hit = false;
    bool ambiguous = false;
    Real t = std::numeric_limits<Real>::infinity();  // hit: distance; near miss: closest approach
    Real incidence = 0;                              // |d . n| at the hit (0: tangent)
};

inline NodeHit planeHit(const PixelRay& ray, Real height, const Margins& margins) {
    NodeHit h;
    const Real above = height - ray.origin.y;  // two doubles: exactly 0 when they are equal
    const Real dy = ray.direction.y;
    if (above == 0) {
        return h;  // camera on the plane: t = 0 is not a hit, for every ray; exact
    }
    const Real elevation = std::asin(std::fabs(dy));
    h.ambiguous = elevation < margins.horizonPixels * ray.pixelAngle;
    if (dy == 0) {
        return h;  // parallel: a miss ("hit at infinity" is not a hit)
    }
    const Real t = above / dy;
    h.t = std::fabs(t);
    h.incidence = std::fabs(dy);
    h.hit = t > 0;
    return h;
}

inline NodeHit sphereHit(const PixelRay& ray, V3 center, Real radius, const Margins& margins) {
    NodeHit h;
    const V3 f = center - ray.origin;
    const Real distance = length(f);
    const Real b = dot(f, ray.direction);            // along the ray to the closest approach
    const Real l = length(cross(f, ray.direction));  // the centre's distance from the ray's line
    // Clamped: within rounding of the silhouette (an excluded pixel anyway) it could dip below 0.
    const Real halfChord2 = std::max(Real(0), (radius - l) * (radius + l));
    if (distance < radius) {
        // From inside every ray hits the far side, well away from any silhouette. (No hard case
        // puts the camera within rounding distance of a sphere's surface.)
        h.hit = true;
        h.t = b + std::sqrt(halfChord2);
        h.incidence = std::sqrt(halfChord2) / radius;
        return h;
    }
    const Real theta = angleBetween(f, ray.direction);
    const Real alpha = std::atan2(radius, std::sqrt((distance - radius) * (distance + radius)));
    h.hit = theta < alpha;
    h.ambiguous = std::fabs(theta - alpha) < margins.silhouettePixels * ray.pixelAngle;
    if (h.hit) {
        h.t = b - std::sqrt(halfChord2);
        h.incidence = std::sqrt(halfChord2) / radius;
    } else {
        h.t = b;  // where it would be hit if a rounding error turned the miss into a hit
    }
    return h;
}

inline NodeHit nodeHit(const PixelRay& ray, const Node& node, const Margins& margins) {
    if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
        return planeHit(ray, Real(plane->height), margins);
    }
    const Sphere& sphere = std::get<Sphere>(node.geometry);
    return sphereHit(ray, toV3(sphere.center), Real(sphere.radius), margins);
}

// Parity of floor(x) for a long double holding any real number.
inline bool isOddCell(Real coordinateOverSize) {
    const Real cell = std::floor(coordinateOverSize);
    return std::fmod(std::fabs(cell), Real(2)) == 1;
}

// Whether the surface crosses the open segment from `from` (on node `ownNode`) to the light.
struct Occlusion {
    bool occluded = false;
    bool ambiguous = false;
};

inline Occlusion segmentOcclusion(const Scene& scene, std::uint32_t ownNode, bool ownFromInside, V3 from, V3 light,
                                  const Margins& margins) {
    const bool fromOnPlane = std::holds_alternative<Plane>(scene.nodes[ownNode].geometry);
    const V3 eye = toV3(scene.camera.position);
    const V3 toLight = light - from;
    const Real segment = length(toLight);
    const V3 u = toLight * (Real(1) / segment);
    // float32 moves the shadow ray's origin by ~eps |from - eye|, its direction by ~eps, hence
    // its line by ~eps |light - from| at the far end, and the light by ~eps |light - eye|.
    const Real baseScale = length(from - eye) + segment + length(light - eye);
    bool occluded = false;
    bool ambiguous = false;
    for (std::uint32_t j = 0; j < scene.nodes.size(); ++j) {
        const Node& node = scene.nodes[j];
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            if (j == ownNode) {
                continue;  // a segment leaving a plane cannot cross it again: exact
            }
            const Real h = Real(plane->height);
            const Real a = from.y - h;
            const Real b = light.y - h;
            if (b == 0) {
                continue;  // the light lies in this plane: it meets the segment at its end, not between
            }
            // Whether the ends lie on opposite sides: float32 perturbs each end's height by ~eps of
            // its height above the eye (a point snapped onto a plane), or of its whole distance
            // from the eye (a sphere point, which comes from t * d), and the plane's by ~eps of its own.
            const Real scale = (fromOnPlane ? std::fabs(from.y - eye.y) : length(from - eye)) +
                               std::fabs(light.y - eye.y) + std::fabs(h - eye.y);
            if (std::min(std::fabs(a), std::fabs(b)) < margins.relative * scale) {
                ambiguous = true;
            } else if ((a < 0) != (b < 0)) {
                occluded = true;
            }
            continue;
        }
        const Sphere& sphere = std::get<Sphere>(node.geometry);
        const V3 c = toV3(sphere.center);
        const Real r = Real(sphere.radius);
        const Real scale = baseScale + length(c - eye) + r;
        const Real lightToCenter = length(light - c);
        if (j == ownNode) {
            if (!ownFromInside) {
                continue;  // leaving a convex surface toward a light it faces: never crossed again
            }
            // From the inside surface toward the light: crossed iff the light is outside.
            if (std::fabs(lightToCenter - r) < margins.relative * scale) {
                ambiguous = true;
            } else if (lightToCenter > r) {
                occluded = true;
            }
            continue;
        }
        const V3 f = c - from;
        const Real along = dot(f, u);
        const Real l = length(cross(f, u));
        const bool lightOnSurface = lightToCenter == r;  // exactly: then one crossing is the light itself
        if (l >= r) {
            // The line misses; a near-tangent line matters only if its closest point is on the segment.
            if (l - r < margins.relative * scale && along > -margins.relative * scale &&
                along < segment + margins.relative * scale) {
                ambiguous = true;
            }
            continue;
        }
        const Real half = std::sqrt((r - l) * (r + l));
        Real crossings[2] = {along - half, along + half};
        if (lightOnSurface) {
            // Drop the crossing at the light (the one nearer the segment's end).
            const int atLight = std::fabs(crossings[0] - segment) < std::fabs(crossings[1] - segment) ? 0 : 1;
            crossings[atLight] = -std::numeric_limits<Real>::infinity();
        }
        if (r - l < margins.relative * scale && along > 0 && along < segment) {
            ambiguous = true;  // grazing the occluder
        }
        for (Real s : crossings) {
            if (!std::isfinite(s))
                continue;
            const Real edge = std::min(std::fabs(s), std::fabs(s - segment));
            if (edge < margins.relative * scale) {
                ambiguous = true;
            } else if (s > 0 && s < segment) {
                occluded = true;
            }
        }
    }
    // An unambiguous occluder decides, whatever the ambiguous ones do.
    return occluded ? Occlusion{true, false} : Occlusion{false, ambiguous};
}

inline glm::dvec3 albedoOf(const Shader& shader, bool odd) {
    if (const auto* lambert = std::get_if<LambertShader>(&shader))
        return lambert->color;
    if (const auto* checker = std::get_if<CheckerShader>(&shader))
        return odd ? checker->color2 : checker->color1;
    return std::get<ConstantShader>(shader).color;
}

inline PixelTruth classify(const Scene& scene, const PixelRay& ray, const Margins& margins) {
    PixelTruth truth;
    const V3 eye = toV3(scene.camera.position);

    // --- the visible node
    std::vector<NodeHit> hits;
    for (const Node& node : scene.nodes) {
        hits.push_back(nodeHit(ray, node, margins));
    }
    std::uint32_t nearest = kNoNode;
    for (std::uint32_t i = 0; i < hits.size(); ++i) {
        if (hits[i].hit && (nearest == kNoNode || hits[i].t < hits[nearest].t)) {
            nearest = i;  // strict <: on an exact tie the earlier node wins
        }
    }
    truth.node = nearest;
    const Real nearestT = nearest == kNoNode ? std::numeric_limits<Real>::infinity() : hits[nearest].t;
    for (std::uint32_t i = 0; i < hits.size(); ++i) {
        if (i == nearest) {
            truth.nodeAmbiguous |= hits[i].ambiguous;
            continue;
        }
        // A node whose own hit or miss is uncertain matters only where it could come out in front.
        if (hits[i].ambiguous && hits[i].t <= nearestT) {
            truth.nodeAmbiguous = true;
        }
        // Two hits at nearly the same distance: float32 moves a hit along the ray by ~eps t /
        // |d.n| (the root's sensitivity to the direction grows as the ray grazes the surface).
        if (hits[i].hit && nearest != kNoNode) {
            const Real scaleA = hits[nearest].incidence > 0 ? hits[nearest].t / hits[nearest].incidence
                                                            : std::numeric_limits<Real>::infinity();
            const Real scaleB =
                hits[i].incidence > 0 ? hits[i].t / hits[i].incidence : std::numeric_limits<Real>::infinity();
            if (std::fabs(hits[i].t - nearestT) < margins.relative * (scaleA + scaleB)) {
                truth.nodeAmbiguous = true;
            }
        }
    }
    if (nearest == kNoNode) {
        truth.color = scene.background;
        return truth;
    }

    // --- the surface point
    const Node& node = scene.nodes[nearest];
    const Shader& shader = scene.shaders[node.shaderIndex];
    truth.t = nearestT;
    truth.incidence = hits[nearest].incidence;
    truth.point = ray.origin + ray.direction * nearestT;
    bool fromInside = false;
    if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
        truth.point.y = Real(plane->height);
        truth.facingNormal = V3{0, ray.direction.y < 0 ? Real(1) : Real(-1), 0};
    } else {
        const Sphere& sphere = std::get<Sphere>(node.geometry);
        const V3 outward = (truth.point - toV3(sphere.center)) * (Real(1) / Real(sphere.radius));
        fromInside = dot(outward, ray.direction) > 0;
        truth.facingNormal = fromInside ? -outward : outward;
    }

    // --- checker parity (plane checkers; the hard cases put no checker on a sphere)
    bool odd = false;
    if (const auto* checker = std::get_if<CheckerShader>(&shader)) {
        if (std::holds_alternative<Plane>(node.geometry)) {
            truth.isPlaneChecker = true;
            const Real size = Real(checker->size);
            const Real u = truth.point.x / size;
            const Real v = truth.point.z / size;
            odd = isOddCell(u) != isOddCell(v);
            truth.checkerOdd = odd;
            const Real edge = std::min(std::fabs(u - std::nearbyint(u)), std::fabs(v - std::nearbyint(v))) * size;
            truth.checkerEdgeDistance = edge;
            // float32 puts the hit ~eps t / |d.y| away along the plane (t = h / d.y with d.y
            // good to ~eps); 1e-5 of that is the lead's "relative 1e-5 t of a checker edge",
            // widened where the ray grazes the plane.
            truth.checkerAmbiguous = edge < margins.relative * truth.t / truth.incidence;
        } else {
            truth.checkerAmbiguous = true;  // not modelled here
        }
    }

    // --- lights
    const glm::dvec3 albedo = albedoOf(shader, odd);
    if (std::holds_alternative<ConstantShader>(shader)) {
        truth.color = albedo;
        return truth;
    }
    glm::dvec3 incident = scene.ambient;
    for (const PointLight& light : scene.lights) {
        LightTruth lt;
        const V3 lightPos = toV3(light.position);
        const V3 toLight = lightPos - truth.point;
        lt.distanceSquared = dot(toLight, toLight);
        if (lt.distanceSquared == 0) {
            truth.lights.push_back(lt);  // a light on the point: no direction, no light
            continue;
        }
        lt.cosTheta = dot(truth.facingNormal, toLight) / std::sqrt(lt.distanceSquared);
        bool facing = false;
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            // The plane's normal is exact: the sign is that of the light's height above it.
            const Real above = lightPos.y - Real(plane->height);
            facing = lt.cosTheta > 0 && above != 0;  // in the plane: cos = 0 exactly, unlit
            const Real scale = std::fabs(lightPos.y - eye.y) + std::fabs(Real(plane->height) - eye.y);
            lt.ambiguous = above != 0 && std::fabs(above) < margins.relative * scale;
        } else {
            facing = lt.cosTheta > 0;
            lt.ambiguous = std::fabs(lt.cosTheta) < margins.sphereCos;
        }
        if (facing) {
            const Occlusion occ = segmentOcclusion(scene, nearest, fromInside, truth.point, lightPos, margins);
            lt.lit = !occ.occluded;
            lt.ambiguous = lt.ambiguous || occ.ambiguous;
        }
        if (lt.lit) {
            incident += light.color * double(Real(light.intensity) * lt.cosTheta / lt.distanceSquared);
        }
        truth.lights.push_back(lt);
    }
    truth.color = albedo * incident;
    return truth;
}

struct ImageTruth {
    std::uint32_t width = 0, height = 0;
    std::vector<PixelRay> rays;
    std::vector<PixelTruth> pixels;
};

inline ImageTruth classifyImage(const Scene& scene, const Margins& margins = {}) {
    ImageTruth truth;
    truth.width = scene.image.width;
    truth.height = scene.image.height;
    const RayGrid grid(scene);
    for (std::uint32_t y = 0; y < truth.height; ++y) {
        for (std::uint32_t x = 0; x < truth.width; ++x) {
            truth.rays.push_back(grid.at(x, y));
            truth.pixels.push_back(classify(scene, truth.rays.back(), margins));
        }
    }
    return truth;
}

// ---------------------------------------------------------------- checks

// What a check looked at and what it found. `checked` counts the pixels it asserted about
// (after excluding ambiguous ones), so a caller can require it to be non-empty.
struct CheckCount {
    explicit CheckCount(std::string checkName) : name(std::move(checkName)) {}

    std::string name;
    std::uint64_t checked = 0;
    std::uint64_t excluded = 0;
    std::uint64_t violations = 0;
    std::string firstViolations;  // "(x,y) want .. got ..; " for the first few
    double worst = 0;             // colour checks: the largest channel difference seen

    void violation(std::uint32_t index, std::uint32_t width, const std::string& what) {
        if (violations < 4) {
            firstViolations +=
                "(" + std::to_string(index % width) + "," + std::to_string(index / width) + ") " + what + "; ";
        }
        ++violations;
    }
};

inline std::string nodeName(std::uint32_t node) {
    return node == kNoNode ? std::string("background") : "node " + std::to_string(node);
}

// Every pixel, for checks that look at all of them.
struct Everywhere {
    bool operator()(const PixelTruth&, const PixelRay&) const { return true; }
};

// The visible node (background included) on every pixel in `where` whose node decision is
// unambiguous.
template <typename Where = Everywhere>
CheckCount checkNodes(const ImageTruth& truth, const std::vector<PixelClass>& classes, const std::string& name = "node",
                      Where where = {}) {
    CheckCount c{name};
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        const PixelTruth& p = truth.pixels[i];
        if (!where(p, truth.rays[i]))
            continue;
        if (p.nodeAmbiguous) {
            ++c.excluded;
            continue;
        }
        ++c.checked;
        if (classes[i].node != p.node) {
            c.violation(i, truth.width, "want " + nodeName(p.node) + " got " + nodeName(classes[i].node));
        }
    }
    return c;
}

// A sphere's disc: exactly the pixels whose ray passes inside its silhouette (and nothing in front).
inline CheckCount checkDisc(const ImageTruth& truth, const std::vector<PixelClass>& classes, std::uint32_t node) {
    CheckCount c{"disc(" + std::to_string(node) + ")"};
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        const PixelTruth& p = truth.pixels[i];
        const bool inTruth = p.node == node;
        const bool inRender = classes[i].node == node;
        if (!inTruth && !inRender)
            continue;
        if (p.nodeAmbiguous) {
            ++c.excluded;
            continue;
        }
        if (inTruth)
            ++c.checked;
        if (inTruth != inRender) {
            c.violation(i, truth.width, "want " + nodeName(p.node) + " got " + nodeName(classes[i].node));
        }
    }
    return c;
}

// Checker parity where the render shows the true node and the cell is unambiguous.
inline CheckCount checkCheckerParity(const ImageTruth& truth, const std::vector<PixelClass>& classes) {
    CheckCount c{"checker"};
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        const PixelTruth& p = truth.pixels[i];
        if (!p.isPlaneChecker || p.nodeAmbiguous || classes[i].node != p.node)
            continue;
        if (p.checkerAmbiguous) {
            ++c.excluded;
            continue;
        }
        ++c.checked;
        const bool odd = (classes[i].flags & PixelClass::kOddCheckerBit) != 0;
        if (odd != p.checkerOdd) {
            c.violation(i, truth.width, std::string("want ") + (p.checkerOdd ? "odd" : "even") + " cell");
        }
    }
    return c;
}

// Light `light` reaches the pixel (faces it and is not shadowed), on the pixels in `where`
// where the render shows the true node and the decision is unambiguous.
template <typename Where = Everywhere>
CheckCount checkLitBits(const ImageTruth& truth, const std::vector<PixelClass>& classes, std::uint32_t light,
                        const std::string& name, Where where = {}) {
    CheckCount c{name};
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        const PixelTruth& p = truth.pixels[i];
        if (p.node == kNoNode || p.nodeAmbiguous || classes[i].node != p.node || light >= p.lights.size())
            continue;
        if (!where(p, truth.rays[i]))
            continue;
        if (p.lights[light].ambiguous || p.checkerAmbiguous) {
            ++c.excluded;
            continue;
        }
        ++c.checked;
        const bool lit = (classes[i].flags & PixelClass::litBit(light)) != 0;
        if (lit != p.lights[light].lit) {
            c.violation(i, truth.width,
                        std::string(p.lights[light].lit ? "want lit" : "want dark") + " (cos " +
                            std::to_string(double(p.lights[light].cosTheta)) + ")");
        }
    }
    return c;
}

// Within `tolerance` in every channel (absolute, relative above 1); records the worst difference.
inline bool nearlyEqual(const glm::vec3& got, const glm::dvec3& want, double tolerance, double& worst) {
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
        const double difference = std::fabs(double(got[k]) - want[k]);
        worst = std::isnan(difference) ? difference : std::max(worst, difference);
        if (!(difference <= tolerance * std::max(1.0, std::fabs(want[k]))))
            ok = false;
    }
    return ok;
}

inline std::string colorText(const glm::dvec3& c) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.7g, %.7g, %.7g)", c.x, c.y, c.z);
    return text;
}

// The linear colour against the model's value (albedo * (ambient + sum I cos / r^2)) on the
// pixels in `where` whose every decision is unambiguous and whose node the render got right.
// `tolerance` is absolute, relative above 1.
template <typename Where = Everywhere>
CheckCount checkShading(const ImageTruth& truth, const std::vector<PixelClass>& classes, const Image& image,
                        double tolerance, Where where = {}) {
    CheckCount c{"shading"};
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        const PixelTruth& p = truth.pixels[i];
        if (!where(p, truth.rays[i]))
            continue;
        if (p.anyAmbiguous() || classes[i].node != p.node) {
            ++c.excluded;
            continue;
        }
        ++c.checked;
        if (!nearlyEqual(image.pixels[i], p.color, tolerance, c.worst)) {
            c.violation(i, truth.width,
                        "want " + colorText(p.color) + " got " + colorText(glm::dvec3(image.pixels[i])));
        }
    }
    return c;
}

// Every pixel in `where` has the colour `value` (a known constant of the scene).
template <typename Where>
CheckCount checkUniform(const std::string& name, const Image& image, Where where, const glm::dvec3& value,
                        double tolerance) {
    CheckCount c{name};
    for (std::uint32_t i = 0; i < image.pixels.size(); ++i) {
        if (!where(i))
            continue;
        ++c.checked;
        if (!nearlyEqual(image.pixels[i], value, tolerance, c.worst)) {
            c.violation(i, image.width, "want " + colorText(value) + " got " + colorText(glm::dvec3(image.pixels[i])));
        }
    }
    return c;
}

inline CheckCount checkAllBackground(const std::vector<PixelClass>& classes, std::uint32_t width) {
    CheckCount c{"all-background"};
    for (std::uint32_t i = 0; i < classes.size(); ++i) {
        ++c.checked;
        if (classes[i].node != kNoNode)
            c.violation(i, width, "got " + nodeName(classes[i].node));
    }
    return c;
}

inline CheckCount checkFinite(const Image& image) {
    CheckCount c{"finite"};
    for (std::uint32_t i = 0; i < image.pixels.size(); ++i) {
        ++c.checked;
        const glm::vec3& v = image.pixels[i];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            c.violation(i, image.width, "got " + colorText(glm::dvec3(v)));
        }
    }
    return c;
}

// How many pixels satisfy `where` (for the non-vacuity requirements).
template <typename Where>
std::uint64_t countPixels(const ImageTruth& truth, Where where) {
    std::uint64_t n = 0;
    for (std::uint32_t i = 0; i < truth.pixels.size(); ++i) {
        if (where(truth.pixels[i], truth.rays[i]))
            ++n;
    }
    return n;
}

}  // namespace hexray::analytic
