// The scene loader: what a valid file becomes, and the one message each kind of bad input gets.
// Messages are compared whole where the format promises their shape, since the CLI shows them as is.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/scene.h"
#include "scene/scene_loader.h"

using namespace hexray;
namespace fs = std::filesystem;

namespace {

fs::path sourceDir() {
#ifdef HEXRAY_SOURCE_DIR
    return HEXRAY_SOURCE_DIR;
#else
    // Standalone builds: the repository root is two folders above this file's folder.
    return fs::path(__FILE__).parent_path().parent_path().parent_path();
#endif
}

// The example from the format's description, verbatim.
const std::string kExampleScene = R"({
  "image":   {"width": 800, "height": 600, "sampling": "center", "encoding": "srgb"},
  "camera":  {"position": [0, 60, -120], "yaw": 0, "pitch": 0, "roll": 0, "fov": 90, "aspect": 1.3333},
  "background": [0, 0, 0],
  "ambient": [0.15, 0.15, 0.15],
  "lights":  [{"position": [30, 100, -70], "color": [1, 1, 1], "intensity": 10000}],
  "shaders": {
    "floor": {"type": "checker", "color1": "#0000cc", "color2": [0.2, 0.3, 0.6], "size": 20},
    "ball":  {"type": "lambert", "color": [0.8, 0, 0]},
    "debug": {"type": "constant", "color": "#e699e6"}
  },
  "nodes": [
    {"geometry": {"type": "plane", "y": 0}, "shader": "floor"},
    {"geometry": {"type": "sphere", "center": [-10, 60, 0], "radius": 10}, "shader": "ball"}
  ]
})";

// A small valid scene that each rejection test breaks in exactly one place.
const std::string kValidScene = R"({
  "image": {"width": 8, "height": 6},
  "camera": {"position": [0, 1, -5]},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [{"position": [0, 10, 0], "intensity": 100}],
  "shaders": {"red": {"type": "lambert", "color": [1, 0, 0]}},
  "nodes": [{"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "shader": "red"}]
})";

// kValidScene with one piece of text replaced; fails the test if the piece is not there.
std::string validSceneWith(const std::string& from, const std::string& to) {
    std::string text = kValidScene;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "test setup: \"" << from << "\" is not in the valid scene";
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

// The message parseScene rejects `text` with, or "" (and a failure) if it accepts it.
std::string errorFor(const std::string& text) {
    try {
        parseScene(text, "test.json");
    } catch (const SceneError& error) {
        return error.what();
    }
    ADD_FAILURE() << "the scene was accepted:\n" << text;
    return "";
}

std::string errorForChange(const std::string& from, const std::string& to) {
    return errorFor(validSceneWith(from, to));
}

// A "#rrggbb" component as the loader reads it: sRGB, as in CSS, made linear.
double srgbByte(unsigned byte) {
    const double encoded = byte / 255.0;
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

void expectVec(const glm::dvec3& actual, const glm::dvec3& expected) {
    EXPECT_EQ(actual.x, expected.x);
    EXPECT_EQ(actual.y, expected.y);
    EXPECT_EQ(actual.z, expected.z);
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A scratch folder for tests that need real files, removed afterwards.
class SceneFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::temp_directory_path() /
                  ("hexray_scene_loader_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = folder_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    fs::path folder_;
};

}  // namespace

// ---------------------------------------------------------------- valid scenes

TEST(SceneLoader, ParsesTheExampleScene) {
    const Scene scene = parseScene(kExampleScene, "example.json");

    EXPECT_EQ(scene.image.width, 800u);
    EXPECT_EQ(scene.image.height, 600u);
    EXPECT_EQ(scene.image.sampling, Sampling::Center);
    EXPECT_EQ(scene.image.encoding, Encoding::Srgb);

    expectVec(scene.camera.position, {0, 60, -120});
    EXPECT_EQ(scene.camera.yawDegrees, 0.0);
    EXPECT_EQ(scene.camera.pitchDegrees, 0.0);
    EXPECT_EQ(scene.camera.rollDegrees, 0.0);
    EXPECT_EQ(scene.camera.fovDegrees, 90.0);
    ASSERT_TRUE(scene.camera.aspect.has_value());
    EXPECT_EQ(*scene.camera.aspect, 1.3333);
    EXPECT_EQ(sheetAspect(scene), 1.3333);

    expectVec(scene.background, {0, 0, 0});
    expectVec(scene.ambient, {0.15, 0.15, 0.15});

    ASSERT_EQ(scene.lights.size(), 1u);
    expectVec(scene.lights[0].position, {30, 100, -70});
    expectVec(scene.lights[0].color, {1, 1, 1});
    EXPECT_EQ(scene.lights[0].intensity, 10000.0);

    // Shaders come in name order, with names kept parallel for messages.
    ASSERT_EQ(scene.shaders.size(), 3u);
    ASSERT_EQ(scene.shaderNames, (std::vector<std::string>{"ball", "debug", "floor"}));
    const auto* ball = std::get_if<LambertShader>(&scene.shaders[0]);
    ASSERT_NE(ball, nullptr);
    expectVec(ball->color, {0.8, 0, 0});
    const auto* debug = std::get_if<ConstantShader>(&scene.shaders[1]);
    ASSERT_NE(debug, nullptr);
    expectVec(debug->color, {srgbByte(0xe6), srgbByte(0x99), srgbByte(0xe6)});
    const auto* floor = std::get_if<CheckerShader>(&scene.shaders[2]);
    ASSERT_NE(floor, nullptr);
    expectVec(floor->color1, {0, 0, srgbByte(0xcc)});
    expectVec(floor->color2, {0.2, 0.3, 0.6});
    EXPECT_EQ(floor->size, 20.0);

    ASSERT_EQ(scene.nodes.size(), 2u);
    const auto* plane = std::get_if<Plane>(&scene.nodes[0].geometry);
    ASSERT_NE(plane, nullptr);
    EXPECT_EQ(plane->height, 0.0);
    EXPECT_EQ(scene.nodes[0].shaderIndex, 2u);  // floor
    const auto* sphere = std::get_if<Sphere>(&scene.nodes[1].geometry);
    ASSERT_NE(sphere, nullptr);
    expectVec(sphere->center, {-10, 60, 0});
    EXPECT_EQ(sphere->radius, 10.0);
    EXPECT_EQ(scene.nodes[1].shaderIndex, 0u);  // ball
}

TEST(SceneLoader, OmittedOptionalFieldsTakeTheirDefaults) {
    const Scene scene = parseScene(R"({
        "image": {"width": 640, "height": 480},
        "camera": {"position": [1, 2, 3]},
        "lights": [{"position": [0, 0, 0], "intensity": 5}],
        "nodes": []
    })",
                                   "defaults.json");

    EXPECT_EQ(scene.image.sampling, Sampling::Center);
    EXPECT_EQ(scene.image.encoding, Encoding::Srgb);
    EXPECT_EQ(scene.camera.yawDegrees, 0.0);
    EXPECT_EQ(scene.camera.pitchDegrees, 0.0);
    EXPECT_EQ(scene.camera.rollDegrees, 0.0);
    EXPECT_EQ(scene.camera.fovDegrees, 90.0);
    EXPECT_FALSE(scene.camera.aspect.has_value());
    EXPECT_EQ(sheetAspect(scene), 640.0 / 480.0);  // the image's when the scene gives none
    expectVec(scene.background, {0, 0, 0});
    expectVec(scene.ambient, {0, 0, 0});
    ASSERT_EQ(scene.lights.size(), 1u);
    expectVec(scene.lights[0].color, {1, 1, 1});
    EXPECT_TRUE(scene.shaders.empty());
    EXPECT_TRUE(scene.shaderNames.empty());
    EXPECT_TRUE(scene.nodes.empty());
}

