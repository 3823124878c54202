#include "oracle/hard_rays.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace hexray::oracle {
namespace {

constexpr std::size_t kLambert = 0;
constexpr std::size_t kChecker = 1;

// One light, a Lambert shader and a checker shader of cell `checkerSize`; nodes added by the family.
Scene baseScene(const glm::dvec3& light, double intensity, double checkerSize = 1.0) {
    Scene scene;
    scene.ambient = Color(0.1);
    scene.background = Color(0.0, 0.0, 0.2);
    scene.shaderNames = {"ball", "floor"};
    scene.shaders = {LambertShader{{0.8, 0.3, 0.1}}, CheckerShader{{0.0, 0.0, 0.8}, {0.2, 0.3, 0.6}, checkerSize}};
    scene.lights.push_back(PointLight{light, Color(1.0), intensity});
    return scene;
}

Node sphereNode(const glm::dvec3& center, double radius) {
    return Node{Sphere{center, radius}, kLambert};
}

Node planeNode(double height) {
    return Node{Plane{height}, kChecker};
}

// The lecture's demo scene (scenes/lecture-demo.json), moved by `offset` and scaled by `scale`
// (intensity by its square).
Scene lectureScene(const glm::dvec3& offset, double scale) {
    Scene scene = baseScene(offset + scale * glm::dvec3(30, 100, -70), 1e4 * scale * scale, 20.0 * scale);
    scene.nodes = {planeNode(offset.y), sphereNode(offset + scale * glm::dvec3(-10, 60, 0), 10.0 * scale)};
    return scene;
}

const glm::dvec3 kLectureEye(0, 60, -120);

class Families {
public:
    std::vector<HardRay> rays;

    void add(const std::string& family, const std::string& name, const Scene& scene, const glm::dvec3& origin,
             const glm::dvec3& direction) {
        rays.push_back({family, name, aimedScene(scene, origin, direction)});
    }

    // Unit spheres 1e2 .. 1e6 radii away, rays aimed across and just beyond the disc.
    void tinySpheresFar() {
        for (const double distance : {1e2, 1e3, 1e4, 1e5, 1e6}) {
            Scene scene = baseScene({0.3 * distance, 0.5 * distance, 0.0}, distance * distance);
            scene.nodes = {sphereNode({0, 0, distance}, 1.0)};
            for (const double offset : {0.0, 0.3, 0.7, 0.9, 0.99, 0.999, 1.001, 1.01, 1.1, 1.5, 2.0}) {
                add("tiny sphere far", "D/r " + std::to_string(distance) + " offset " + std::to_string(offset), scene,
                    {0, 0, 0}, {offset * 0.8, offset * 0.6, distance});
            }
        }
    }

    // A sphere of radius R as the ground, the eye h above its top: rays at multiples of the
    // horizon's dip sqrt(2h / R), and two steep ones.
    void hugeSphereGround() {
        for (const double radius : {1e3, 1e6, 1e9}) {
            for (const double height : {1.0, 1e-3}) {
                Scene scene = baseScene({10 * height, 100 * height, 10 * height}, 1e4 * height * height);
                scene.nodes = {sphereNode({0, -radius, 0}, radius)};
                const double dip = std::acos(radius / (radius + height));
                for (const double angle :
                     {0.5 * dip, 0.9 * dip, 0.99 * dip, 1.01 * dip, 1.1 * dip, 2 * dip, 10 * dip, 0.5, 1.5}) {
                    add("huge sphere ground", "R " + std::to_string(radius) + " angle " + std::to_string(angle), scene,
                        {0, height, 0}, {0.0, -std::sin(angle), std::cos(angle)});
                }
            }
        }
    }

    // Lines passing the centre of a unit sphere 10 away at 1 + delta, on four sides.
    void tangentRays() {
        Scene scene = baseScene({5, 8, 0}, 100.0);
        scene.nodes = {sphereNode({0, 0, 10}, 1.0)};
        for (const double side : {0.0, 0.5 * std::numbers::pi, 0.25 * std::numbers::pi, 3.5}) {
            for (const double delta :
                 {0.0, 1e-1, -1e-1, 1e-3, -1e-3, 1e-5, -1e-5, 1e-7, -1e-7, 1e-9, -1e-9, 1e-12, -1e-12}) {
                const double sine = (1.0 + delta) / 10.0;
                const double cosine = std::sqrt(1.0 - sine * sine);
                add("tangent to a sphere", "delta " + std::to_string(delta), scene, {0, 0, 0},
                    {sine * std::cos(side), sine * std::sin(side), cosine});
            }
        }
    }

