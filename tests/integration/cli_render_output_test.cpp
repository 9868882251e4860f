// Where `lightprobe render` writes, and what it says meanwhile, with the real tool: no image onto a
// terminal, a missing output folder refused before any rendering, and progress on standard error (a bar
// on a terminal, a line at each 10% elsewhere) with the rate and the time left.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/png_pixels.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

// `lightprobe render quad.glb` at 16 x 16 pixels, 1 sample each unless `options` say more.
std::vector<std::string> model_render(const std::vector<std::string>& options) {
  std::vector<std::string> args = {"render", test::model_path("quad.glb").string(), "--height", "16"};
  for (const std::string option : {"--width", "--spp"})
    if (std::find(options.begin(), options.end(), option) == options.end())
      args.insert(args.end(), {option, option == "--width" ? "16" : "1"});
  args.insert(args.end(), options.begin(), options.end());
  return args;
}

TEST(CliRenderOutput, AnImageIsNotWrittenOntoATerminal) {
  const test::CliRun refused = test::run_cli_on_terminal(model_render({}), test::Terminal::Stdout);
  EXPECT_EQ(refused.exit_status, 2);
  EXPECT_EQ(refused.out, "");
  EXPECT_EQ(refused.err,
            "error: bad_request: standard output is a terminal: give -o FILE, or redirect standard output to "
            "a file or a pipe (-o - writes the image to the terminal anyway)\n");
  // Piped, the same command writes the image.
  const test::CliRun piped = test::run_cli(model_render({"-q"}));
  ASSERT_EQ(piped.exit_status, 0) << piped.err;
  const test::PngPixels png =
      test::decode_png(std::span(reinterpret_cast<const uint8_t*>(piped.out.data()), piped.out.size()));
  EXPECT_EQ(png.width, 16);
}

// Refused at once: nothing rendered (no progress line), no file left.
TEST(CliRenderOutput, AMissingOutputFolderIsRefusedBeforeRendering) {
  const test::TempDir dir;
  const std::string missing = "not_found: the output folder '";
  test::expect_cli_refusals(
      model_render({}),
      {{{"-o", "missing/thumb.png"}, missing + "missing' does not exist"},
       {{"--turntable", "2", "-o", "frames/"}, missing + "frames/' does not exist"},
       {{"--turntable", "2", "-o", "missing/frames"}, missing + "missing/frames' does not exist"}},
      dir.path());
}

// Lines at 10%, 20%, ... 100% and nothing else, each with the rate and the time left (the last, the time
// taken); a turntable's name the frame being rendered.
TEST(CliRenderOutput, ProgressElsewhereThanATerminalIsALineAtEachTenth) {
  const test::TempDir dir;
  const std::regex line(
      R"(render( frame ([1-4])/4)? (\d+)%  \d+(\.\d+)?[kMG]? samples/s  (ETA|in) \d+:\d\d)");
  for (const bool turntable : {false, true}) {
    SCOPED_TRACE(turntable);
    const test::CliRun run = test::run_cli(
        model_render(turntable ? std::vector<std::string>{"--turntable", "4", "-o", "."}
                               : std::vector<std::string>{"--width", "64", "--spp", "4", "-o", "a.png"}),
        dir.path());
    ASSERT_EQ(run.exit_status, 0) << run.err;
    std::vector<int> percents;
    int last_frame = 1;
    for (size_t start = 0; start < run.err.size();) {
      const size_t end = run.err.find('\n', start);
      ASSERT_NE(end, std::string::npos) << "an unfinished line: " << run.err.substr(start);
      const std::string text = run.err.substr(start, end - start);
      std::smatch m;
      ASSERT_TRUE(std::regex_match(text, m, line)) << text;
      EXPECT_EQ(m[1].matched, turntable) << text;
      if (turntable) {
        EXPECT_GE(std::stoi(m[2]), last_frame) << text;
        last_frame = std::stoi(m[2]);
      }
      percents.push_back(std::stoi(m[3]));
      EXPECT_EQ(m[5], percents.back() == 100 ? "in" : "ETA") << text;
      start = end + 1;
    }
    EXPECT_EQ(percents, (std::vector<int>{10, 20, 30, 40, 50, 60, 70, 80, 90, 100}));
    if (turntable) {
      EXPECT_EQ(last_frame, 4);
    }
  }
}

// On a terminal, one bar redrawn in place (carriage returns, no new line until it is full), with the
// rate and the time left.
TEST(CliRenderOutput, ProgressOnATerminalIsABar) {
  const test::TempDir dir;
  const test::CliRun run = test::run_cli_on_terminal(model_render({"--width", "64", "-o", "a.png"}),
                                                     test::Terminal::Stderr, dir.path());
  ASSERT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.err.rfind("\rrender [", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  EXPECT_TRUE(std::regex_search(run.err, std::regex(R"(\] 100%  \d+(\.\d+)?[kMG]? samples/s  in \d+:\d\d)")))
      << run.err;
  EXPECT_NE(run.err.find("ETA "), std::string::npos) << run.err;
}

}  // namespace
}  // namespace lp