TEST(SceneLoader, OmittedListsAreEmpty) {
    const Scene scene = parseScene(R"({"image": {"width": 1, "height": 1}, "camera": {"position": [0, 0, 0]},
                                       "nodes": []})",
                                   "empty.json");
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(scene.shaders.empty());
    EXPECT_TRUE(scene.nodes.empty());
}

TEST(SceneLoader, ReadsTheCourseSettings) {
    const Scene scene =
        parseScene(validSceneWith(R"("image": {"width": 8, "height": 6})",
                                  R"("image": {"width": 8, "height": 6, "sampling": "corner", "encoding": "linear"})"),
                   "course.json");
    EXPECT_EQ(scene.image.sampling, Sampling::Corner);
    EXPECT_EQ(scene.image.encoding, Encoding::Linear);
}

TEST(SceneLoader, ReadsCameraAngles) {
    const Scene scene = parseScene(
        validSceneWith(R"("camera": {"position": [0, 1, -5]})",
                       R"("camera": {"position": [0, 1, -5], "yaw": 30, "pitch": -20.5, "roll": 370, "fov": 179.5})"),
        "angles.json");
    EXPECT_EQ(scene.camera.yawDegrees, 30.0);
    EXPECT_EQ(scene.camera.pitchDegrees, -20.5);
    EXPECT_EQ(scene.camera.rollDegrees, 370.0);
    EXPECT_EQ(scene.camera.fovDegrees, 179.5);
}