    // The eye exactly on a sphere of radius 5 (at Pythagorean points, so |eye - centre| = 5
    // exactly), looking in at tilts from straight in down to 1e-4 rad from the tangent plane,
    // and along it. The first two are issue 12's finding 1.
    void originsOnSphere() {
        Scene findings = baseScene({0, 20, -20}, 400.0);
        findings.nodes = {sphereNode({0, 0, 0}, 5.0)};
        add("origin on a sphere", "finding 1: (3.97, -3.04, 0)", findings, {3, 4, 0}, {3.97, -3.04, 0});
        add("origin on a sphere", "finding 1: (4, -3.5, 0)", findings, {3, 4, 0}, {4, -3.5, 0});
        for (const glm::dvec3 center :
             {glm::dvec3(0, 0, 0), glm::dvec3(1000, -2000, 500), glm::dvec3(1e6, 1e6, -1e6)}) {
            Scene scene = baseScene(center + glm::dvec3(0, 20, -20), 400.0);
            scene.nodes = {sphereNode(center, 5.0)};
            for (const glm::dvec3 onSurface :
                 {glm::dvec3(3, 4, 0), glm::dvec3(0, 5, 0), glm::dvec3(0, 0, -5), glm::dvec3(-4, 0, 3)}) {
                const glm::dvec3 normal = onSurface / 5.0;
                const glm::dvec3 tangent = glm::normalize(glm::cross(normal, glm::dvec3(0.6, 0.0, 0.8)));
                for (const double tilt : {0.5 * std::numbers::pi, 0.5, 0.05, 1e-2, 1e-4, 0.0}) {
                    add("origin on a sphere", "tilt " + std::to_string(tilt), scene, center + onSurface,
                        std::cos(tilt) * tangent - std::sin(tilt) * normal);
                }
            }
        }
    }

    // The eye off a sphere of radius 5 by 1e-2 .. 1e-10 of the radius, in and out.
    void originsNearSphere() {
        Scene scene = baseScene({0, 20, -20}, 400.0);
        scene.nodes = {sphereNode({0, 0, 0}, 5.0)};
        for (const glm::dvec3 normal : {glm::dvec3(0.6, 0.8, 0), glm::dvec3(0, 0, -1)}) {
            const glm::dvec3 tangent = glm::normalize(glm::cross(normal, glm::dvec3(0.6, 0.0, 0.8)));
            for (const double off : {1e-2, -1e-2, 1e-4, -1e-4, 1e-7, -1e-7, 1e-10, -1e-10}) {
                for (const double tilt : {1.0, 0.05, -0.5}) {
                    add("origin near a sphere", "off " + std::to_string(off) + " tilt " + std::to_string(tilt), scene,
                        5.0 * (1.0 + off) * normal, std::cos(tilt) * tangent - std::sin(tilt) * normal);
                }
            }
        }
    }

    // The lecture's scene moved 1e3 .. 1e15 away from the origin: the sphere, its rim, lit and
    // shadowed floor, the horizon and the sky.
    void largeOffsets() {
        const glm::dvec3 aims[] = {{-10, 0, 120},  {-0.1, 0, 120},  {-19.9, 0, 120}, {-10, 9.99, 120},
                                   {0, -60, 150},  {-30, -60, 200}, {40, -60, 60},   {-11, -60, 240},
                                   {0, -60, 5000}, {0, 1, 1},       {-60, -60, 80}};
        for (const double offset : {1e3, 1e5, 1e7, 1e10, 1e15}) {
            const glm::dvec3 shift(offset, offset, -offset);
            const Scene scene = lectureScene(shift, 1.0);
            for (const glm::dvec3& aim : aims) {
                add("large offset", "offset " + std::to_string(offset), scene, shift + kLectureEye, aim);
            }
        }
    }

    // Rays falling toward a checkered plane with slopes 1e-1 .. 1e-9, from 1 and 1e-3 above it.
    void grazingPlane() {
        for (const double height : {1.0, 1e-3}) {
            Scene scene = baseScene({2, 5, 3}, 100.0);
            scene.nodes = {planeNode(0.0)};
            for (const double azimuth : {0.0, 0.65, 1.5707}) {
                for (int k = 1; k <= 9; ++k) {
                    const double slope = std::pow(10.0, -k);
                    add("grazing a plane", "slope " + std::to_string(slope), scene, {0.3, height, 0.7},
                        {std::sin(azimuth), -slope, std::cos(azimuth)});
                }
            }
        }
    }

