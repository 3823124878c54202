// The course's pinhole camera: rotation conventions, the sheet's corners, the diagonal FOV.
// Expected values are worked out by hand from the course's definitions.

#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "scene/scene.h"

using namespace hexray;

namespace {

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
    const double cosine = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(cosine) * 180.0 / std::numbers::pi;
}

CameraSettings cameraWith(double yaw, double pitch, double roll) {
    CameraSettings camera;
    camera.yawDegrees = yaw;
    camera.pitchDegrees = pitch;
    camera.rollDegrees = roll;
    return camera;
}

}  // namespace

TEST(Camera, ForwardForTheCourseCheckAngles) {
    // The course notes' check: yaw 30, pitch 20, roll 10.
    expectNear(cameraForward(cameraWith(30, 20, 10)), {-0.4698, 0.3420, 0.8138}, 1e-4);
}

TEST(Camera, ForwardMatchesClosedForm) {
    // (-sin yaw cos pitch, sin pitch, cos yaw cos pitch); roll does not move the forward axis.
    const double yaw = 30.0 * std::numbers::pi / 180.0;
    const double pitch = 20.0 * std::numbers::pi / 180.0;
    const glm::dvec3 expected(-std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    expectNear(cameraForward(cameraWith(30, 20, 10)), expected, 1e-12);
    expectNear(cameraForward(cameraWith(30, 20, -75)), expected, 1e-12);
}

TEST(Camera, DefaultLooksAlongPlusZ) {
    expectNear(cameraForward(CameraSettings{}), {0, 0, 1}, 0.0);
}

TEST(Camera, PositiveYawLooksTowardMinusX) {
    expectNear(cameraForward(cameraWith(90, 0, 0)), {-1, 0, 0}, 1e-12);
    EXPECT_LT(cameraForward(cameraWith(10, 0, 0)).x, 0.0);
}

TEST(Camera, PositivePitchLooksUp) {
    expectNear(cameraForward(cameraWith(0, 90, 0)), {0, 1, 0}, 1e-12);
    EXPECT_GT(cameraForward(cameraWith(0, 10, 0)).y, 0.0);
}

TEST(Camera, PositiveRollTipsUpTowardPlusX) {
    const glm::dvec3 up90 = cameraRotation(cameraWith(0, 0, 90)) * glm::dvec3(0, 1, 0);
    expectNear(up90, {1, 0, 0}, 1e-12);
    const glm::dvec3 up10 = cameraRotation(cameraWith(0, 0, 10)) * glm::dvec3(0, 1, 0);
    const double s = std::sin(10.0 * std::numbers::pi / 180.0);
    const double c = std::cos(10.0 * std::numbers::pi / 180.0);
    expectNear(up10, {s, c, 0}, 1e-12);
}

TEST(Camera, RollThenPitchThenYaw) {
    // Roll 90 then yaw 90: up (+Y) first tips to +X, then yaw 90 (which turns +Z to -X)
    // turns +X to +Z. Yaw first would leave up at +Y and roll would then give +X.
    const glm::dvec3 up = cameraRotation(cameraWith(90, 0, 90)) * glm::dvec3(0, 1, 0);
    expectNear(up, {0, 0, 1}, 1e-12);
    // Pitch 90 then yaw 90: forward goes up to +Y, and yaw about Y leaves it there.
    expectNear(cameraForward(cameraWith(90, 90, 0)), {0, 1, 0}, 1e-12);
    // Pitch 45 then yaw 90: forward (0, s, c) turns to (-c, s, 0); yaw first would give (-1, 0, 0).
    const double h = std::sqrt(0.5);
    expectNear(cameraForward(cameraWith(90, 45, 0)), {-h, h, 0}, 1e-12);
}

TEST(Camera, DefaultSheetCornersFov90Aspect4to3) {
    // m = tan(45 deg) / sqrt((4/3)^2 + 1) = 1 / (5/3) = 0.6.
    CameraSettings camera;
    camera.position = {1, 2, 3};
    const PixelSheet sheet = makePixelSheet(camera, 4.0 / 3.0);
    expectNear(sheet.origin, {1, 2, 3}, 0.0);
    expectNear(sheet.topLeft, {-0.8, 0.6, 1}, 1e-12);
    expectNear(sheet.right, {1.6, 0, 0}, 1e-12);
    expectNear(sheet.down, {0, -1.2, 0}, 1e-12);
}

TEST(Camera, DiagonalAngleEqualsFov) {
    struct Case {
        double fov, aspect, yaw, pitch, roll;
    };
    for (const Case& c : {Case{90, 4.0 / 3.0, 0, 0, 0}, Case{60, 16.0 / 9.0, 0, 0, 0}, Case{120, 1.0, 0, 0, 0},
                          Case{30, 0.5, 0, 0, 0}, Case{75, 2.0, 30, 20, 10}}) {
        CameraSettings camera = cameraWith(c.yaw, c.pitch, c.roll);
        camera.fovDegrees = c.fov;
        const PixelSheet sheet = makePixelSheet(camera, c.aspect);
        const glm::dvec3 bottomRight = sheet.topLeft + sheet.right + sheet.down;
        EXPECT_NEAR(degreesBetween(sheet.topLeft, bottomRight), c.fov, 1e-9) << "fov " << c.fov;
        // The other diagonal too.
        const glm::dvec3 topRight = sheet.topLeft + sheet.right;
        const glm::dvec3 bottomLeft = sheet.topLeft + sheet.down;
        EXPECT_NEAR(degreesBetween(topRight, bottomLeft), c.fov, 1e-9) << "fov " << c.fov;
        // The sheet's sides keep the aspect ratio.
        EXPECT_NEAR(glm::length(sheet.right) / glm::length(sheet.down), c.aspect, 1e-12);
    }
}

TEST(Camera, SheetIsCentredOnForward) {
    const CameraSettings camera = cameraWith(30, 20, 10);
    const PixelSheet sheet = makePixelSheet(camera, 4.0 / 3.0);
    const glm::dvec3 centre = sheet.topLeft + 0.5 * sheet.right + 0.5 * sheet.down;
    expectNear(centre, cameraForward(camera), 1e-12);  // at distance 1 along forward
}

TEST(Camera, SheetAspectPrefersTheCamerasOwn) {
    Scene scene;
    scene.image.width = 800;
    scene.image.height = 400;
    EXPECT_DOUBLE_EQ(sheetAspect(scene), 2.0);
    scene.camera.aspect = 4.0 / 3.0;
    EXPECT_DOUBLE_EQ(sheetAspect(scene), 4.0 / 3.0);
}

TEST(Camera, SamplingOffsets) {
    EXPECT_EQ(samplingOffset(Sampling::Center), 0.5);
    EXPECT_EQ(samplingOffset(Sampling::Corner), 0.0);
}

TEST(SampleOffset, OneSampleIsTheCentreOrTheCorner) {
    EXPECT_EQ(sampleOffset(0, 1, Sampling::Center), glm::dvec2(0.5, 0.5));
    EXPECT_EQ(sampleOffset(0, 1, Sampling::Corner), glm::dvec2(0.0, 0.0));
}

TEST(SampleOffset, FourSamplesAreStratifiedInRowsAndColumns) {
    // u = (i + 0.5) / 4; v = radical inverse of i (0, 1/2, 1/4, 3/4) + 1/8.
    const glm::dvec2 expected[] = {{0.125, 0.125}, {0.375, 0.625}, {0.625, 0.375}, {0.875, 0.875}};
    for (std::uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(sampleOffset(i, 4, Sampling::Center), expected[i]) << i;
        EXPECT_EQ(sampleOffset(i, 4, Sampling::Corner), expected[i] - 0.5) << i;
    }
}

TEST(SampleOffset, ManySamplesCoverThePixelEvenly) {
    // Every one of the 16 x 16 cells of the pixel holds exactly one of 256 samples.
    std::set<std::pair<int, int>> cells;
    for (std::uint32_t i = 0; i < 256; ++i) {
        const glm::dvec2 offset = sampleOffset(i, 256, Sampling::Center);
        ASSERT_GE(offset.x, 0.0);
        ASSERT_LT(offset.x, 1.0);
        ASSERT_GE(offset.y, 0.0);
        ASSERT_LT(offset.y, 1.0);
        cells.insert({int(offset.x * 16), int(offset.y * 16)});
    }
    EXPECT_EQ(cells.size(), 256u);
}

TEST(Camera, LookAtGivesBackTheAnglesOfTheCameraItPointsAs) {
    for (const glm::dvec3 angles : {glm::dvec3(30, 20, 10), glm::dvec3(-28, -12, 4), glm::dvec3(135, 30, -60),
                                    glm::dvec3(-170, -80, 179), glm::dvec3(0, 0, 0)}) {
        CameraSettings camera = cameraWith(angles.x, angles.y, angles.z);
        camera.position = {3, -4, 5};
        const glm::dvec3 target = camera.position + 7.0 * cameraForward(camera);
        const glm::dvec3 up = cameraRotation(camera) * glm::dvec3(0, 1, 0);
        const CameraAngles found = lookAtAngles(camera.position, target, up);
        EXPECT_NEAR(found.yawDegrees, angles.x, 1e-12);
        EXPECT_NEAR(found.pitchDegrees, angles.y, 1e-12);
        EXPECT_NEAR(found.rollDegrees, angles.z, 1e-12);
    }
}

TEST(Camera, LookAtTakesOnlyThePartOfUpAcrossTheView) {
    // Looking along +Z: an up leaning toward the view or away from it is still plain +Y, and an
    // up tipped 45 degrees toward +X is a roll of 45 degrees.
    const glm::dvec3 eye(0, 0, 0);
    const glm::dvec3 target(0, 0, 10);
    EXPECT_NEAR(lookAtAngles(eye, target, glm::normalize(glm::dvec3(0, 1, 5))).rollDegrees, 0, 1e-12);
    EXPECT_NEAR(lookAtAngles(eye, target, glm::normalize(glm::dvec3(0, 1, -5))).rollDegrees, 0, 1e-12);
    EXPECT_NEAR(lookAtAngles(eye, target, glm::normalize(glm::dvec3(1, 1, 0))).rollDegrees, 45, 1e-12);
    EXPECT_NEAR(lookAtAngles(eye, target, glm::dvec3(0, -1, 0)).rollDegrees, 180, 1e-12);
}
