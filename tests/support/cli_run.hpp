#pragma once
// Runs the real lightprobe command-line tool (build/bin/lightprobe) and collects what it did.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "api/params.hpp"

namespace lp::test {

struct CliRun {
  int exit_status = 0;  // -N if signal N ended it
  std::string out;      // standard output, byte for byte
  std::string err;      // standard error
};

// `lightprobe args...`, run without a shell in `cwd` (default: the test's working directory), to its end.
CliRun run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd = {});

// Which of the tool's outputs is a terminal in run_cli_on_terminal.
enum class Terminal { Stdout, Stderr };

// As run_cli, but `which` is the slave of a pseudo-terminal (raw mode: bytes pass unchanged) whose
// master the test reads into `out` or `err`.
CliRun run_cli_on_terminal(const std::vector<std::string>& args, Terminal which,
                           const std::filesystem::path& cwd = {});

// Options appended to a command, and the "CODE: MESSAGE" it must fail with.
using CliRefusals = std::vector<std::pair<std::vector<std::string>, std::string>>;
// Runs `command` + each case's options in `dir` and expects exit status 2 with that error line, nothing
// on standard output, and `dir` left empty (gtest expectations).
void expect_cli_refusals(const std::vector<std::string>& command, const CliRefusals& cases,
                         const std::filesystem::path& dir);

// The {"error":{"code":...,"message":...}} the API answers, as the tool prints it: "error: CODE: MESSAGE\n".
std::string cli_error_line(const api::Json& api_error_body);

}  // namespace lp::test
