#include "fuzz/scene_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace hexray::test {
namespace {

// Draws from std::mt19937_64 with its own mappings (<random>'s distributions are not portable).
class Draw {
public:
    explicit Draw(std::uint64_t seed) : engine_(seed) {}

    double unit() { return double(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
    double uniform(double low, double high) { return low + (high - low) * unit(); }
    bool chance(double probability) { return unit() < probability; }
    std::uint32_t below(std::uint32_t count) { return std::uint32_t(unit() * double(count)); }
    double sign() { return chance(0.5) ? -1.0 : 1.0; }
    double logUniform(double lowExponent, double highExponent) {
        return std::pow(10.0, uniform(lowExponent, highExponent));
    }
    glm::dvec3 unitVector() {
        const double z = uniform(-1.0, 1.0);
        const double angle = uniform(0.0, 2.0 * std::numbers::pi);
        const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {rho * std::cos(angle), rho * std::sin(angle), z};
    }
    // One of the axes' six unit directions: points on a sphere along them are exact.
    glm::dvec3 axis() {
        glm::dvec3 v(0.0);
        v[int(below(3))] = sign();
        return v;
    }
    // How many of something: 0 and 1 often, a few usually, now and then many (`many` at most).
    std::uint32_t count(std::uint32_t few, std::uint32_t many) {
        if (chance(0.15))
            return 0;
        if (chance(0.1))
            return few + 1 + below(many - few);
        return 1 + below(few);
    }

private:
    std::mt19937_64 engine_;
};

// A length held within the supported range: 0 below it, the largest length above it.
double supported(double length) {
    const double magnitude = std::abs(length);
    if (magnitude < kMinSceneLength)
        return 0.0;
    return magnitude > kMaxSceneLength ? std::copysign(kMaxSceneLength, length) : length;
}

glm::dvec3 supported(const glm::dvec3& point) {
    return {supported(point.x), supported(point.y), supported(point.z)};
}

Color colour(Draw& draw) {
    if (draw.chance(0.05))
        return Color(0.0);
    if (draw.chance(0.05))
        return Color(draw.chance(0.5) ? kMaxColorComponent : draw.logUniform(0, 3));
    return {draw.unit(), draw.unit(), draw.unit()};
}

// The scene as it is built: its scale, the point the camera looks at, and whether it places things
// exactly on boundaries (so that the rest, most scenes, are held to compare's ambiguity limit).
struct Builder {
    Draw draw;
    Scene scene;
    double scale = 1.0;
    glm::dvec3 focus{0.0};
    bool onBoundaries = false;

    explicit Builder(std::uint64_t seed) : draw(seed) {}

    // The scene's overall size: mostly ordinary, often anywhere in the range, sometimes at its
    // edges; the focus near the origin or far from it.
    void chooseScale() {
        const double exponent = draw.chance(0.55)  ? draw.uniform(-3, 3)
                                : draw.chance(0.7) ? draw.uniform(-44, 44)
                                                   : draw.sign() * draw.uniform(45, 49);
        scale = std::pow(10.0, exponent);
        if (draw.chance(0.3)) {
            focus = supported(draw.unitVector() * scale * draw.logUniform(0, draw.chance(0.5) ? 6 : 30));
        }
    }

    // A length relative to the scale: mostly within a few times it, sometimes far smaller or larger.
    double relative(double ordinarySpread = 1.0) {
        if (draw.chance(0.1))
            return scale * draw.logUniform(-12, -3);
        if (draw.chance(0.1))
            return scale * draw.logUniform(2, 12);
        return scale * draw.logUniform(-ordinarySpread, ordinarySpread);
    }

    glm::dvec3 pointNearFocus() { return supported(focus + draw.unitVector() * relative(1.0) * draw.uniform(0, 3)); }

    void addShaders() {
        const std::uint32_t count = 1 + draw.below(4);
        for (std::uint32_t i = 0; i < count; ++i) {
            scene.shaderNames.push_back(std::to_string(i).insert(0, 1, 's'));
            switch (draw.below(3)) {
                case 0:
                    scene.shaders.push_back(ConstantShader{colour(draw)});
                    break;
                case 1:
                    scene.shaders.push_back(LambertShader{colour(draw)});
                    break;
                default: {
                    // A sphere's cells are degrees, a plane's lengths: both scales appear.
                    const double size = draw.chance(0.5) ? draw.logUniform(-1, 2.5) : relative(2.0);
                    scene.shaders.push_back(
                        CheckerShader{colour(draw), colour(draw), std::clamp(size, kMinSceneLength, kMaxSceneLength)});
                }
            }
        }
    }

    std::uint32_t anyShader() { return draw.below(std::uint32_t(scene.shaders.size())); }

    Sphere sphere() {
        Sphere sphere{pointNearFocus(), std::max(supported(relative(1.0)), kMinSceneLength)};
        // Near-tangent placements: resting on a plane, touching another sphere.
        const auto planes = nodesOf<Plane>();
        const auto spheres = nodesOf<Sphere>();
        if (onBoundaries && !planes.empty() && draw.chance(0.2)) {
            const Plane& plane = *planes[draw.below(std::uint32_t(planes.size()))];
            sphere.center.y = supported(plane.height + draw.sign() * sphere.radius);
        } else if (onBoundaries && !spheres.empty() && draw.chance(0.15)) {
            const Sphere& other = *spheres[draw.below(std::uint32_t(spheres.size()))];
            sphere.center = supported(other.center + draw.axis() * (other.radius + sphere.radius));
        }
        return sphere;
    }

    Plane plane() {
        if (onBoundaries && draw.chance(0.15))
            return Plane{scene.camera.position.y};  // through the camera
        return Plane{supported(focus.y + draw.sign() * relative(1.0) * draw.uniform(0, 2))};
    }

    template <class Kind>
    std::vector<const Kind*> nodesOf() const {
        std::vector<const Kind*> found;
        for (const Node& node : scene.nodes) {
            if (const auto* kind = std::get_if<Kind>(&node.geometry))
                found.push_back(kind);
        }
        return found;
    }

    void addNodes() {
        const std::uint32_t count = draw.chance(0.03) ? 33 + draw.below(60) : draw.count(6, 36);
        for (std::uint32_t i = 0; i < count; ++i) {
            const Geometry geometry = draw.chance(0.25) ? Geometry(plane()) : Geometry(sphere());
            scene.nodes.push_back(Node{geometry, anyShader()});
        }
    }

    // A light somewhere around, or exactly on a plane or a sphere, inside a sphere, at the eye.
    glm::dvec3 lightPosition() {
        const auto planes = nodesOf<Plane>();
        const auto spheres = nodesOf<Sphere>();
        const double where = draw.unit();
        if (where < 0.1 && onBoundaries && !planes.empty()) {
            glm::dvec3 point = pointNearFocus();
            point.y = planes[draw.below(std::uint32_t(planes.size()))]->height;
            return point;
        }
        if (where < 0.2 && !spheres.empty()) {
            const Sphere& sphere = *spheres[draw.below(std::uint32_t(spheres.size()))];
            const bool onSurface = onBoundaries && draw.chance(0.5);
            return supported(sphere.center + draw.axis() * sphere.radius * (onSurface ? 1.0 : draw.unit()));
        }
        if (where < 0.25)
            return scene.camera.position;
        return supported(focus + draw.unitVector() * relative(1.0) * draw.uniform(0.5, 10));
    }

    void addLights() {
        const std::uint32_t count = draw.chance(0.03) ? 32 + draw.below(8) : draw.count(3, 34);
        for (std::uint32_t i = 0; i < count; ++i) {
            PointLight light;
            light.position = lightPosition();
            light.color = colour(draw);
            // An irradiance at distance 1, so a length squared: lit at the scene's own distances.
            const double intensity = scale * scale * draw.logUniform(-1, 3);
            light.intensity = draw.chance(0.05) ? 0.0 : std::clamp(intensity, kMinIntensity, kMaxIntensity);
            scene.lights.push_back(light);
        }
    }

    // Where the camera is: around the focus looking at it, inside a sphere, on a plane or a
    // sphere; how it turns: toward the focus, straight up or down, or anywhere.
    void placeCamera() {
        CameraSettings& camera = scene.camera;
        camera.position = supported(focus - draw.unitVector() * relative(0.5) * draw.uniform(2, 20));
        const double fov = draw.unit();
        camera.fovDegrees = fov < 0.1   ? draw.logUniform(-2, 0)
                            : fov < 0.2 ? draw.uniform(170, 179.9)
                                        : draw.uniform(30, 120);
        if (draw.chance(0.1))
            camera.aspect = draw.logUniform(-1, 1);
        aimAt(focus);
        const double turn = draw.unit();
        if (turn < 0.15) {
            camera.pitchDegrees = draw.sign() * 90.0;
        } else if (turn < 0.3) {
            camera.yawDegrees = draw.uniform(-360, 360);
            camera.pitchDegrees = draw.uniform(-90, 90);
        }
        if (draw.chance(0.3))
            camera.rollDegrees = draw.uniform(-180, 180);
    }

    void aimAt(const glm::dvec3& target) {
        const glm::dvec3 offset = target - scene.camera.position;
        const double length = glm::length(offset);
        if (!(length > 0.0) || !std::isfinite(length))
            return;
        const glm::dvec3 d = offset / length;
        scene.camera.pitchDegrees = glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
        scene.camera.yawDegrees = glm::degrees(std::atan2(-d.x, d.z));
    }

    // After the nodes exist: the camera moved inside a sphere or onto a plane or a sphere.
    void moveCameraOntoNodes() {
        const auto planes = nodesOf<Plane>();
        const auto spheres = nodesOf<Sphere>();
        const double where = draw.unit();
        if (where < 0.1 && !spheres.empty()) {
            const Sphere& sphere = *spheres[draw.below(std::uint32_t(spheres.size()))];
            scene.camera.position = supported(sphere.center + draw.unitVector() * sphere.radius * draw.uniform(0, 0.9));
        } else if (where < 0.15 && onBoundaries && !spheres.empty()) {
            const Sphere& sphere = *spheres[draw.below(std::uint32_t(spheres.size()))];
            scene.camera.position = supported(sphere.center + draw.axis() * sphere.radius);
        } else if (where < 0.25 && onBoundaries && !planes.empty()) {
            scene.camera.position.y = planes[draw.below(std::uint32_t(planes.size()))]->height;
        }
    }

    void chooseImage() {
        scene.image.width = 32;
        scene.image.height = 24;
        scene.image.sampling = draw.chance(0.3) ? Sampling::Corner : Sampling::Center;
        scene.image.encoding = draw.chance(0.3) ? Encoding::Linear : Encoding::Srgb;
        scene.background = colour(draw);
        scene.ambient = draw.chance(0.3) ? Color(0.0) : colour(draw) * 0.3;
    }
};

}  // namespace

Scene generateScene(std::uint64_t seed) {
    Builder builder(seed);
    builder.onBoundaries = builder.draw.chance(0.4);
    builder.chooseImage();
    builder.chooseScale();
    builder.placeCamera();
    builder.addShaders();
    builder.addNodes();
    builder.moveCameraOntoNodes();
    builder.addLights();
    return builder.scene;
}

Scene generateOutOfRangeScene(std::uint64_t seed) {
    Scene scene = generateScene(seed);
    Draw draw(~seed);
    const double beyond =
        draw.chance(0.5) ? kMaxSceneLength * draw.uniform(1.5, 1e10) : kMinSceneLength / draw.uniform(1.5, 1e10);
    switch (draw.below(4)) {
        case 0:
            scene.camera.position.x = draw.sign() * beyond;
            break;
        case 1:
            if (!scene.lights.empty()) {
                scene.lights[0].intensity = draw.chance(0.5) ? kMaxIntensity * 10.0 : kMinIntensity / 10.0;
                break;
            }
            [[fallthrough]];
        case 2:
            scene.nodes.push_back(Node{Sphere{{0.0, 0.0, 0.0}, beyond}, 0});
            break;
        default:
            scene.nodes.push_back(Node{Plane{draw.sign() * beyond}, 0});
            break;
    }
    return scene;
}

}  // namespace hexray::test
