#include "visors/mc/local_pool.hpp"

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

// Starts children for queued runs while fewer than `workers` run.
core::Result<bool> fill(const Campaign& campaign, const PoolOptions& options, const std::function<std::optional<std::int64_t>()>& next,
                        std::vector<Child>& children) {
  while (static_cast<int>(children.size()) < std::max(1, options.workers)) {
    const auto index = next();
    if (!index) return true;
    auto child = start(campaign, run_spec(campaign, *index), options);
    if (!child.ok()) return child.error();
    fcntl(child->fd, F_SETFL, O_NONBLOCK);
    children.push_back(std::move(child).value());
  }
  return true;
}

// One pass over the children: stops those past their time limit, collects those that ended.
core::Result<bool> collect(const Campaign& campaign, std::vector<Child>& children, const std::vector<pollfd>& fds,
                           const std::function<core::Result<bool>(const RunSpec&, const RunRecord&)>& finished) {
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
    if (auto ok = finished(spec, record); !ok) return ok;
  }
  return true;
}

std::vector<pollfd> wait_for_children(const std::vector<Child>& children, int timeout_ms) {
  std::vector<pollfd> fds;
  for (const Child& c : children) fds.push_back(pollfd{c.fd, POLLIN, 0});
  (void)poll(fds.data(), fds.size(), timeout_ms);
  return fds;
}

}  // namespace

RunRecord run_isolated(const Campaign& campaign, const RunSpec& spec, const PoolOptions& options) {
  std::vector<Child> children;
  bool given = false;
  const auto next = [&]() -> std::optional<std::int64_t> {
    if (given) return std::nullopt;
    given = true;
    return spec.index;
  };
  RunRecord out;
  out.run = spec.index;
  if (auto ok = fill(campaign, options, next, children); !ok) {
    out.error = ok.error().describe();
    return out;
  }
  while (!children.empty()) {
    const auto fds = wait_for_children(children, 200);
    (void)collect(campaign, children, fds, [&](const RunSpec&, const RunRecord& r) -> core::Result<bool> {
      out = r;
      return true;
    });
  }
  return out;
}

core::Result<bool> run_local(const Campaign& campaign, const std::vector<std::int64_t>& runs, const PoolOptions& options,
                             const RunSink& on_finished, const std::function<void(const PoolProgress&)>& progress,
                             RemoteWorkers* remote) {
  const auto t0 = Clock::now();
  PoolProgress p;
  p.total = static_cast<std::int64_t>(runs.size());
  std::vector<Child> children;
  std::size_t queued = 0;
  const auto next = [&]() -> std::optional<std::int64_t> {
    if (queued == runs.size()) return std::nullopt;
    return runs[queued++];
  };
  const auto finished = [&](const RunSpec& spec, const RunRecord& record) -> core::Result<bool> {
    ++p.finished;
    if (!record.ok) ++p.failed;
    return on_finished(spec, record);
  };
  const auto stop = [&](const core::Error& e) -> core::Result<bool> {
    kill_all(children);
    if (remote != nullptr) remote->finish();
    return e;
  };
  auto last_report = t0;
  for (;;) {
    if (auto ok = fill(campaign, options, next, children); !ok) return stop(ok.error());
    if (remote != nullptr) {
      const auto done = [&](const RunRecord& r) { return finished(run_spec(campaign, r.run), r); };
      if (auto ok = remote->serve(next, done); !ok) return stop(ok.error());
    }
    const std::int64_t away = remote != nullptr ? remote->outstanding() : 0;
    if (children.empty() && away == 0 && queued == runs.size()) break;
    // Short waits while remote ranks may be asking: their requests are answered between polls.
    const auto fds = wait_for_children(children, remote != nullptr ? 5 : 200);
    if (auto ok = collect(campaign, children, fds, finished); !ok) return stop(ok.error());
    p.running = static_cast<std::int64_t>(children.size()) + away;
    p.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (progress && Clock::now() - last_report > std::chrono::seconds(1)) {
      progress(p);
      last_report = Clock::now();
    }
  }
  if (remote != nullptr) remote->finish();
  if (progress) progress(p);
  return true;
}

}  // namespace visors::mc
