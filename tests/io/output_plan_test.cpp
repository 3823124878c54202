// The plan refuses an output that is an input or another output, however the path reaches it,
// and an output that cannot be written, before any work.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/output_error.h"
#include "io/output_plan.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

class OutputPlanTest : public test::TemporaryDirectoryTest {
protected:
    void SetUp() override {
        TemporaryDirectoryTest::SetUp();
        std::ofstream(dir_ / "scene.json") << "{}";
        fs::create_directories(dir_ / "out");
    }

    std::string path(const std::string& relative) const { return (dir_ / relative).string(); }

    // The message of the OutputConflict `plan` throws, or "" if it passes.
    static std::string conflictOf(const OutputPlan& plan) {
        try {
            plan.check();
        } catch (const OutputConflict& conflict) {
            return conflict.what();
        }
        return "";
    }

    static bool isAovName(const std::string& name) { return name == "depth.png" || name == "scene.json"; }
};

TEST_F(OutputPlanTest, AnOutputReachingTheSceneByAnyPathIsRefused) {
    fs::create_hard_link(dir_ / "scene.json", dir_ / "hard.png");
    fs::create_symlink("scene.json", dir_ / "soft.png");
    for (const std::string output : {"scene.json", "hard.png", "soft.png", "out/../scene.json"}) {
        OutputPlan plan;
        plan.addInput("the scene", path("scene.json"));
        plan.addFile("-o", path(output));
        EXPECT_EQ(conflictOf(plan), "-o " + path(output) + ": the same file as the scene " + path("scene.json"))
            << output;
    }
}

TEST_F(OutputPlanTest, TwoNewOutputsReachingOneFileAreRefused) {
    fs::create_directory_symlink("out", dir_ / "alias");
    OutputPlan plan;
    plan.addFile("--diff", path("out/x.png"));
    plan.addFile("--mask", path("alias/x.png"));
    EXPECT_EQ(conflictOf(plan), "--mask " + path("alias/x.png") + ": the same file as --diff " + path("out/x.png"));
}

TEST_F(OutputPlanTest, AnOutputDirectoryMayNotBeAnOutputNorHoldOneUnderANameItWrites) {
    OutputPlan same;
    same.addFile("-o", path("l.png"));
    same.addDirectory("--aov", path("l.png"), isAovName);
    EXPECT_EQ(conflictOf(same), "--aov " + path("l.png") + ": the same path as -o " + path("l.png"));

    OutputPlan inside;
    inside.addFile("-o", path("aov/depth.png"));
    inside.addDirectory("--aov", path("aov"), isAovName);
    EXPECT_EQ(conflictOf(inside), "--aov " + path("aov") + ": would write over -o " + path("aov/depth.png"));

    OutputPlan scene;  // a scene file an AOV set would replace
    scene.addInput("the scene", path("scene.json"));
    scene.addDirectory("--aov", dir_, isAovName);
    EXPECT_NE(conflictOf(scene).find("would write over the scene"), std::string::npos) << conflictOf(scene);

    OutputPlan other;  // a name the set does not write is no conflict
    other.addFile("-o", path("aov/image.png"));
    other.addDirectory("--aov", path("aov"), isAovName);
    fs::create_directories(dir_ / "aov");
    EXPECT_EQ(conflictOf(other), "");
}

TEST_F(OutputPlanTest, SeparateOutputsPass) {
    OutputPlan plan;
    plan.addInput("the scene", path("scene.json"));
    plan.addInput("the scene", path("missing.json"));  // reported by the command itself
    plan.addFile("--diff", path("out/diff.png"));
    plan.addFile("--mask", path("out/mask.png"));
    plan.addDirectory("--aov", path("new/aov/gpu"), isAovName);
    plan.addDirectory("--aov", path("new/aov/cpu"), isAovName);
    EXPECT_NO_THROW(plan.check());
    EXPECT_FALSE(fs::exists(dir_ / "new"));  // checking creates nothing
}

TEST_F(OutputPlanTest, AnOutputThatCannotBeWrittenIsAnOutputError) {
    std::ofstream(dir_ / "file.txt") << "not a directory";
    OutputPlan missing;
    missing.addFile("--csv", path("nodir/x.csv"));
    EXPECT_THROW(missing.check(), OutputError);
    OutputPlan underAFile;
    underAFile.addDirectory("--aov", path("file.txt/aov"), isAovName);
    try {
        underAFile.check();
        FAIL() << "expected OutputError";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find("--aov " + path("file.txt/aov") + ": cannot create the directory"),
                  std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace hexray
