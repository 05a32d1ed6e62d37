// Running work in a child process with a time limit (POSIX), for the tools
// and the benchmark: a crash, a hang or a memory peak stays in the child.
//   run_forked(task, limit): forks; the child runs `task` (a function
//     returning a string) and sends the string back through a pipe;
//   run_program(args, log, limit): runs a program, output to `log`.
// On timeout the child (and its process group, if it has one) is killed.
#ifndef CUT_PARAM_TOOLS_CHILD_PROCESS_H
#define CUT_PARAM_TOOLS_CHILD_PROCESS_H

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cut_tools {

struct Child_result
{
  enum Kind { EXITED, SIGNALED, TIMED_OUT, NOT_STARTED } kind = NOT_STARTED;
  int code = 0;        // exit status (3: the task threw) or signal number
  std::string output;  // what the task returned (after a throw: "EXCEPTION " and its message)
  double seconds = 0.; // wall time of the child
};

namespace child_process_detail {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

inline void flush_all()
{
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
}

// Waits for `pid` for at most `timeout` seconds, reading `fd` (if >= 0) as
// it goes; kills the child (and its process group) on timeout.
inline Child_result wait_for(pid_t pid, int fd, double timeout, Clock::time_point start)
{
  Child_result r;
  char buffer[4096];
  bool open = fd >= 0;
  auto drain = [&] {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if(n > 0) r.output.append(buffer, std::size_t(n));
    else if(n == 0 || errno != EINTR) open = false;
  };
  for(;;)
  {
    if(open)
    {
      pollfd p{fd, POLLIN, 0};
      if(poll(&p, 1, 20) > 0) drain();
    }
    else
      usleep(20000);
    int status = 0;
    if(waitpid(pid, &status, WNOHANG) == pid)
    {
      while(open) drain();
      r.seconds = seconds_since(start);
      if(WIFSIGNALED(status)) { r.kind = Child_result::SIGNALED; r.code = WTERMSIG(status); }
      else { r.kind = Child_result::EXITED; r.code = WEXITSTATUS(status); }
      break;
    }
    if(seconds_since(start) > timeout)
    {
      kill(-pid, SIGKILL); // its group, if the child made one
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.kind = Child_result::TIMED_OUT;
      r.seconds = seconds_since(start);
      break;
    }
  }
  if(fd >= 0) close(fd);
  return r;
}

} // namespace child_process_detail

/// Forks; the child runs `task` (returning std::string) and exits with
/// _exit() (no static destructors) after writing the string to a pipe. The
/// child stays in the caller's process group, so that Ctrl-C stops it too.
template <typename Task>
Child_result run_forked(Task task, double timeout)
{
  namespace d = child_process_detail;
  int fds[2];
  if(pipe(fds) != 0) return {};
  d::flush_all();
  const auto start = d::Clock::now();
  const pid_t pid = fork();
  if(pid < 0) { close(fds[0]); close(fds[1]); return {}; }
  if(pid == 0)
  {
    close(fds[0]);
    std::string message;
    int code = 0;
    try { message = task(); }
    catch(const std::exception& e) { message = std::string("EXCEPTION ") + e.what(); code = 3; }
    catch(...) { message = "EXCEPTION"; code = 3; }
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
    d::flush_all();
    _exit(code);
  }
  close(fds[1]);
  return d::wait_for(pid, fds[0], timeout, start);
}

/// Runs the program args[0] with arguments args[1..], its standard output and
/// error in the file `log`, in a process group of its own (killed as a whole
/// on timeout). Exit status 127: it could not be started.
inline Child_result run_program(const std::vector<std::string>& args, const std::string& log, double timeout)
{
  namespace d = child_process_detail;
  d::flush_all();
  const auto start = d::Clock::now();
  const pid_t pid = fork();
  if(pid < 0) return {};
  if(pid == 0)
  {
    setpgid(0, 0);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if(fd >= 0) { dup2(fd, 1); dup2(fd, 2); close(fd); }
    std::vector<char*> argv;
    for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return d::wait_for(pid, -1, timeout, start);
}

} // namespace cut_tools

#endif
