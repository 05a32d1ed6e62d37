#include "child_process.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cut_benchmark {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Waits for `pid` for at most `time_limit` seconds, reading `fd` as it goes;
// kills the child on timeout.
Child_result wait_for(pid_t pid, int fd, double time_limit, Clock::time_point start)
{
  Child_result r;
  char buffer[4096];
  bool open = true;
  for(;;)
  {
    if(open)
    {
      pollfd p{fd, POLLIN, 0};
      if(poll(&p, 1, 20) > 0)
      {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if(n > 0) r.output.append(buffer, std::size_t(n));
        else if(n == 0 || errno != EINTR) open = false;
      }
    }
    else
      usleep(20000);
    int status = 0;
    if(waitpid(pid, &status, WNOHANG) == pid)
    {
      while(open)
      {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if(n > 0) r.output.append(buffer, std::size_t(n));
        else open = false;
      }
      r.seconds = seconds_since(start);
      if(WIFSIGNALED(status)) { r.kind = Child_result::SIGNALED; r.code = WTERMSIG(status); }
      else { r.kind = Child_result::EXITED; r.code = WEXITSTATUS(status); }
      break;
    }
    if(seconds_since(start) > time_limit)
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.kind = Child_result::TIMED_OUT;
      r.seconds = seconds_since(start);
      break;
    }
  }
  close(fd);
  return r;
}

} // namespace

Child_result run_forked(const std::function<std::string()>& task, double time_limit)
{
  int fds[2];
  if(pipe(fds) != 0) return {};
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const auto start = Clock::now();
  const pid_t pid = fork();
  if(pid < 0) { close(fds[0]); close(fds[1]); return {}; }
  if(pid == 0)
  {
    close(fds[0]);
    std::string message;
    int code = 0;
    try { message = task(); }
    catch(const std::exception& e) { message = e.what(); code = 3; }
    catch(...) { code = 3; }
    const char* p = message.data();
    std::size_t left = message.size();
    while(left > 0)
    {
      const ssize_t n = write(fds[1], p, left);
      if(n < 0 && errno == EINTR) continue;
      if(n <= 0) break;
      p += n;
      left -= std::size_t(n);
    }
    close(fds[1]);
    std::cout.flush();
    std::cerr.flush();
    _exit(code);
  }
  close(fds[1]);
  return wait_for(pid, fds[0], time_limit, start);
}

long peak_resident_kib()
{
  rusage usage{};
  if(getrusage(RUSAGE_SELF, &usage) != 0) return -1;
  return usage.ru_maxrss; // KiB on Linux
}

} // namespace cut_benchmark
