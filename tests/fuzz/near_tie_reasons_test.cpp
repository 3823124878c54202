// The reasons a scene may be near-tied on many pixels: each is found where it is, and a scene with
// none of them has none.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/near_tie_reasons.h"

namespace hexray {
namespace {

// A floor under a ball, lit from above, the camera off to one side: nothing on a boundary.
Scene clearScene() {
    Scene scene;
    scene.image.width = 32;  // the differential check's size
    scene.image.height = 24;
    scene.camera.position = {0.3, 2.1, -5.2};
    scene.camera.pitchDegrees = -15.0;
    scene.shaderNames = {"matte", "tiles"};
    scene.shaders = {LambertShader{}, CheckerShader{Color(1.0), Color(0.0), 0.7}};
    scene.nodes = {Node{Plane{-1.0}, 1}, Node{Sphere{{0.1, 0.2, 0.3}, 0.9}, 0}};
    scene.lights = {PointLight{{1.0, 6.0, -2.0}, Color(1.0), 30.0}};
    return scene;
}

std::string reasonsOf(const Scene& scene) {
    std::string all;
    for (const std::string& reason : test::nearTieReasons(scene))
        all += reason + "; ";
    return all;
}

TEST(NearTieReasons, NoneInAnOrdinaryScene) {
    EXPECT_EQ(reasonsOf(clearScene()), "");
}

TEST(NearTieReasons, FindEachKind) {
    const auto reasonsWith = [](auto&& change) {
        Scene scene = clearScene();
        change(scene);
        return reasonsOf(scene);
    };
    EXPECT_EQ(reasonsWith([](Scene& s) { s.lights[0].position.y = -1.0; }), "light 0 lies on node 0; ");
    EXPECT_EQ(reasonsWith([](Scene& s) { s.camera.position = {0.1, 1.1, 0.3}; }), "the camera lies on node 1; ");
    EXPECT_EQ(reasonsWith([](Scene& s) { std::get<Sphere>(s.nodes[1].geometry).center.y = -0.1; }),
              "node 1 touches node 0; ");
    EXPECT_EQ(reasonsWith([](Scene& s) { s.nodes.push_back(Node{Plane{-1.0}, 0}); }), "node 0 coincides with node 2; ");
    EXPECT_EQ(reasonsWith([](Scene& s) {
                  s.nodes.push_back(Node{Sphere{{0.1, 0.2, 2.0}, 0.8}, 0});
              }),
              "node 1 touches node 2; node 2 touches node 1; ");
    EXPECT_EQ(reasonsWith([](Scene& s) { std::get<Sphere>(s.nodes[1].geometry).radius = 1e-30; }),
              "node 1 is smaller than the rounding of its position; ");
    EXPECT_EQ(reasonsWith([](Scene& s) {
                  s.shaderNames.push_back("fine");
                  s.shaders.push_back(CheckerShader{Color(1.0), Color(0.0), 0.2});
                  s.nodes[1].shaderIndex = 2;
              }),
              "node 1's checker cells are finer than float atan resolves; ");
    // Cells that far out of scale also put an edge (as good as) below the eye.
    EXPECT_EQ(reasonsWith([](Scene& s) { std::get<CheckerShader>(s.shaders[1]).size = 1e-12; }),
              "node 0's checker cells are out of scale with the points seen on it; "
              "a checker edge of node 0 passes through the eye; ");
    EXPECT_EQ(reasonsWith([](Scene& s) { std::get<CheckerShader>(s.shaders[1]).size = 1e15; }),
              "node 0's checker cells are out of scale with the points seen on it; "
              "a checker edge of node 0 passes through the eye; ");
}

// Boundaries seen edge-on from the eye: a level camera's horizon, a plane's cell edge below the
// eye, a sphere's meridian or equator through it.
TEST(NearTieReasons, EdgesThroughTheEye) {
    Scene level = clearScene();
    level.camera.pitchDegrees = 0.0;
    EXPECT_EQ(reasonsOf(level), "the camera looks level at node 0; ");
    Scene aboveAnEdge = clearScene();
    aboveAnEdge.camera.position.x = 1.4;  // two cells of 0.7
    EXPECT_EQ(reasonsOf(aboveAnEdge), "a checker edge of node 0 passes through the eye; ");
    Scene onTheEquator = clearScene();
    onTheEquator.shaderNames.push_back("halves");
    onTheEquator.shaders.push_back(CheckerShader{Color(1.0), Color(0.0), 180.0});
    onTheEquator.nodes[1] = Node{Sphere{{0.3, 2.1, 5.0}, 0.9}, 2};  // the eye on its equator and the +-180 meridian
    EXPECT_EQ(reasonsOf(onTheEquator), "a checker edge of node 1 passes through the eye; ");
}

// Differential seed 151461335713: an eye 5e43 outside a sphere of radius 1e50 and 3e43 below its
// equator, where the float atan blurs a checker edge over about 1.5e45 (1e-5 rad of the sphere):
// all the eye sees of the sphere lies within that of the equator (half the image near-tied).
Scene nearAHugeSpheresEquator() {
    Scene scene;
    scene.image.width = 32;
    scene.image.height = 24;
    scene.camera.position = {5e43, -3e43, 0.0};
    scene.shaderNames = {"halves"};
    scene.shaders = {CheckerShader{Color(1.0), Color(0.0), 2.2}};
    scene.nodes = {Node{Sphere{{-1e50, 0.0, 0.0}, 1e50}, 0}};
    return scene;
}

// The blur seen from the eye spans a pixel or more: a band of near-tied pixels along the edge. Against
// the CPU reference (hexray compare --precision f64), the scene above with its eye 2e46 below the
// equator is near-tied on 6 % of its pixels (the band is 4 pixels wide), at 8e46 on none.
TEST(NearTieReasons, ASpheresEdgeBlurredOverPixelsByTheFloatAtan) {
    const std::string blurred = "a checker edge of node 0 is blurred over pixels by float atan; ";
    EXPECT_EQ(reasonsOf(nearAHugeSpheresEquator()), blurred);
    Scene offTheEquator = nearAHugeSpheresEquator();
    offTheEquator.camera.position.y = -2e46;
    EXPECT_EQ(reasonsOf(offTheEquator), blurred);
    offTheEquator.camera.position.y = -1e47;
    EXPECT_EQ(reasonsOf(offTheEquator), "");
    Scene farFromTheSphere = nearAHugeSpheresEquator();
    farFromTheSphere.camera.position.x = 1e47;
    EXPECT_EQ(reasonsOf(farFromTheSphere), "");
    // Beside a meridian (here 90.2 degrees, 41 cells of 2.2), far off the equator.
    Scene besideAMeridian = nearAHugeSpheresEquator();
    besideAMeridian.camera.position = {-5.5593e45, -1e48, -3.4905e47};
    EXPECT_EQ(reasonsOf(besideAMeridian), blurred);
}

// A light far from the plane's rounding but close to it against the scene's extent is on it.
TEST(NearTieReasons, ALightNearAPlaneIsOnItAgainstTheScenesExtent) {
    Scene scene = clearScene();
    scene.lights[0].position = {0.0, -1.0 + 1e-6, 0.0};
    EXPECT_EQ(reasonsOf(scene), "");
    std::get<Sphere>(scene.nodes[1].geometry) = Sphere{{0.0, 5.0, 1e9}, 1.0};
    EXPECT_EQ(reasonsOf(scene), "light 0 lies on node 0; ");
}

}  // namespace
}  // namespace hexray
