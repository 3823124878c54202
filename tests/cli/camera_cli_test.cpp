// The look-at camera through the real executable: the same image as the angles it stands for,
// on both backends; mixed or degenerate cameras refused with the place named.

#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "camera/camera.h"
#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;

std::string vec(const glm::dvec3& v) {
    char text[128];
    std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
    return text;
}

// spheres-and-lights.json's scene with `camera` as its camera.
std::string sceneWithCamera(const std::string& camera) {
    return R"({
  "image": {"width": 120, "height": 68, "spp": 2},
  "camera": )" +
           camera + R"(,
  "background": "#10141c",
  "ambient": [0.05, 0.05, 0.06],
  "lights": [{"position": [-40, 90, -60], "color": [1, 0.85, 0.7], "intensity": 9000},
             {"position": [60, 30, -20], "color": [0.4, 0.6, 1], "intensity": 2500}],
  "shaders": {"floor": {"type": "checker", "color1": [0.8, 0.8, 0.8], "color2": [0.2, 0.2, 0.25], "size": 15},
              "red": {"type": "lambert", "color": [0.8, 0.1, 0.1]},
              "teal": {"type": "lambert", "color": [0.1, 0.6, 0.55]}},
  "nodes": [{"geometry": {"type": "plane", "y": 0}, "shader": "floor"},
            {"geometry": {"type": "sphere", "center": [-20, 15, 0], "radius": 15}, "shader": "red"},
            {"geometry": {"type": "sphere", "center": [18, 10, -12], "radius": 10}, "shader": "teal"}]
})";
}

class CameraCliTest : public CliTest {
protected:
    // Renders the scene with the angles and with the look-at camera made from them (its target
    // 150 units along the view, its up the camera's own), on `backend`.
    void expectSameImage(double yaw, double pitch, double roll, const std::string& backend) {
        CameraSettings angles;
        angles.position = {-70, 45, -110};
        angles.yawDegrees = yaw;
        angles.pitchDegrees = pitch;
        angles.rollDegrees = roll;
        const glm::dvec3 target = angles.position + 150.0 * cameraForward(angles);
        const glm::dvec3 up = cameraRotation(angles) * glm::dvec3(0, 1, 0);
        char anglesText[160];
        std::snprintf(anglesText, sizeof anglesText,
                      R"({"position": [-70, 45, -110], "yaw": %g, "pitch": %g, "roll": %g})", yaw, pitch, roll);
        writeScene("angles.json", sceneWithCamera(anglesText));
        writeScene("look-at.json", sceneWithCamera(R"({"position": [-70, 45, -110], "lookAt": )" + vec(target) +
                                                   R"(, "up": )" + vec(up) + "}"));
        for (const char* name : {"angles", "look-at"}) {
            const RunResult run = hexray("render " + std::string(name) + ".json --backend " + backend);
            ASSERT_EQ(run.exitCode, 0) << run.err;
        }
        EXPECT_EQ(readPng(dir_ / "look-at.png").bytes, readPng(dir_ / "angles.png").bytes)
            << backend << " yaw " << yaw << " pitch " << pitch << " roll " << roll;
    }
};

TEST_F(CameraCliTest, ALookAtCameraGivesTheImageOfItsAnglesOnTheGpu) {
    expectSameImage(-28, -12, 4, "gpu");
    expectSameImage(135, 30, -60, "gpu");
}

TEST_F(CameraCliTest, ALookAtCameraGivesTheImageOfItsAnglesOnTheCpu) {
    expectSameImage(-28, -12, 4, "cpu");
    expectSameImage(135, 30, -60, "cpu");
}

TEST_F(CameraCliTest, TheDefaultUpIsPlusYWithoutRoll) {
    writeScene("angles.json", sceneWithCamera(R"({"position": [0, 30, -100], "yaw": 0, "pitch": 0})"));
    writeScene("look-at.json", sceneWithCamera(R"({"position": [0, 30, -100], "lookAt": [0, 30, 0]})"));
    for (const char* name : {"angles", "look-at"}) {
        ASSERT_EQ(hexray("render " + std::string(name) + ".json --backend cpu").exitCode, 0);
    }
    EXPECT_EQ(readPng(dir_ / "look-at.png").bytes, readPng(dir_ / "angles.png").bytes);
}

TEST_F(CameraCliTest, MixedOrDegenerateLookAtCamerasAreRefusedNamingThePlace) {
    const struct {
        const char* camera;
        const char* message;
    } cases[] = {
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 5], "yaw": 10})",
         "camera.yaw: cannot be used with camera.lookAt (a look-at camera's direction comes from lookAt and up)"},
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 5], "roll": 0})",
         "camera.roll: cannot be used with camera.lookAt"},
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 0]})",
         "camera.lookAt: must differ from camera.position (the camera would look nowhere)"},
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 5], "up": [0, 0, -2]})",
         "camera.up: must not be parallel to the view direction lookAt - position"},
        {R"({"position": [0, 1, 0], "lookAt": [0, -5, 0]})",
         "camera.lookAt: the camera looks straight up or down, along the default up [0, 1, 0]: give camera.up"},
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 5], "up": [0, 0, 0]})", "camera.up: must not be zero"},
        {R"({"position": [0, 1, 0], "up": [0, 1, 0]})", "camera.up: only with camera.lookAt"},
        {R"({"position": [0, 1, 0], "lookAt": [0, 1, 1e60]})", "camera.lookAt[2]: must be 0 or between 1e-50 and"},
    };
    for (const auto& [camera, message] : cases) {
        writeScene("bad.json", sceneWithCamera(camera));
        const RunResult run = hexray("render bad.json");
        EXPECT_EQ(run.exitCode, 2) << camera;
        EXPECT_NE(run.err.find(std::string("bad.json: ") + message), std::string::npos) << camera << "\n" << run.err;
        EXPECT_EQ(createdFiles(), std::vector<std::string>{}) << camera;
    }
}

}  // namespace
}  // namespace hexray