TEST(SceneLoader, HexColoursAreCaseInsensitiveAndHdrComponentsAreKept) {
    const Scene scene = parseScene(
        validSceneWith(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": "#FfA00b", "background": [2.5, 0, 1e3])"),
        "colours.json");
    expectVec(scene.ambient, {1.0, srgbByte(0xa0), srgbByte(0x0b)});
    expectVec(scene.background, {2.5, 0, 1000});
}

// "#1a2433" is CSS's colour: sRGB, linearised on load (the sRGB-encoded PNG then shows those bytes
// again); [r, g, b] stays linear as written.
TEST(SceneLoader, HexColoursAreSrgbLikeCss) {
    const Scene scene =
        parseScene(validSceneWith(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": "#808080", "background": "#0a00ff")"),
                   "colours.json");
    EXPECT_NEAR(scene.ambient.r, 0.2158605, 1e-7);        // mid-grey is a fifth of the light, not half
    EXPECT_EQ(scene.background.r, 10.0 / 255.0 / 12.92);  // the linear toe below 0.04045
    EXPECT_EQ(scene.background.g, 0.0);
    EXPECT_EQ(scene.background.b, 1.0);
    const Scene linear =
        parseScene(validSceneWith(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": [0.5, 0.5, 0.5])"), "linear.json");
    EXPECT_EQ(linear.ambient.r, 0.5);
}

// The schema's commented example (tests/scene/schema/commented.json) is a scene: "$schema", a
// string for editors, is accepted and ignored.
TEST(SceneLoader, AcceptsTheSchemaKeyForEditors) {
    const Scene scene = loadSceneFile(sourceDir() / "tests/scene/schema/commented.json");
    EXPECT_EQ(scene.image.width, 320u);
    EXPECT_EQ(scene.background.r, srgbByte(0x1a));
    EXPECT_EQ(errorForChange(R"("ambient")", R"("$schema": 3, "ambient")"),
              "test.json: [\"$schema\"]: expected a string (got number 3)");
}

TEST(SceneLoader, AnIntegralFloatIsAnInteger) {
    const Scene scene = parseScene(validSceneWith(R"("width": 8)", R"("width": 8.0)"), "float.json");
    EXPECT_EQ(scene.image.width, 8u);
}

TEST(SceneLoader, AcceptsTheLargestAllowedImages) {
    EXPECT_EQ(parseScene(validSceneWith(R"("width": 8, "height": 6)", R"("width": 16384, "height": 1)"), "wide.json")
                  .image.width,
              16384u);
    EXPECT_EQ(parseScene(validSceneWith(R"("width": 8, "height": 6)", R"("width": 16384, "height": 16384, "spp": 16)"),
                         "big.json")
                  .image.height,
              16384u);
}

TEST(SceneLoader, ShaderIndicesFollowShaderNames) {
    const Scene scene = parseScene(R"({
        "image": {"width": 8, "height": 6},
        "camera": {"position": [0, 1, -5]},
        "shaders": {"red": {"type": "lambert", "color": [1, 0, 0]}, "blue": {"type": "constant", "color": "#0000ff"}},
        "nodes": [{"geometry": {"type": "plane", "y": -2}, "shader": "blue"},
                  {"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "shader": "red"}]
    })",
                                   "indices.json");
    ASSERT_EQ(scene.shaderNames, (std::vector<std::string>{"blue", "red"}));
    ASSERT_EQ(scene.nodes.size(), 2u);
    EXPECT_EQ(scene.nodes[0].shaderIndex, 0u);
    EXPECT_EQ(std::get<Plane>(scene.nodes[0].geometry).height, -2.0);
    EXPECT_EQ(scene.nodes[1].shaderIndex, 1u);
    EXPECT_TRUE(std::holds_alternative<ConstantShader>(scene.shaders[0]));
    EXPECT_TRUE(std::holds_alternative<LambertShader>(scene.shaders[1]));
}

// ---------------------------------------------------------------- JSON syntax

TEST(SceneLoaderRejects, MissingCommaWithLineAndColumn) {
    const std::string message = errorFor(
        "{\n"
        "  \"image\": {\"width\": 8, \"height\": 6}\n"
        "  \"camera\": {\"position\": [0, 0, 0]},\n"
        "  \"nodes\": []\n"
        "}\n");
    // The parser stops at the end of the unexpected string "camera": line 3, column 10.
    EXPECT_EQ(message,
              "test.json:3:10: JSON syntax error: syntax error while parsing object - "
              "unexpected string literal; expected '}'");
}

TEST(SceneLoaderRejects, SyntaxErrorColumnsCountCharactersNotBytes) {
    // "é" is two bytes in UTF-8 but one column; the stray ']' is the 13th character of line 2.
    const std::string message = errorFor("{\n  \"caf\xC3\xA9\": 1 ]\n}");
    EXPECT_TRUE(contains(message, "test.json:2:13: JSON syntax error: ")) << message;
    EXPECT_FALSE(contains(message, "json.exception")) << message;
}

TEST(SceneLoaderRejects, TruncatedFile) {
    EXPECT_EQ(errorFor("{"),
              "test.json:1:2: JSON syntax error: syntax error while parsing object key - "
              "unexpected end of input; expected string literal");
    EXPECT_TRUE(contains(errorFor(""), "test.json:1:1: JSON syntax error: ")) << errorFor("");
}

TEST(SceneLoaderRejects, DuplicateKey) {
    EXPECT_EQ(errorForChange(R"("width": 8,)", R"("width": 8, "width": 9,)"), "test.json: image.width: duplicate key");
}

// Found by the fuzzer's reasoning about input size: one stored path per nesting level made
// 20 KB of '[' take a minute and 1.4 GB; 200 KB would have exhausted memory.
TEST(SceneLoaderRejects, DeepNestingQuicklyAndAtItsPlace) {
    std::string path = "nodes";
    for (int level = 2; level <= 64; ++level)
        path += "[0]";  // root, nodes, 62 arrays; the 65th is refused
    EXPECT_EQ(errorFor(R"({"nodes": )" + std::string(200000, '[')),
              "test.json: " + path + ": nested deeper than 64 levels");
    // 64 levels are still read (and then rejected for what they are).
    EXPECT_EQ(errorFor(std::string(64, '[') + std::string(64, ']')),
              "test.json: (root): expected an object (got an array of 1 element)");
}

// Paths the parser reports (not the scene reader) inside nested arrays and objects.
TEST(SceneLoaderRejects, ParserProblemsNamedAtNestedPaths) {
    EXPECT_EQ(errorFor(R"({"lights": [1, {"a": [2, 3, 1e999]}]})"),
              "test.json: lights[1].a[2]: must be a finite number (got 1e999)");
    EXPECT_EQ(errorFor(R"({"lights": [1, {"a": [[2], 3, {"b": 1, "b": 2}]}]})"),
              "test.json: lights[1].a[2].b: duplicate key");
}

TEST(SceneLoaderRejects, LongTokensAreCutInSyntaxErrors) {
    EXPECT_EQ(
        errorFor(R"({"image": ")" + std::string(100000, 'x')),
        "test.json:1:100012: JSON syntax error: syntax error while parsing value - invalid string: missing closing "
        "quote; last read: '\"" +
            std::string(39, 'x') + "...'");
    // Cut between characters, not inside one: the 20th two-byte character would straddle the cut.
    std::string accents;
    for (int i = 0; i < 100; ++i)
        accents += "\u00e9";
    std::string shown = "\"";
    for (int i = 0; i < 19; ++i)
        shown += "\u00e9";
    EXPECT_EQ(errorFor(R"({"image": ")" + accents),
              "test.json:1:112: JSON syntax error: syntax error while parsing value - invalid string: missing closing "
              "quote; last read: '" +
                  shown + "...'");
}

TEST(SceneLoaderRejects, LongKeysAreCutInMessages) {
    const std::string key(100000, 'k');
    EXPECT_EQ(errorForChange(R"("width": 8,)", R"("width": 8, ")" + key + R"(": 1,)"),
              "test.json: image[\"" + std::string(40, 'k') +
                  "\"...]: unknown key (allowed: encoding, height, sampling, spp, width)");
}

// ---------------------------------------------------------------- text encodings and comments

// `text` (ASCII) in a wider encoding: each character `width` bytes, little- or big-endian.
std::string widened(const std::string& text, int width, bool littleEndian) {
    std::string wide;
    for (const char c : text) {
        std::string unit(std::size_t(width), '\0');
        unit[littleEndian ? 0 : std::size_t(width - 1)] = c;
        wide += unit;
    }
    return wide;
}

TEST(SceneLoaderRejects, Utf16AndUtf32WithOrWithoutAByteOrderMarkByName) {
    struct Case {
        const char* bom;
        int width;
        bool littleEndian;
        const char* name;
        const char* iconvName;
    };
    for (const Case& c : {Case{"\xFF\xFE", 2, true, "UTF-16 (little-endian)", "UTF-16LE"},
                          Case{"\xFE\xFF", 2, false, "UTF-16 (big-endian)", "UTF-16BE"},
                          Case{"\xFF\xFE\0\0", 4, true, "UTF-32 (little-endian)", "UTF-32LE"},
                          Case{"\0\0\xFE\xFF", 4, false, "UTF-32 (big-endian)", "UTF-32BE"}}) {
        const std::string bom(c.bom, std::size_t(c.width));
        for (const std::string& text :
             {bom + widened(kValidScene, c.width, c.littleEndian), widened(kValidScene, c.width, c.littleEndian)}) {
            EXPECT_EQ(errorFor(text), std::string("test.json: the file is ") + c.name +
                                          " text, and scene files are UTF-8: convert it, e.g. with iconv -f " +
                                          c.iconvName + " -t UTF-8");
        }
    }
}

TEST(SceneLoader, AcceptsAUtf8ByteOrderMarkAndCountsNoColumnForIt) {
    const Scene scene = parseScene("\xEF\xBB\xBF" + kValidScene, "test.json");
    EXPECT_EQ(scene.image.width, 8u);
    EXPECT_EQ(errorFor("\xEF\xBB\xBF{]"),
              "test.json:1:2: JSON syntax error: syntax error while parsing object key - "
              "unexpected ']'; expected string literal");
}

TEST(SceneLoader, LineAndBlockCommentsAreIgnored) {
    const std::string commented = validSceneWith(R"("image": {"width": 8, "height": 6},)",
                                                 "// the image\n  \"image\": {\"width\": /* small */ 8, \"height\": 6},"
                                                 " /* a block\n  over lines */");
    const Scene scene = parseScene("/* first */" + commented + "\n// last", "test.json");
    EXPECT_EQ(scene.image.width, 8u);
    EXPECT_EQ(scene.nodes.size(), 1u);
    EXPECT_EQ(errorFor("{\n  /* never closed"),
              "test.json:2:18: JSON syntax error: syntax error while parsing object key - invalid comment; missing "
              "closing '*/'; last read: '{<U+000A>  /* never closed'; expected string literal");
}

// A comment is read as whitespace, so the place of an error after it counts the comment's own
// lines and characters (é is one column, not two bytes).
TEST(SceneLoader, ErrorsAfterCommentsNameTheirLineAndColumn) {
    EXPECT_EQ(errorFor("// café scene\n/* two\n   lines */ {\"image\": {\"width\": 8,, }}"),
              "test.json:3:35: JSON syntax error: syntax error while parsing object key - unexpected ','; "
              "expected string literal");
    EXPECT_EQ(errorFor("{ /* é */ \"image\": 8 // é\n ]"),
              "test.json:2:2: JSON syntax error: syntax error while parsing object - unexpected ']'; expected '}'");
    // Errors found after parsing name the value's path, whatever the comments around it.
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": /* oops */ -1 /* negative */)"),
              "test.json: nodes[0].geometry.radius: must be > 0 (got -1)");
}

