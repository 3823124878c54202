#include "fuzz/near_tie_reasons.h"
#include "unit_roundoff.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace hexray::test {
namespace {

// Two lengths closer than this, relative to the magnitudes they come from, count as equal: f64's
// decision bounds are 2 (direction roundoff + 16) units of 2^-53, and a field of view near 180
// degrees (direction roundoff in the hundreds) and rays grazing at a hundredth take them to about
// 2^-30; far above the rounding of a placement computed to lie on a boundary.
constexpr double kCoincidence = 0x1p-30;
// A plane's checker cells finer than this share of the scale of its visible points (their
// coordinates, the plane's distance from the eye): toward the horizon a hit's coordinates carry
// roundoff of that scale over the squared grazing cosine, and at 32 x 24 pixels the rows next to
// the horizon graze at a few hundredths. Or coarser than this many times the plane's distance:
// every point the eye sees near the plane lies within rounding of the cell edges that pass below
// the eye (the shader's cell coordinates carry the roundoff of the cell size).
constexpr double kFinestPlaneCell = 0x1p-30;
constexpr double kCoarsestPlaneCell = 0x1p40;
// A sphere's checker edges come from the driver's float atan (decisionBounds: 128 float32 units,
// whatever the precision), of a normal that carries roundoff of (distance from the eye + radius) /
// radius: cells narrower than this many such bounds leave a few per cent of the pixels near an edge.
constexpr double kAtanBoundRadians = 128.0 * FLOAT32_UNIT_ROUNDOFF;
constexpr double kSphereCellBounds = 1000.0;
// Or a field of view so narrow that a pixel spans fewer than this many such bounds: an edge in
// view, or a pole where every meridian meets, is then near-tied over many pixels.
constexpr double kSpherePixelBounds = 100.0;

double magnitude(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

bool coincide(double a, double b, double scale) {
    return std::abs(a - b) <= kCoincidence * scale;
}

// A point on a surface, up to the rounding of the coordinates and distances involved. `reach`: how
// far the point's rays run (a light's to any point the camera sees), against which its distance
// from the surface is a grazing angle.
bool onSphere(const glm::dvec3& point, const Sphere& sphere, double reach) {
    const double distance = glm::length(point - sphere.center);
    return coincide(distance, sphere.radius,
                    distance + sphere.radius + magnitude(point) + magnitude(sphere.center) + reach);
}

bool onPlane(const glm::dvec3& point, const Plane& plane, double reach) {
    return coincide(point.y, plane.height, std::abs(point.y) + std::abs(plane.height) + reach);
}

// How far x lies from the nearest multiple of `size`, in x's units.
double offMultiple(double x, double size) {
    return std::abs(x - size * std::nearbyint(x / size));
}

std::string name(const char* what, std::size_t index) {
    return std::string(what) + " " + std::to_string(index);
}

class Reasons {
public:
    explicit Reasons(const Scene& scene) : scene_(scene), extent_(extentOf(scene)) {}

    std::vector<std::string> all() {
        pointsOnSurfaces();
        touchingSurfaces();
        coincidentPlanes();
        finerThanResolution();
        edgesThroughTheEye();
        return reasons_;
    }

private:
    // The camera or a light on a surface: the camera's rays or the light's cosines graze it.
    void pointsOnSurfaces() {
        onSurfaces(scene_.camera.position, "the camera");
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
            onSurfaces(scene_.lights[i].position, name("light", i));
        }
    }

    void onSurfaces(const glm::dvec3& point, const std::string& what) {
        for (std::size_t n = 0; n < scene_.nodes.size(); ++n) {
            const Geometry& g = scene_.nodes[n].geometry;
            const double reach = glm::length(point - scene_.camera.position) + extent_;
            const bool on = std::holds_alternative<Plane>(g) ? onPlane(point, std::get<Plane>(g), reach)
                                                             : onSphere(point, std::get<Sphere>(g), reach);
            if (on)
                add(what + " lies on node " + std::to_string(n));
        }
    }

    // A sphere tangent to a plane or to another sphere (inside or out): the hits of the two
    // surfaces tie along the contact.
    void touchingSurfaces() {
        for (std::size_t a = 0; a < scene_.nodes.size(); ++a) {
            const auto* sphere = std::get_if<Sphere>(&scene_.nodes[a].geometry);
            if (!sphere)
                continue;
            for (std::size_t b = 0; b < scene_.nodes.size(); ++b) {
                if (b != a && touches(*sphere, scene_.nodes[b].geometry)) {
                    add("node " + std::to_string(a) + " touches node " + std::to_string(b));
                }
            }
        }
    }

    // Two planes at one height, against their distance from the eye: their hits tie everywhere. (Two
    // equal spheres touch, see below.)
    void coincidentPlanes() {
        for (std::size_t a = 0; a < scene_.nodes.size(); ++a) {
            for (std::size_t b = a + 1; b < scene_.nodes.size(); ++b) {
                const auto* first = std::get_if<Plane>(&scene_.nodes[a].geometry);
                const auto* second = std::get_if<Plane>(&scene_.nodes[b].geometry);
                const double reach = first ? std::abs(first->height - scene_.camera.position.y) : 0.0;
                if (first && second && onPlane(glm::dvec3(0.0, first->height, 0.0), *second, reach)) {
                    add("node " + std::to_string(a) + " coincides with node " + std::to_string(b));
                }
            }
        }
    }

    static bool touches(const Sphere& sphere, const Geometry& other) {
        if (const auto* plane = std::get_if<Plane>(&other)) {
            const double gap = std::abs(sphere.center.y - plane->height);
            return coincide(gap, sphere.radius, gap + sphere.radius + std::abs(plane->height));
        }
        const Sphere& s = std::get<Sphere>(other);
        const double distance = glm::length(sphere.center - s.center);
        const double scale = distance + sphere.radius + s.radius + magnitude(sphere.center) + magnitude(s.center);
        return coincide(distance, sphere.radius + s.radius, scale) ||
               coincide(distance, std::abs(sphere.radius - s.radius), scale);
    }

    // A sphere smaller than the rounding of its own position, checker cells on a sphere finer than
    // the float atan resolves, or on a plane out of scale with the points the eye sees on it.
    void finerThanResolution() {
        for (std::size_t n = 0; n < scene_.nodes.size(); ++n) {
            const Node& node = scene_.nodes[n];
            const auto* sphere = std::get_if<Sphere>(&node.geometry);
            if (!sphere) {
                planeCellsOutOfScale(n);
                continue;
            }
            const double position = std::max(magnitude(sphere->center), magnitude(scene_.camera.position));
            if (sphere->radius <= kCoincidence * position) {
                add("node " + std::to_string(n) + " is smaller than the rounding of its position");
            }
            const auto* checker = std::get_if<CheckerShader>(&scene_.shaders[node.shaderIndex]);
            if (checker && sphereCellsUnresolved(*sphere, checker->size)) {
                add("node " + std::to_string(n) + "'s checker cells are finer than float atan resolves");
            }
        }
    }

    // How far apart (in radians of the sphere) two normals may be that the float atan cannot tell
    // apart, at a point seen head-on: the bound on its own, scaled by the normal's roundoff.
    double atanResolution(const Sphere& sphere) const {
        return kAtanBoundRadians * (glm::length(sphere.center - scene_.camera.position) + sphere.radius) /
               sphere.radius;
    }

    bool sphereCellsUnresolved(const Sphere& sphere, double cellDegrees) const {
        const double bound = glm::degrees(atanResolution(sphere));
        return cellDegrees < kSphereCellBounds * bound || pixelDegrees() < kSpherePixelBounds * bound;
    }

    double pixelDegrees() const {
        return scene_.camera.fovDegrees / std::hypot(double(scene_.image.width), double(scene_.image.height));
    }

    // A boundary surface through the eye is seen edge-on, along a whole line of pixels: a level
    // camera's horizon (on the image's middle line, where a row of samples may lie) over a plane; a
    // plane's cell edge below the eye; a sphere's meridian or latitude cone through the eye.
    void edgesThroughTheEye() {
        const CameraSettings& camera = scene_.camera;
        const bool level = camera.pitchDegrees == 0.0 && std::fmod(camera.rollDegrees, 180.0) == 0.0;
        for (std::size_t n = 0; n < scene_.nodes.size(); ++n) {
            const Geometry& geometry = scene_.nodes[n].geometry;
            if (level && std::holds_alternative<Plane>(geometry)) {
                add("the camera looks level at node " + std::to_string(n));
            }
            const auto* checker = std::get_if<CheckerShader>(&scene_.shaders[scene_.nodes[n].shaderIndex]);
            if (!checker)
                continue;
            const auto* sphere = std::get_if<Sphere>(&geometry);
            const bool edgeThroughEye = sphere ? eyeOffSphereEdge(*sphere, checker->size) <= kCoincidence
                                               : planeEdgeBelowEye(std::get<Plane>(geometry), checker->size);
            if (edgeThroughEye) {
                add("a checker edge of node " + std::to_string(n) + " passes through the eye");
            } else if (sphere && sphereEdgeBlurredOverPixels(*sphere, checker->size)) {
                add("a checker edge of node " + std::to_string(n) + " is blurred over pixels by float atan");
            }
        }
    }

    // A sphere's checker edge blurred by the float atan over a band (atanResolution wide on the
    // surface; wider where rays graze it, which foreshortening undoes) that spans a pixel or more as
    // seen from the eye's distance to the edge: a huge sphere seen from close by. (At 32 x 24 a band
    // two pixels wide leaves about 4 % of them near-tied, four pixels 6 to 8 %.)
    bool sphereEdgeBlurredOverPixels(const Sphere& sphere, double size) const {
        const double blur = atanResolution(sphere) * sphere.radius;
        const double eyeDistance = glm::length(scene_.camera.position - sphere.center);
        const double toEdge = std::hypot(eyeDistance - sphere.radius, eyeDistance * eyeOffSphereEdge(sphere, size));
        return 2.0 * blur >= toEdge * glm::radians(pixelDegrees());
    }

    bool planeEdgeBelowEye(const Plane& plane, double size) const {
        const glm::dvec3& eye = scene_.camera.position;
        const double scale = std::abs(plane.height - eye.y) + size;
        return offMultiple(eye.x, size) <= kCoincidence * (std::abs(eye.x) + scale) ||
               offMultiple(eye.z, size) <= kCoincidence * (std::abs(eye.z) + scale);
    }

    // How far the eye's direction from the sphere's centre lies from the nearest checker edge, in
    // radians: angles in the sphere's frame, as the renderers' (longitude, latitude) of a normal.
    double eyeOffSphereEdge(const Sphere& sphere, double size) const {
        const glm::dvec3 v = scene_.camera.position - sphere.center;
        const double length = glm::length(v);
        const double axisDistance = std::hypot(v.x, v.z) / length;  // 0 on the polar axis
        const double cells = std::min(size, 360.0);
        const double longitude = glm::degrees(std::atan2(v.x, v.z));
        const double offMeridian = std::min(offMultiple(longitude, cells), 180.0 - std::abs(longitude));
        const double latitude = glm::degrees(std::asin(std::clamp(v.y / length, -1.0, 1.0)));
        return std::min(glm::radians(offMeridian) * axisDistance, glm::radians(offMultiple(latitude, cells)));
    }

    void planeCellsOutOfScale(std::size_t n) {
        const auto* checker = std::get_if<CheckerShader>(&scene_.shaders[scene_.nodes[n].shaderIndex]);
        if (!checker)
            return;
        const glm::dvec3& eye = scene_.camera.position;
        const double distance = std::abs(std::get<Plane>(scene_.nodes[n].geometry).height - eye.y);
        if (checker->size < kFinestPlaneCell * (magnitude(eye) + distance) ||
            checker->size > kCoarsestPlaneCell * distance) {
            add("node " + std::to_string(n) + "'s checker cells are out of scale with the points seen on it");
        }
    }

    void add(std::string reason) { reasons_.push_back(std::move(reason)); }

    // How far from the eye the scene's surfaces and lights reach.
    static double extentOf(const Scene& scene) {
        const glm::dvec3& eye = scene.camera.position;
        double extent = 0.0;
        for (const Node& node : scene.nodes) {
            const auto* sphere = std::get_if<Sphere>(&node.geometry);
            extent = std::max(extent, sphere ? glm::length(sphere->center - eye) + sphere->radius
                                             : std::abs(std::get<Plane>(node.geometry).height - eye.y));
        }
        for (const PointLight& light : scene.lights) {
            extent = std::max(extent, glm::length(light.position - eye));
        }
        return extent;
    }

    const Scene& scene_;
    double extent_;
    std::vector<std::string> reasons_;
};

}  // namespace

std::vector<std::string> nearTieReasons(const Scene& scene) {
    return Reasons(scene).all();
}

}  // namespace hexray::test
