#pragma once
// Figures of a running process from /proc/PID/status, for tests that bound what a request costs.
namespace lp::test {

// Peak resident memory (VmHWM) of process `pid`, in MiB; -1 if it cannot be read.
double peak_rss_mib(int pid);

}  // namespace lp::test
