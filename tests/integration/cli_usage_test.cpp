// The command line itself: --help for the tool and every command, and usage mistakes that fail with
// bad_request and exit status 2 before anything is read or written.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/temp_dir.hpp"

namespace lp {
namespace {

const std::vector<std::string> kCommands = {"info", "sample",   "median-cut", "fresnel", "render", "convert",
                                            "sh",   "brdf-lut", "sun",        "bake",    "denoise"};

TEST(CliUsage, HelpForTheToolAndEveryCommand) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--help"}, {"-h"}, {"help"}}) {
    const test::CliRun run = test::run_cli(args);
    EXPECT_EQ(run.exit_status, 0);
    EXPECT_EQ(run.out.rfind("lightprobe: ", 0), 0u);
    for (const std::string& command : kCommands)
      EXPECT_NE(run.out.find("  " + command + " "), std::string::npos);
  }
  for (const std::string& command : kCommands) {
    SCOPED_TRACE(command);
    const test::CliRun run = test::run_cli({command, "--help"});
    EXPECT_EQ(run.exit_status, 0);
    EXPECT_EQ(run.out.rfind("Usage: lightprobe " + command, 0), 0u) << run.out;
    EXPECT_NE(run.out.find("\n  -"), std::string::npos) << "no options listed";
    EXPECT_EQ(run.err, "");
  }
}

// What --help states comes from the API's declarations: limits and defaults are the parsers'.
TEST(CliUsage, HelpStatesTheApisLimitsAndDefaults) {
  const std::string sample = test::run_cli({"sample", "--help"}).out;
  EXPECT_NE(sample.find("samples, in [1, 10000000] (required)"), std::string::npos) << sample;
  EXPECT_NE(sample.find("independent, stratified, sobol (default independent)"), std::string::npos);
  const std::string median_cut = test::run_cli({"median-cut", "--help"}).out;
  EXPECT_NE(median_cut.find("lights, in [1, 65536] (default 64)"), std::string::npos) << median_cut;
  EXPECT_NE(median_cut.find("json, mitsuba, blender, usd, gltf (default json) or csv, pbrt"),
            std::string::npos)
      << median_cut;
  const std::string convert = test::run_cli({"convert", "--help"}).out;
  EXPECT_NE(convert.find("latlong, cube, cross, octahedral, equal-area (default latlong)"), std::string::npos)
      << convert;
  EXPECT_NE(convert.find("[2, 8192]"), std::string::npos) << convert;
  const std::string bake = test::run_cli({"bake", "--help"}).out;
  EXPECT_NE(bake.find("latlong, cube, cross, octahedral, equal-area (default latlong)"), std::string::npos)
      << bake;
  EXPECT_NE(bake.find("in [8, 2048] (default 256)"), std::string::npos) << bake;
  EXPECT_NE(bake.find("exr, ktx2 (default ktx2)"), std::string::npos) << bake;
}

TEST(CliUsage, MistakesAreBadRequestsWithExitStatusTwo) {
  const test::TempDir dir;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"paint"},
       "unknown command 'paint' (expected one of: info, sample, median-cut, fresnel, render, convert, sh, "
       "brdf-lut, sun, bake, denoise)"},
      {{"info"}, "usage: lightprobe info MAP|MODEL [options] (see --help)"},
      {{"info", "a.exr", "b.exr"}, "usage: lightprobe info MAP|MODEL [options] (see --help)"},
      {{"info", "default", "--colour", "red"}, "unknown option '--colour' (see lightprobe info --help)"},
      {{"info", "default", "-x"}, "unknown option '-x'"},
      {{"sample", "default", "--count"}, "--count needs a value"},
      {{"sample", "default", "--count", "1", "--count", "2"}, "--count is given more than once"},
      {{"render", "scene.json", "--quiet=yes"}, "--quiet takes no value"},
      {{"convert", "in.exr"}, "usage: lightprobe convert IN OUT [options] (see --help)"},
      {{"denoise"},
       "usage: lightprobe denoise COLOR -o OUT [--albedo A] [--normal N] [--ldr] [options] (see --help)"},
  };
  for (const auto& [args, message] : cases) {
    const test::CliRun run = test::run_cli(args, dir.path());
    EXPECT_EQ(run.exit_status, 2) << message;
    EXPECT_EQ(run.err, "error: bad_request: " + message + "\n");
    EXPECT_EQ(run.out, "");
  }
  const test::CliRun nothing = test::run_cli({});
  EXPECT_EQ(nothing.exit_status, 2);
  EXPECT_EQ(nothing.err.rfind("lightprobe: ", 0), 0u);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// A result that cannot be written is a failure of the run, not of the input: exit status 1.
TEST(CliUsage, AnUnwritableOutputIsWriteFailed) {
  const test::CliRun run = test::run_cli({"info", "default", "-o", "/proc/lightprobe-cannot-write.json"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_EQ(run.err.rfind("error: write_failed: cannot create '/proc/lightprobe-cannot-write.json': ", 0), 0u)
      << run.err;
}

TEST(CliUsage, VersionIsTheProjects) {
  const test::CliRun run = test::run_cli({"--version"});
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_EQ(run.out, std::string("lightprobe ") + LIGHTPROBE_VERSION + "\n");
}

}  // namespace
}  // namespace lp