    // The eye exactly on the plane y = 5 and 1e-3 .. 1e-12 above it: down, level and up.
    void originsOnAndNearPlane() {
        Scene scene = baseScene({0, 10, 0}, 100.0, 2.0);
        scene.nodes = {planeNode(5.0)};
        for (const double above : {0.0, 1e-3, 1e-6, 1e-9, 1e-12}) {
            for (const double azimuth : {0.3, 2.0}) {
                for (const double slope : {-1.0, -0.3, -1e-2, -1e-4, 0.0, 0.3}) {
                    add("origin on or near a plane", "above " + std::to_string(above), scene, {1.5, 5.0 + above, -2.5},
                        {std::sin(azimuth), slope, std::cos(azimuth)});
                }
            }
        }
    }

    // Hits on a unit checker 1e2 .. 1e6 away, at fractions of a cell from an edge.
    void checkerEdgesFar() {
        Scene scene = baseScene({0, 10, 0}, 100.0);
        scene.nodes = {planeNode(0.0)};
        const glm::dvec3 eye(0.25, 1.0, 0.25);
        for (const double distance : {1e2, 1e3, 1e4, 1e5, 1e6}) {
            for (const double fraction : {0.5, 0.1, 1e-2, 1e-3, 1e-4, 1e-5, 0.9, 0.99, 0.999, 0.9999, 0.99999}) {
                const glm::dvec3 target(distance + fraction, 0.0, 0.3 * distance + 0.5);
                add("checker edges far", "distance " + std::to_string(distance), scene, eye, target - eye);
            }
        }
    }

    // Floor points of the lecture's scene across both edges of the sphere's shadow, at 1 .. 1e-6
    // radii from the edge (found by bisection on the segment's clearance from the sphere).
    void shadowEdges() {
        const Scene scene = lectureScene(glm::dvec3(0.0), 1.0);
        const glm::dvec3 light = scene.lights[0].position;
        const Sphere& sphere = std::get<Sphere>(scene.nodes[1].geometry);
        const auto clearance = [&](double x, double z) {
            const glm::dvec3 p(x, 0, z);
            const glm::dvec3 w = light - p;
            const double s = std::clamp(glm::dot(sphere.center - p, w) / glm::dot(w, w), 0.0, 1.0);
            return glm::length(p + s * w - sphere.center) - sphere.radius;
        };
        for (const double z : {95.0, 115.0}) {
            // The shadow falls around (-70, 0, 105) (the light through the sphere's centre); its
            // edges lie either side of that along x.
            for (const double outside : {-150.0, 0.0}) {
                double in = -70.0;
                double out = outside;
                for (int i = 0; i < 200; ++i) {
                    const double mid = 0.5 * (in + out);
                    (clearance(mid, z) < 0 ? in : out) = mid;
                }
                const double direction = outside > in ? 1.0 : -1.0;
                for (const double off : {1.0, -1.0, 1e-1, -1e-1, 1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6, 1e-8, -1e-8}) {
                    const glm::dvec3 target(in + direction * off * sphere.radius, 0.0, z);
                    add("shadow edges", "off " + std::to_string(off), scene, kLectureEye, target - kLectureEye);
                }
            }
        }
    }

    // The lecture's scene scaled by 1e30 and 1e-30: a 5 x 5 grid over the view.
    void scaledScenes() {
        for (const double scale : {1e30, 1e-30}) {
            const Scene scene = lectureScene(glm::dvec3(0.0), scale);
            for (const double x : {-0.8, -0.4, 0.0, 0.4, 0.8}) {
                for (const double y : {0.4, 0.0, -0.2, -0.4, -0.6}) {
                    add("scaled by 1e30 and 1e-30", "scale " + std::to_string(scale), scene, scale * kLectureEye,
                        {x, y, 1.0});
                }
            }
        }
    }
};

}  // namespace

Scene aimedScene(Scene scene, const glm::dvec3& origin, const glm::dvec3& direction) {
    const glm::dvec3 d = glm::normalize(direction);
    scene.image = ImageSettings{};
    scene.image.width = 1;
    scene.image.height = 1;
    scene.camera = CameraSettings{};
    scene.camera.position = origin;
    scene.camera.pitchDegrees = glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
    scene.camera.yawDegrees = glm::degrees(std::atan2(-d.x, d.z));
    return scene;
}

std::vector<HardRay> hardRays() {
    Families families;
    families.tinySpheresFar();
    families.hugeSphereGround();
    families.tangentRays();
    families.originsOnSphere();
    families.originsNearSphere();
    families.largeOffsets();
    families.grazingPlane();
    families.originsOnAndNearPlane();
    families.checkerEdgesFar();
    families.shadowEdges();
    families.scaledScenes();
    return std::move(families.rays);
}

}  // namespace hexray::oracle