// ---------------------------------------------------------------- structure and types

TEST(SceneLoaderRejects, RootThatIsNotAnObject) {
    EXPECT_EQ(errorFor("[]"), "test.json: (root): expected an object (got an array of 0 elements)");
    EXPECT_EQ(errorFor("42"), "test.json: (root): expected an object (got number 42)");
}

TEST(SceneLoaderRejects, MissingRequiredFields) {
    EXPECT_EQ(errorForChange(R"("width": 8, )", ""), "test.json: image.width: missing required field");
    EXPECT_EQ(errorForChange(R"("image": {"width": 8, "height": 6},)", ""), "test.json: image: missing required field");
    EXPECT_EQ(errorForChange(R"("camera": {"position": [0, 1, -5]},)", R"("camera": {},)"),
              "test.json: camera.position: missing required field");
    EXPECT_EQ(errorForChange(R"("intensity": 100)", R"("color": [1, 1, 1])"),
              "test.json: lights[0].intensity: missing required field");
    EXPECT_EQ(errorForChange(R"(, "radius": 1)", ""), "test.json: nodes[0].geometry.radius: missing required field");
    EXPECT_EQ(errorForChange(R"(, "shader": "red")", ""), "test.json: nodes[0].shader: missing required field");
    EXPECT_EQ(errorForChange(R"("type": "lambert", )", ""), "test.json: shaders.red.type: missing required field");
    EXPECT_EQ(errorFor(R"({"image": {"width": 8, "height": 6}, "camera": {"position": [0, 0, 0]}})"),
              "test.json: nodes: missing required field");
}

TEST(SceneLoaderRejects, WrongJsonTypes) {
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": "big")"),
              "test.json: nodes[0].geometry.radius: expected a number (got string \"big\")");
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": true)"),
              "test.json: image.width: expected an integer (got boolean true)");
    EXPECT_EQ(errorForChange(R"("shader": "red")", R"("shader": 1)"),
              "test.json: nodes[0].shader: expected a string (got number 1)");
    EXPECT_EQ(errorForChange(R"("image": {"width": 8, "height": 6})", R"("image": [8, 6])"),
              "test.json: image: expected an object (got an array of 2 elements)");
    EXPECT_EQ(errorForChange(R"("lights": [{"position": [0, 10, 0], "intensity": 100}])", R"("lights": {})"),
              "test.json: lights: expected an array (got an object)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1])"),
              "test.json: camera.position: expected an array of 3 numbers [x, y, z] (got an array of 2 elements)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, null, -5])"),
              "test.json: camera.position[1]: expected a number (got null)");
}

// ---------------------------------------------------------------- image size

TEST(SceneLoaderRejects, NonIntegerWidth) {
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": 800.5)"),
              "test.json: image.width: must be an integer (got 800.5)");
}

TEST(SceneLoaderRejects, WidthOrHeightOutOfRange) {
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": 0)"),
              "test.json: image.width: must be between 1 and 16384 (got 0)");
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": -5)"),
              "test.json: image.width: must be between 1 and 16384 (got -5)");
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": 1e6)"),
              "test.json: image.width: must be between 1 and 16384 (got 1000000)");
    EXPECT_EQ(errorForChange(R"("height": 6)", R"("height": 16385)"),
              "test.json: image.height: must be between 1 and 16384 (got 16385)");
    EXPECT_EQ(errorForChange(R"("height": 6)", R"("height": 18446744073709551615)"),
              "test.json: image.height: must be between 1 and 16384 (got 18446744073709551615)");
}

TEST(SceneLoaderRejects, TooManySamples) {
    EXPECT_EQ(errorForChange(R"("width": 8, "height": 6)", R"("width": 16384, "height": 16384, "spp": 17)"),
              "test.json: image: 16384 x 16384 pixels x 17 samples = 4563402752 exceeds the limit of 4294967296 "
              "samples per image (lower spp or the image size)");
}

// ---------------------------------------------------------------- numeric ranges

TEST(SceneLoaderRejects, FovOutsideTheOpenRange) {
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1, -5], "fov": 0)"),
              "test.json: camera.fov: must be > 0 and < 180 (got 0)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1, -5], "fov": 180)"),
              "test.json: camera.fov: must be > 0 and < 180 (got 180)");
}

TEST(SceneLoaderRejects, NonPositiveAspect) {
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1, -5], "aspect": 0)"),
              "test.json: camera.aspect: must be > 0 (got 0)");
}

TEST(SceneLoaderRejects, NonPositiveRadius) {
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": 0)"),
              "test.json: nodes[0].geometry.radius: must be > 0 (got 0)");
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": -3)"),
              "test.json: nodes[0].geometry.radius: must be > 0 (got -3)");
}

