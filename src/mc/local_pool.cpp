#include "mc/local_pool.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

namespace visors::mc {
namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  pid_t pid = -1;
  int fd = -1;
  RunSpec spec;
  std::string output;
  Clock::time_point start;
  bool timed_out = false;
};

// In the child: runs one run, writes its record to `fd`, exits without unwinding the parent's
// state (no destructors, no atexit handlers of the parent's copy).
[[noreturn]] void child_main(const Campaign& campaign, const RunSpec& spec, const PoolOptions& options, int fd,
                             pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(3);  // the parent died before the line above
  const RunRecord record = execute_run(campaign, spec, options.scratch, options.keep_runs);
  const std::string text = to_json_text(record);
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(4);
    done += static_cast<std::size_t>(n);
  }
  _exit(0);
}

core::Result<Child> start(const Campaign& campaign, const RunSpec& spec, const PoolOptions& options) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return core::Error{"mc", std::string("pipe: ") + std::strerror(errno)};
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return core::Error{"mc", std::string("fork: ") + std::strerror(errno)};
  }
  if (pid == 0) {
    close(fds[0]);
    child_main(campaign, spec, options, fds[1], parent);
  }
  close(fds[1]);
  Child c;
  c.pid = pid;
  c.fd = fds[0];
  c.spec = spec;
  c.start = Clock::now();
  return c;
}

// The record of a child whose pipe reached end of file, after reaping it.
RunRecord finish(Child& c, double time_limit_s) {
  close(c.fd);
  int status = 0;
  while (waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
  }
  const double wall = std::chrono::duration<double>(Clock::now() - c.start).count();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    if (auto record = run_record_from_json_text(c.output); record.ok()) return *record;
  }
  RunRecord r;
  r.run = c.spec.index;
  r.wall_s = wall;
  if (c.timed_out) {
    r.error = fmt::format("time limit exceeded ({} s)", time_limit_s);
  } else if (WIFSIGNALED(status)) {
    r.error = fmt::format("crashed: signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  } else {
    r.error = fmt::format("exited with status {} without a result", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  return r;
}

// Reads what is available; true at end of file.
bool drain(Child& c) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(c.fd, buffer, sizeof buffer);
    if (n > 0) {
      c.output.append(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0) return true;
    if (errno == EINTR) continue;
    return errno != EAGAIN;
  }
}

void kill_all(std::vector<Child>& children) {
  for (Child& c : children) {
    kill(c.pid, SIGKILL);
    close(c.fd);
    waitpid(c.pid, nullptr, 0);
  }
  children.clear();
}

}  // namespace

core::Result<bool> run_local(const Campaign& campaign, const std::vector<std::int64_t>& runs, const PoolOptions& options,
                             const RunSink& on_finished, const std::function<void(const PoolProgress&)>& progress) {
  const auto t0 = Clock::now();
  const int workers = std::max(1, options.workers);
  PoolProgress p;
  p.total = static_cast<std::int64_t>(runs.size());
  std::vector<Child> children;
  std::size_t next = 0;
  auto last_report = t0;
  while (next < runs.size() || !children.empty()) {
    while (static_cast<int>(children.size()) < workers && next < runs.size()) {
      auto child = start(campaign, run_spec(campaign, runs[next]), options);
      if (!child.ok()) {
        kill_all(children);
        return child.error();
      }
      fcntl(child->fd, F_SETFL, O_NONBLOCK);
      children.push_back(std::move(child).value());
      ++next;
    }
    std::vector<pollfd> fds;
    for (const Child& c : children) fds.push_back(pollfd{c.fd, POLLIN, 0});
    (void)poll(fds.data(), fds.size(), 200);
    const auto now = Clock::now();
    for (std::size_t i = children.size(); i-- > 0;) {
      Child& c = children[i];
      if (!c.timed_out && std::chrono::duration<double>(now - c.start).count() > campaign.time_limit_s) {
        kill(c.pid, SIGKILL);  // its pipe then reaches end of file
        c.timed_out = true;
      }
      if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) == 0 || !drain(c)) continue;
      const RunRecord record = finish(c, campaign.time_limit_s);
      const RunSpec spec = c.spec;
      children.erase(children.begin() + static_cast<std::ptrdiff_t>(i));
      ++p.finished;
      if (!record.ok) ++p.failed;
      if (auto ok = on_finished(spec, record); !ok) {
        kill_all(children);
        return ok.error();
      }
      last_report = {};  // report this one
    }
    p.running = static_cast<std::int64_t>(children.size());
    p.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (progress && Clock::now() - last_report > std::chrono::seconds(1)) {
      progress(p);
      last_report = Clock::now();
    }
  }
  if (progress) progress(p);
  return true;
}

}  // namespace visors::mc
