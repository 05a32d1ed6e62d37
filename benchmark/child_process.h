// Runs a function in a forked child process with a time limit; what it
// returns comes back through a pipe. The benchmark's scaling runs use it, so
// that each run's peak memory is its own process's and a run over the limit
// can be killed.
#ifndef CUT_PARAM_BENCHMARK_CHILD_PROCESS_H
#define CUT_PARAM_BENCHMARK_CHILD_PROCESS_H

#include <functional>
#include <string>

namespace cut_benchmark {

struct Child_result
{
  enum Kind { EXITED, SIGNALED, TIMED_OUT, NOT_STARTED } kind = NOT_STARTED;
  int code = 0;        // exit status (3: the function threw) or signal number
  std::string output;  // what the function returned
  double seconds = 0.; // wall time of the child
};

/// Forks; the child runs `task` and exits (with _exit(), no static
/// destructors) after writing its result to the pipe. The parent waits at
/// most `time_limit` seconds, then kills the child (SIGKILL).
Child_result run_forked(const std::function<std::string()>& task, double time_limit);

/// The maximum resident set size of this process so far, in KiB (getrusage).
long peak_resident_kib();

} // namespace cut_benchmark

#endif