TEST(SceneLoaderRejects, NonPositiveCheckerSize) {
    EXPECT_EQ(errorForChange(R"({"type": "lambert", "color": [1, 0, 0]})",
                             R"({"type": "checker", "color1": [1, 0, 0], "color2": "#000000", "size": 0})"),
              "test.json: shaders.red.size: must be > 0 (got 0)");
}

TEST(SceneLoaderRejects, NegativeIntensity) {
    EXPECT_EQ(errorForChange(R"("intensity": 100)", R"("intensity": -1)"),
              "test.json: lights[0].intensity: must be >= 0 (got -1)");
}

TEST(SceneLoaderRejects, NonFiniteNumbers) {
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": 1e999)"),
              "test.json: nodes[0].geometry.radius: must be a finite number (got 1e999)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, -1e999, -5])"),
              "test.json: camera.position[1]: must be a finite number (got -1e999)");
    EXPECT_EQ(errorForChange(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": [0.1, 0.1, 2e400])"),
              "test.json: ambient[2]: must be a finite number (got 2e400)");
}

// ---------------------------------------------------------------- the supported range (scene.h)

TEST(SceneLoader, AcceptsLengthsAtTheEdgesOfTheSupportedRange) {
    const Scene scene = parseScene(
        validSceneWith(R"("center": [0, 0, 0], "radius": 1)", R"("center": [1e50, -1e50, 1e-50], "radius": 1e-50)"),
        "test.json");
    const Sphere& sphere = std::get<Sphere>(scene.nodes[0].geometry);
    EXPECT_EQ(sphere.center, glm::dvec3(1e50, -1e50, 1e-50));
    EXPECT_EQ(sphere.radius, 1e-50);
    EXPECT_EQ(parseScene(validSceneWith(R"("radius": 1)", R"("radius": 1e50)"), "t").nodes.size(), 1u);
    EXPECT_EQ(parseScene(validSceneWith(R"("intensity": 100)", R"("intensity": 1e100)"), "t").lights[0].intensity,
              1e100);
    EXPECT_EQ(parseScene(validSceneWith(R"("intensity": 100)", R"("intensity": 1e-100)"), "t").lights[0].intensity,
              1e-100);
    EXPECT_EQ(parseScene(validSceneWith(R"("intensity": 100)", R"("intensity": 0)"), "t").lights[0].intensity, 0.0);
    EXPECT_EQ(parseScene(validSceneWith(R"([1, 0, 0])", R"([1e10, 0, 0])"), "t").shaders.size(), 1u);
}

// Issue 12, finding 4: a plane at y = 1e308 and a radius of 1e308 were accepted, and rendered
// wrong on both backends with exit 0.
TEST(SceneLoaderRejects, LengthsBeyondTheSupportedRange) {
    const std::string range = "in magnitude, the supported range of lengths";
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": 1e308)"),
              "test.json: nodes[0].geometry.radius: must be between 1e-50 and 1e+50 " + range + " (got 1e+308)");
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": 9.99e-51)"),
              "test.json: nodes[0].geometry.radius: must be between 1e-50 and 1e+50 " + range + " (got 9.99e-51)");
    EXPECT_EQ(
        errorForChange(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})", R"({"type": "plane", "y": 1e308})"),
        "test.json: nodes[0].geometry.y: must be 0 or between 1e-50 and 1e+50 " + range + " (got 1e+308)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1, -1.0000001e50])"),
              "test.json: camera.position[2]: must be 0 or between 1e-50 and 1e+50 " + range + " (got -1.0000001e+50)");
    EXPECT_EQ(
        errorForChange(R"("center": [0, 0, 0])", R"("center": [0, 1e-300, 0])"),
        "test.json: nodes[0].geometry.center[1]: must be 0 or between 1e-50 and 1e+50 " + range + " (got 1e-300)");
    EXPECT_EQ(errorForChange(R"("position": [0, 10, 0])", R"("position": [3.5e58, 10, 0])"),
              "test.json: lights[0].position[0]: must be 0 or between 1e-50 and 1e+50 " + range + " (got 3.5e+58)");
    EXPECT_EQ(errorForChange(R"({"type": "lambert", "color": [1, 0, 0]})",
                             R"({"type": "checker", "color1": [1, 0, 0], "color2": "#000000", "size": 2e50})"),
              "test.json: shaders.red.size: must be between 1e-50 and 1e+50 " + range + " (got 2e+50)");
    EXPECT_EQ(errorForChange(R"("intensity": 100)", R"("intensity": 1e101)"),
              "test.json: lights[0].intensity: must be 0 or between 1e-100 and 1e+100 in magnitude, the supported "
              "range of intensities (got 1e+101)");
    EXPECT_EQ(errorForChange(R"([1, 0, 0])", R"([1, 2e10, 0])"),
              "test.json: shaders.red.color[1]: colour component must be at most 10000000000, the supported range "
              "(got number 20000000000)");
}

// ---------------------------------------------------------------- colours

TEST(SceneLoaderRejects, BadHexColours) {
    const std::string forms = "[r, g, b] with finite components >= 0, or \"#rrggbb\"";
    EXPECT_EQ(errorForChange(R"("color": [1, 0, 0])", R"("color": "#12345g")"),
              "test.json: shaders.red.color: expected a colour: " + forms + " (got string \"#12345g\")");
    EXPECT_EQ(errorForChange(R"("color": [1, 0, 0])", R"("color": "#12345")"),
              "test.json: shaders.red.color: expected a colour: " + forms + " (got string \"#12345\")");
    EXPECT_EQ(errorForChange(R"("color": [1, 0, 0])", R"("color": "red")"),
              "test.json: shaders.red.color: expected a colour: " + forms + " (got string \"red\")");
    EXPECT_EQ(errorForChange(R"("color": [1, 0, 0])", R"("color": "#+12345")"),
              "test.json: shaders.red.color: expected a colour: " + forms + " (got string \"#+12345\")");
}

TEST(SceneLoaderRejects, BadColourArrays) {
    const std::string forms = "[r, g, b] with finite components >= 0, or \"#rrggbb\"";
    EXPECT_EQ(errorForChange(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": [0.1, 0.1])"),
              "test.json: ambient: expected a colour: " + forms + " (got an array of 2 elements)");
    EXPECT_EQ(
        errorForChange(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": [0.1, -0.5, 0.1])"),
        "test.json: ambient[1]: colour component must be a finite number >= 0 (got number -0.5); a colour is " + forms);
    EXPECT_EQ(errorForChange(R"("ambient": [0.1, 0.1, 0.1])", R"("ambient": 0.1)"),
              "test.json: ambient: expected a colour: " + forms + " (got number 0.1)");
}

// ---------------------------------------------------------------- names

TEST(SceneLoaderRejects, UnknownShaderName) {
    EXPECT_EQ(errorForChange(R"("shader": "red")", R"("shader": "rde")"),
              "test.json: nodes[0].shader: unknown shader \"rde\" (defined: red); did you mean \"red\"?");
    EXPECT_EQ(
        errorFor(kExampleScene.substr(0, kExampleScene.find(R"("shader": "ball")")) + R"("shader": "flor"}]})"),
        "test.json: nodes[1].shader: unknown shader \"flor\" (defined: ball, debug, floor); did you mean \"floor\"?");
    EXPECT_EQ(errorForChange(R"("shaders": {"red": {"type": "lambert", "color": [1, 0, 0]}},)", ""),
              "test.json: nodes[0].shader: unknown shader \"red\" (no shaders are defined)");
}

// A near miss of a known key, value or shader name is named (util/closest_name.h); a far one is not.
TEST(SceneLoaderRejects, SuggestsTheNameMeant) {
    EXPECT_EQ(
        errorForChange(R"("intensity": 100)", R"("intensity": 100, "colour": [1, 1, 1])"),
        "test.json: lights[0].colour: unknown key (allowed: color, intensity, position); did you mean \"color\"?");
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("raduis": 1)"),
              "test.json: nodes[0].geometry.raduis: unknown key (allowed: center, radius, type); did you mean "
              "\"radius\"?");
    EXPECT_EQ(errorForChange(R"("type": "lambert")", R"("type": "lamber")"),
              "test.json: shaders.red.type: unknown value \"lamber\" (allowed: checker, constant, lambert); did you "
              "mean \"lambert\"?");
    EXPECT_EQ(errorForChange(R"("shader": "red")", R"("shader": "Red")"),
              "test.json: nodes[0].shader: unknown shader \"Red\" (defined: red); did you mean \"red\"?");
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": 8, "depth": 3)"),
              "test.json: image.depth: unknown key (allowed: encoding, height, sampling, spp, width)");
    EXPECT_EQ(errorForChange(R"("shader": "red")", R"("shader": "blue")"),
              "test.json: nodes[0].shader: unknown shader \"blue\" (defined: red)");
}

