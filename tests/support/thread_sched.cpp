#include "support/thread_sched.hpp"

#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace lp::test {
namespace {

// Field 19 of a stat line is the nice value and field 41 the policy; the name (field 2) may hold spaces,
// so the fields are counted after its closing parenthesis.
ThreadSched thread_sched(const std::filesystem::path& stat) {
  std::ifstream in(stat);
  std::string line;
  std::getline(in, line);
  std::istringstream fields(line.substr(line.rfind(')') + 2));
  std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
  return {std::stoi(f.at(19 - 3)), std::stoi(f.at(41 - 3))};
}

int count(const std::vector<ThreadSched>& threads, ThreadSched sched) {
  return int(std::count(threads.begin(), threads.end(), sched));
}

}  // namespace

ProcessThreads threads_of(int pid) {
  const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
  ProcessThreads out{thread_sched(tasks / std::to_string(pid) / "stat"), {}};
  for (const auto& task : std::filesystem::directory_iterator(tasks)) {
    try {
      out.all.push_back(thread_sched(task.path() / "stat"));
    } catch (const std::exception&) {  // the thread ended while it was read
    }
  }
  return out;
}

void expect_render_threads_at(const ProcessThreads& threads, ThreadSched render, int renderers) {
  EXPECT_EQ(threads.main.policy, SCHED_OTHER);
  const int at_render = count(threads.all, render);
  const int at_main = count(threads.all, threads.main);
  EXPECT_GE(at_render, renderers);
  EXPECT_GE(at_main, 1);
  EXPECT_EQ(render == threads.main ? at_main : at_render + at_main, int(threads.all.size()));
}

}  // namespace lp::test
