// The options bounce-render, bounce-view, bounce-trace and bounce-bake share
// (engine/cli/shared_options.h): a tool's defaults survive a parse that does not give them, the
// values given land in their fields, and a bad value is refused with the message each tool
// printed before the options were declared once (CLI11's, e.g. "--mode: x not in {...}").
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/shared_options.h"

namespace bounce {
namespace {

const std::vector<std::string> kModes = {"full", "direct", "cost"};

// Every shared group on one App, as bounce-render and bounce-view declare them.
struct Tool {
  CLI::App app{"test", "test"};
  SharedOptions o;
  explicit Tool(int width = 512, int height = 512) {
    o.width = width;
    o.height = height;
    addSceneOption(app, o);
    addCameraOption(app, o);
    addSizeOptions(app, o, 16, "window", "default 512");
    addExposureOption(app, o);
    addBakeOptions(app, o);
    addModeOption(app, o, kModes, "what to draw");
    addMsaaOption(app, o);
    addCostViewOptions(app, o, "the frame's largest");
    addDynamicVplsOption(app, o);
    addPathTracingOptions(app, o);
  }
  // Parses `args` (without the program name); returns CLI11's message, empty when accepted.
  std::string parse(std::vector<std::string> args) {
    std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector from its back
    try {
      app.parse(args);
    } catch (const CLI::ParseError& e) {
      return e.what();
    }
    return "";
  }
};

TEST(SharedOptions, TheToolsDefaultsSurviveAParseThatDoesNotGiveThem) {
  Tool tool(1280, 720);
  ASSERT_EQ(tool.parse({"room.gltf"}), "");
  EXPECT_EQ(tool.o.scene, "room.gltf");
  EXPECT_EQ(tool.o.width, 1280);
  EXPECT_EQ(tool.o.height, 720);
  EXPECT_EQ(tool.o.exposure, 0.0f);
  EXPECT_EQ(tool.o.msaa, 4);
  EXPECT_EQ(tool.o.mode, "");  // full with a bake, direct without: the tool decides
  EXPECT_EQ(tool.o.costCount, "vpls");
  EXPECT_FALSE(tool.o.costMax.has_value());
  EXPECT_EQ(tool.o.dynamicVpls, "retrace");
  EXPECT_EQ(tool.o.lightChoice, "place");
  EXPECT_EQ(tool.o.backend, "embree");
}

TEST(SharedOptions, GivenValuesLandInTheirFields) {
  Tool tool;
  ASSERT_EQ(tool.parse({"box.gltf",     "--camera",    "top",        "--width", "64",
                        "--height",     "32",          "--exposure", "-1.5",    "--bake",
                        "box.bake",     "--mode",      "cost",       "--msaa",  "1",
                        "--cost-count", "taps",        "--cost-max", "20",      "--dynamic-vpls",
                        "cut",          "--max-depth", "3",          "--seed",  "7",
                        "--threads",    "2",           "--backend",  "bvh",     "--light-choice",
                        "power"}),
            "");
  EXPECT_EQ(tool.o.camera, "top");
  EXPECT_EQ(tool.o.width, 64);
  EXPECT_EQ(tool.o.height, 32);
  EXPECT_EQ(tool.o.exposure, -1.5f);
  EXPECT_EQ(tool.o.bake, "box.bake");
  EXPECT_EQ(tool.o.mode, "cost");
  EXPECT_EQ(tool.o.msaa, 1);
  EXPECT_EQ(tool.o.costCount, "taps");
  EXPECT_EQ(tool.o.costMax, 20.0f);
  EXPECT_EQ(tool.o.dynamicVpls, "cut");
  EXPECT_EQ(tool.o.maxDepth, 3);
  EXPECT_EQ(tool.o.seed, 7u);
  EXPECT_EQ(tool.o.threads, 2);
  EXPECT_EQ(tool.o.backend, "bvh");
  EXPECT_EQ(tool.o.lightChoice, "power");
}

// The messages the tools printed before (captured from bounce-render, bounce-view, bounce-trace
// and bounce-bake built from the commit before the shared declarations).
TEST(SharedOptions, BadValuesAreRefusedWithTheToolsMessages) {
  const auto refusal = [](std::vector<std::string> args) {
    args.insert(args.begin(), "box.gltf");
    return Tool().parse(args);
  };
  EXPECT_EQ(refusal({"--mode", "bogus"}), "--mode: bogus not in {full,direct,cost}");
  EXPECT_EQ(refusal({"--width", "15"}), "--width: Value 15 not in range 16 to 16384");
  EXPECT_EQ(refusal({"--height", "16385"}), "--height: Value 16385 not in range 16 to 16384");
  EXPECT_EQ(refusal({"--msaa", "65"}), "--msaa: Value 65 not in range 1 to 64");
  EXPECT_EQ(refusal({"--bake", "d", "--no-bake"}), "--bake excludes --no-bake");
  EXPECT_EQ(refusal({"--no-bake", "--bake", "d"}), "--bake excludes --no-bake");
  EXPECT_EQ(refusal({"--cost-count", "x"}), "--cost-count: x not in {lights,vpls,taps}");
  EXPECT_NE(refusal({"--cost-max", "0"}), "");
  EXPECT_EQ(refusal({"--dynamic-vpls", "x"}), "--dynamic-vpls: x not in {retrace,cut}");
  EXPECT_EQ(refusal({"--exposure", "abc"}), "Could not convert: --exposure = abc");
  EXPECT_EQ(refusal({"--max-depth", "-1"}), "--max-depth: Value -1 not in range 0 to 100000");
  EXPECT_EQ(refusal({"--seed", "-1"}), "Could not convert: --seed = -1");
  EXPECT_EQ(refusal({"--threads", "2000"}), "--threads: Value 2000 not in range 0 to 1024");
  EXPECT_EQ(refusal({"--backend", "x"}), "--backend: x not in {embree,bvh}");
  EXPECT_EQ(refusal({"--light-choice", "x"}), "--light-choice: x is not place or power");
  EXPECT_EQ(Tool().parse({}), "scene is required");
}

}  // namespace
}  // namespace bounce