TEST(SceneLoaderRejects, UnknownKeysAtEveryDepth) {
    EXPECT_EQ(errorForChange(R"("lights":)", R"("lihgts":)"),
              "test.json: lihgts: unknown key (allowed: $schema, ambient, background, camera, image, lights, nodes, "
              "shaders); did you mean \"lights\"?");
    EXPECT_EQ(errorForChange(R"("width": 8)", R"("width": 8, "depth": 3)"),
              "test.json: image.depth: unknown key (allowed: encoding, height, sampling, spp, width)");
    EXPECT_EQ(errorForChange(R"("position": [0, 1, -5])", R"("position": [0, 1, -5], "fvo": 60)"),
              "test.json: camera.fvo: unknown key (allowed: aspect, fov, lookAt, pitch, position, roll, up, yaw); did "
              "you mean \"fov\"?");
    EXPECT_EQ(
        errorForChange(R"("intensity": 100)", R"("intensity": 100, "colour": [1, 1, 1])"),
        "test.json: lights[0].colour: unknown key (allowed: color, intensity, position); did you mean \"color\"?");
    EXPECT_EQ(errorForChange(R"("color": [1, 0, 0])", R"("color": [1, 0, 0], "size": 2)"),
              "test.json: shaders.red.size: unknown key (allowed: color, type)");
    EXPECT_EQ(errorForChange(R"("radius": 1)", R"("radius": 1, "y": 0)"),
              "test.json: nodes[0].geometry.y: unknown key (allowed: center, radius, type)");
    EXPECT_EQ(errorForChange(R"("shader": "red")", R"("shader": "red", "name": "ball")"),
              "test.json: nodes[0].name: unknown key (allowed: geometry, shader)");
}

TEST(SceneLoaderRejects, KeysThatAreNotIdentifiersAreQuotedInPaths) {
    EXPECT_EQ(errorForChange(R"("red": {"type": "lambert", "color": [1, 0, 0]})",
                             R"("red": {"type": "lambert", "color": [1, 0, 0]}, "my ball": {"type": "lambert"})"),
              "test.json: shaders[\"my ball\"].color: missing required field");
}

TEST(SceneLoaderRejects, BadEnumStrings) {
    EXPECT_EQ(
        errorForChange(R"("height": 6)", R"("height": 6, "sampling": "centre")"),
        "test.json: image.sampling: unknown value \"centre\" (allowed: center, corner); did you mean \"center\"?");
    EXPECT_EQ(errorForChange(R"("height": 6)", R"("height": 6, "encoding": "gamma")"),
              "test.json: image.encoding: unknown value \"gamma\" (allowed: linear, srgb)");
    EXPECT_EQ(errorForChange(R"("type": "sphere")", R"("type": "cube")"),
              "test.json: nodes[0].geometry.type: unknown value \"cube\" (allowed: plane, sphere)");
    EXPECT_EQ(errorForChange(R"("type": "lambert")", R"("type": "phong")"),
              "test.json: shaders.red.type: unknown value \"phong\" (allowed: checker, constant, lambert)");
}

// ---------------------------------------------------------------- nodes, many and of every shape

const std::string kValidNode = R"({"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "shader": "red"})";

// kValidScene whose only node is replaced by `nodes` (the text between the list's brackets).
std::string validSceneWithNodes(const std::string& nodes) {
    return validSceneWith(kValidNode, nodes);
}

// `count` spheres, the i-th at (i, 0, 0), except that node `at` is `replacement`.
std::string manySpheres(std::size_t count, std::size_t at = std::string::npos, const std::string& replacement = "") {
    std::string nodes;
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0)
            nodes += ",\n";
        nodes += i == at ? replacement
                         : R"({"geometry": {"type": "sphere", "center": [)" + std::to_string(i) +
                               R"(, 0, 0], "radius": 1}, "shader": "red"})";
    }
    return validSceneWithNodes(nodes);
}

TEST(SceneLoaderNodes, ManyNodesAreAllRead) {
    const Scene scene = parseScene(manySpheres(100000), "test.json");
    ASSERT_EQ(scene.nodes.size(), 100000u);
    for (const std::size_t i : {std::size_t{0}, std::size_t{51234}, std::size_t{99999}}) {
        const Sphere& sphere = std::get<Sphere>(scene.nodes[i].geometry);
        expectVec(sphere.center, {double(i), 0, 0});
        EXPECT_EQ(sphere.radius, 1.0);
        EXPECT_EQ(scene.nodes[i].shaderIndex, 0u);
    }
}

// The duplicate-key check does not stop after the start of a file.
TEST(SceneLoaderNodes, DuplicateKeyDeepInsideALargeFile) {
    const std::string geometry = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "radius": 2})";
    EXPECT_EQ(errorFor(manySpheres(100000, 99990, R"({"geometry": )" + geometry + R"(, "shader": "red"})")),
              "test.json: nodes[99990].geometry.radius: duplicate key");
    EXPECT_EQ(errorFor(manySpheres(100000, 77777,
                                   R"({"shader": "red", "geometry": {"type": "plane", "y": 0},)"
                                   R"( "shader": "red"})")),
              "test.json: nodes[77777].shader: duplicate key");
}

