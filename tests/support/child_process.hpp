#pragma once
// Starting a program of ours as a child process, its output going to files the test reads.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace lp::test {

// Environment variables (name, value) a child gets on top of this process's environment.
using Variables = std::vector<std::pair<std::string, std::string>>;

// Runs argv[0] (a path) with `argv` and no shell, its standard output and error written to the open file
// descriptors given (they may be one), in `cwd` unless empty, with this process's environment and
// `variables` (replacing variables of the same name). Returns the child's pid.
int start_process(const std::vector<std::string>& argv, int stdout_fd, int stderr_fd,
                  const std::filesystem::path& cwd = {}, const Variables& variables = {});

// A waitpid status as the tests report it: the exit status, or -N if signal N ended the process.
int exit_status_of(int wait_status);

}  // namespace lp::test
