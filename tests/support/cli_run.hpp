#pragma once
// Runs the real lightprobe command-line tool (build/bin/lightprobe) and collects what it did.
#include <filesystem>
#include <string>
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

// The {"error":{"code":...,"message":...}} the API answers, as the tool prints it: "error: CODE: MESSAGE\n".
std::string cli_error_line(const api::Json& api_error_body);

}  // namespace lp::test