TEST(SceneLoaderNodes, AProblemInTheLastNodeOfALargeFile) {
    EXPECT_EQ(errorFor(manySpheres(100000, 99999, R"({"geometry": {"type": "plane", "y": "0"}, "shader": "red"})")),
              "test.json: nodes[99999].geometry.y: expected a number (got string \"0\")");
}

// Nodes are read as the parser meets them, before the shaders when the file lists those later.
TEST(SceneLoaderNodes, NodesMayComeBeforeTheShadersTheyName) {
    const Scene scene = parseScene(R"({"nodes": [
        {"shader": "b", "geometry": {"radius": 2, "center": [1, 2, 3], "type": "sphere"}},
        {"geometry": {"y": -4, "type": "plane"}, "shader": "a"},
        {"geometry": {"type": "plane", "y": 5}, "shader": "b"}],
      "shaders": {"b": {"type": "constant", "color": [0, 0, 1]}, "a": {"type": "lambert", "color": [1, 0, 0]}},
      "camera": {"position": [0, 1, -5]}, "image": {"width": 8, "height": 6}})",
                                   "test.json");
    ASSERT_EQ(scene.shaderNames, (std::vector<std::string>{"a", "b"}));
    ASSERT_EQ(scene.nodes.size(), 3u);
    EXPECT_EQ(scene.nodes[0].shaderIndex, 1u);
    EXPECT_EQ(scene.nodes[1].shaderIndex, 0u);
    EXPECT_EQ(scene.nodes[2].shaderIndex, 1u);
    expectVec(std::get<Sphere>(scene.nodes[0].geometry).center, {1, 2, 3});
    EXPECT_EQ(std::get<Sphere>(scene.nodes[0].geometry).radius, 2.0);
    EXPECT_EQ(std::get<Plane>(scene.nodes[1].geometry).height, -4.0);
    EXPECT_EQ(std::get<Plane>(scene.nodes[2].geometry).height, 5.0);
}

TEST(SceneLoaderNodes, NumbersInEveryJsonFormAreReadAlike) {
    const Scene scene = parseScene(
        validSceneWithNodes(
            R"({"geometry": {"type": "sphere", "center": [1, -2, 3.5e2], "radius": 18446744073709551615}, "shader": "red"},
           {"geometry": {"type": "plane", "y": -7.25}, "shader": "red"})"),
        "test.json");
    const Sphere& sphere = std::get<Sphere>(scene.nodes[0].geometry);
    expectVec(sphere.center, {1, -2, 350});
    EXPECT_EQ(sphere.radius, 18446744073709551615.0);
    EXPECT_EQ(std::get<Plane>(scene.nodes[1].geometry).height, -7.25);
}

// Every way a node can be wrong gets the message of its first problem.
TEST(SceneLoaderNodes, EachBadNodeIsNamedWithItsFirstProblem) {
    const std::pair<std::string, std::string> cases[] = {
        {R"(5)", "nodes[0]: expected an object (got number 5)"},
        {R"([])", "nodes[0]: expected an object (got an array of 0 elements)"},
        {R"({"shader": "red"})", "nodes[0].geometry: missing required field"},
        {R"({"geometry": null, "shader": "red"})", "nodes[0].geometry: expected an object (got null)"},
        {R"({"geometry": {"type": "plane", "y": 0}, "shader": null})", "nodes[0].shader: expected a string (got null)"},
        {R"({"geometry": {"type": "plane", "y": 0}, "shader": "red", "name": "x"})",
         "nodes[0].name: unknown key (allowed: geometry, shader)"},
        {R"({"geometry": {"center": [0, 0, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.type: missing required field"},
        {R"({"geometry": {"type": "Sphere", "center": [0, 0, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.type: unknown value \"Sphere\" (allowed: plane, sphere); did you mean \"sphere\"?"},
        {R"({"geometry": {"type": "sphere", "center": [0, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.center: expected an array of 3 numbers [x, y, z] (got an array of 2 elements)"},
        {R"({"geometry": {"type": "sphere", "center": [0, 0, 0, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.center: expected an array of 3 numbers [x, y, z] (got an array of 4 elements)"},
        {R"({"geometry": {"type": "sphere", "center": [0, "a", 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.center[1]: expected a number (got string \"a\")"},
        {R"({"geometry": {"type": "sphere", "center": [[0], 0, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.center[0]: expected a number (got an array of 1 element)"},
        {R"({"geometry": {"type": "sphere", "center": [0, 0, 0]}, "shader": "red"})",
         "nodes[0].geometry.radius: missing required field"},
        {R"({"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 1e-320}, "shader": "red"})",
         "nodes[0].geometry.radius: must be between 1e-50 and 1e+50 in magnitude, the supported range of lengths "
         "(got 1e-320)"},
        {R"({"geometry": {"type": "sphere", "center": [0, 1e60, 0], "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.center[1]: must be 0 or between 1e-50 and 1e+50 in magnitude, the supported range of "
         "lengths (got 1e+60)"},
        {R"({"geometry": {"type": "plane", "y": 0, "radius": 1}, "shader": "red"})",
         "nodes[0].geometry.radius: unknown key (allowed: type, y)"},
        {R"({"geometry": {"type": "plane"}, "shader": "red"})", "nodes[0].geometry.y: missing required field"},
        {R"({"geometry": {"type": "plane", "y": true}, "shader": "red"})",
         "nodes[0].geometry.y: expected a number (got boolean true)"},
        {R"({"geometry": {"type": "plane", "type": "plane", "y": 0}, "shader": "red"})",
         "nodes[0].geometry.type: duplicate key"},
    };
    for (const auto& [node, message] : cases) {
        SCOPED_TRACE(node);
        EXPECT_EQ(errorFor(validSceneWithNodes(node)), "test.json: " + message);
    }
}

