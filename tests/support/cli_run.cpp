#include "support/cli_run.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/wait.h>
#include <termios.h>
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

std::string read_file_text(const std::filesystem::path& path) {
  const auto bytes = read_bytes(path);
  return {bytes.begin(), bytes.end()};
}

// Everything written to the pseudo-terminal until every slave is closed (read() then fails with EIO).
std::string read_terminal(int master) {
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = read(master, buffer, sizeof buffer)) > 0;) text.append(buffer, size_t(n));
  return text;
}

}  // namespace

CliRun run_cli_on_terminal(const std::vector<std::string>& args, Terminal which,
                           const std::filesystem::path& cwd) {
  int master = -1, slave = -1;
  termios raw{};
  cfmakeraw(&raw);
  if (openpty(&master, &slave, nullptr, &raw, nullptr) != 0) throw std::runtime_error("openpty failed");
  const TempDir capture;
  const int file = open_output(capture.path() / "file");
  std::vector<std::string> argv = {LIGHTPROBE_CLI_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  const bool on_stdout = which == Terminal::Stdout;
  const int pid = start_process(argv, on_stdout ? slave : file, on_stdout ? file : slave, cwd);
  close(slave);
  close(file);
  const std::string terminal = read_terminal(master);
  close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  CliRun run;
  run.exit_status = exit_status_of(status);
  (on_stdout ? run.out : run.err) = terminal;
  (on_stdout ? run.err : run.out) = read_file_text(capture.path() / "file");
  return run;
}

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
  run.out = read_file_text(capture.path() / "out");
  run.err = read_file_text(capture.path() / "err");
  return run;
}

void expect_cli_refusals(const std::vector<std::string>& command, const CliRefusals& cases,
                         const std::filesystem::path& dir) {
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args = command;
    args.insert(args.end(), options.begin(), options.end());
    const CliRun run = run_cli(args, dir);
    EXPECT_EQ(run.exit_status, 2) << message;
    EXPECT_EQ(run.err, "error: " + message + "\n");
    EXPECT_EQ(run.out, "") << message;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

std::string cli_error_line(const api::Json& api_error_body) {
  const api::Json& e = api_error_body.at("error");
  return "error: " + e.at("code").get<std::string>() + ": " + e.at("message").get<std::string>() + "\n";
}

}  // namespace lp::test
