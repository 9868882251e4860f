#include "support/cli_run.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

#include "support/child_process.hpp"
#include "support/temp_dir.hpp"
#include "support/test_data.hpp"

namespace lp::test {
namespace {

int open_output(const std::filesystem::path& path) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (fd < 0) throw std::runtime_error("cannot create " + path.string());
  return fd;
}

}  // namespace

CliRun run_cli(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  const TempDir capture;
  const int out = open_output(capture.path() / "out"), err = open_output(capture.path() / "err");
  std::vector<std::string> argv = {LIGHTPROBE_CLI_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  const int pid = start_process(argv, out, err, cwd);
  close(out);
  close(err);
  int status = 0;
  waitpid(pid, &status, 0);
  CliRun run;
  run.exit_status = exit_status_of(status);
  const auto out_bytes = read_bytes(capture.path() / "out"), err_bytes = read_bytes(capture.path() / "err");
  run.out.assign(out_bytes.begin(), out_bytes.end());
  run.err.assign(err_bytes.begin(), err_bytes.end());
  return run;
}

std::string cli_error_line(const api::Json& api_error_body) {
  const api::Json& e = api_error_body.at("error");
  return "error: " + e.at("code").get<std::string>() + ": " + e.at("message").get<std::string>() + "\n";
}

}  // namespace lp::test