// Nodes are read as the parser meets them, but problems are reported as if the file were read
// whole: the parser's first, then the scene's parts in a fixed order, then the first bad node.
TEST(SceneLoaderNodes, ProblemsAreReportedInTheSameOrderWhereverTheNodesAre) {
    const std::string badRadius =
        R"({"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 0}, "shader": "red"})";
    const std::string unknownShader = R"({"geometry": {"type": "plane", "y": 0}, "shader": "blue"})";
    EXPECT_EQ(errorFor(R"({"nodes": [)" + badRadius + R"(], "image": {"width": 0, "height": 6}})"),
              "test.json: image.width: must be between 1 and 16384 (got 0)");
    EXPECT_EQ(errorFor(validSceneWithNodes(unknownShader + ", " + badRadius)),
              "test.json: nodes[0].shader: unknown shader \"blue\" (defined: red)");
    EXPECT_EQ(errorFor(validSceneWithNodes(badRadius + ", " + unknownShader)),
              "test.json: nodes[0].geometry.radius: must be > 0 (got 0)");
    EXPECT_EQ(errorFor(R"({"nodes": [)" + badRadius + R"(], "image": {"width": 8, "width": 8}})"),
              "test.json: image.width: duplicate key");
    EXPECT_EQ(errorFor(R"({"nodes": [)" + badRadius + R"(], "image": })"),
              "test.json:1:107: JSON syntax error: syntax error while parsing value - unexpected '}'; "
              "expected '[', '{', or a literal");
}

// ---------------------------------------------------------------- files

TEST_F(SceneFileTest, LoadsAFileAndNamesItInMessages) {
    const fs::path good = write("good.json", kValidScene);
    EXPECT_EQ(loadSceneFile(good).image.width, 8u);

    const fs::path bad = write("bad.json", validSceneWith(R"("radius": 1)", R"("radius": -3)"));
    try {
        loadSceneFile(bad);
        ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), bad.string() + ": nodes[0].geometry.radius: must be > 0 (got -3)");
    }
}

// Just over the limit, in a sparse file that takes no disk.
TEST_F(SceneFileTest, FilesOverTheSizeLimitAreRefused) {
    const fs::path huge = folder_ / "huge.json";
    std::ofstream(huge, std::ios::binary).close();
    fs::resize_file(huge, (std::uintmax_t{256} << 20) + 1);  // sparse: no disk used
    try {
        loadSceneFile(huge);
        ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), huge.string() + ": cannot read scene file: larger than 256 MiB");
    }
}

TEST_F(SceneFileTest, MissingFile) {
    const fs::path missing = folder_ / "no_such_scene.json";
    try {
        loadSceneFile(missing);
        ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), missing.string() + ": cannot read scene file: No such file or directory");
    }
}

TEST_F(SceneFileTest, DirectoryGivenAsTheFile) {
    try {
        loadSceneFile(folder_);
        ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), folder_.string() + ": cannot read scene file: Is a directory");
    }
}

TEST(SceneFiles, EverySceneUnderScenesLoads) {
    const fs::path scenes = sourceDir() / "scenes";
    ASSERT_TRUE(fs::is_directory(scenes)) << scenes;
    for (const auto& entry : fs::recursive_directory_iterator(scenes)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".json" ||
            entry.path().filename() == "hexray-expectations.json")  // compare's, not a scene
            continue;
        try {
            loadSceneFile(entry.path());
        } catch (const SceneError& error) {
            ADD_FAILURE() << error.what();
        }
    }
}

// ---------------------------------------------------------------- overrideImageSize

TEST(OverrideImageSize, ReplacesTheSize) {
    Scene scene = parseScene(kValidScene, "test.json");
    overrideImageSize(scene, 320, 200, "command line");
    EXPECT_EQ(scene.image.width, 320u);
    EXPECT_EQ(scene.image.height, 200u);
}

TEST(OverrideImageSize, RejectsWithTheSameChecksAndLeavesTheSceneAlone) {
    Scene scene = parseScene(kValidScene, "test.json");
    const auto errorFor = [&](std::int64_t width, std::int64_t height, const std::string& source) -> std::string {
        try {
            overrideImageSize(scene, width, height, source);
        } catch (const SceneError& error) {
            return error.what();
        }
        ADD_FAILURE() << width << " x " << height << " was accepted";
        return "";
    };
    EXPECT_EQ(errorFor(0, 6, "--width"), "--width: must be between 1 and 16384 (got 0)");
    EXPECT_EQ(errorFor(8, 20000, "--height"), "--height: must be between 1 and 16384 (got 20000)");
    EXPECT_EQ(errorFor(-1, 6, "command line"), "command line: width must be between 1 and 16384 (got -1)");
    EXPECT_EQ(errorFor(8, 0, "--width/--height"), "--width/--height: height must be between 1 and 16384 (got 0)");
    scene.image.samplesPerPixel = 32;
    EXPECT_EQ(errorFor(16384, 16384, "command line"),
              "command line: 16384 x 16384 pixels x 32 samples = 8589934592 exceeds the limit of 4294967296 "
              "samples per image (lower spp or the image size)");
    EXPECT_EQ(scene.image.width, 8u);
    EXPECT_EQ(scene.image.height, 6u);
}

TEST(SamplesPerPixel, DefaultOneReadFromSppAndChecked) {
    EXPECT_EQ(parseScene(kValidScene, "test.json").image.samplesPerPixel, 1u);
    EXPECT_EQ(
        parseScene(validSceneWith(R"("width": 8,)", R"("width": 8, "spp": 16,)"), "test.json").image.samplesPerPixel,
        16u);
    EXPECT_EQ(errorForChange(R"("width": 8,)", R"("width": 8, "spp": 0,)"),
              "test.json: image.spp: must be between 1 and 1024 (got 0)");
    EXPECT_EQ(errorForChange(R"("width": 8,)", R"("width": 8, "spp": 2.5,)"),
              "test.json: image.spp: must be an integer (got 2.5)");
}

TEST(SamplesPerPixel, OverrideIsCheckedTheSameWay) {
    Scene scene = parseScene(kValidScene, "test.json");
    overrideSamplesPerPixel(scene, 64, "--spp");
    EXPECT_EQ(scene.image.samplesPerPixel, 64u);
    try {
        overrideSamplesPerPixel(scene, 5000, "--spp");
        ADD_FAILURE() << "5000 samples were accepted";
    } catch (const SceneError& error) {
        EXPECT_STREQ(error.what(), "--spp: must be between 1 and 1024 (got 5000)");
    }
    EXPECT_EQ(scene.image.samplesPerPixel, 64u);
    overrideSamplesPerPixel(scene, 1, "--spp");
    overrideImageSize(scene, 16384, 16384, "--width/--height");
    try {
        overrideSamplesPerPixel(scene, 17, "--spp");
        ADD_FAILURE() << "17 samples of 16384 x 16384 were accepted";
    } catch (const SceneError& error) {
        EXPECT_NE(std::string(error.what()).find("--spp: 16384 x 16384 pixels x 17 samples"), std::string::npos)
            << error.what();
    }
}
