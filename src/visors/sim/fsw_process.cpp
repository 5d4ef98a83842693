#include "visors/sim/fsw_process.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

extern char** environ;

namespace visors::sim {
namespace {

// The output slot of a record's channel, or null for a channel that is no output.
gnc::OutputRecords::Record* output_slot(gnc::OutputRecords& out, std::span<const std::uint8_t> record) {
  const auto channel = gnc::channel_of(record);
  if (!channel) return nullptr;
  switch (*channel) {
    case gnc::Channel::kManeuver: return &out.maneuver;
    case gnc::Channel::kObservation: return &out.observation;
    case gnc::Channel::kCrosslink: return &out.crosslink;
    case gnc::Channel::kTelemetry: return &out.telemetry;
    case gnc::Channel::kNavigationTelemetry: return &out.navigation;
    default: return nullptr;
  }
}

std::string last_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

// Spawns argv with stdin/stdout on the pipes' child ends and stderr on `log`. The pipes are
// close-on-exec, so the child keeps only the ends dup2 gives it (and a second child none of the
// first's: each sees the end of its input when the host closes it).
core::Result<pid_t> spawn(const std::vector<std::string>& argv, int child_in, int child_out, const std::filesystem::path& log) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, child_in, STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, child_out, STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int error = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) return core::Error{"", fmt::format("cannot start '{}': {}", argv[0], std::strerror(error))};
  return pid;
}

}  // namespace

core::Result<FswProcess> FswProcess::start(const std::vector<std::string>& command, const std::filesystem::path& config,
                                           std::string_view craft, const std::filesystem::path& log, int ready_timeout_ms) {
  FswProcess p;
  p.name_ = fmt::format("fsw.{}", craft);
  p.log_ = log;
  if (command.empty()) return core::Error{p.name_, "no command to start the flight software with"};
  std::signal(SIGPIPE, SIG_IGN);  // a process that stopped is an error of send(), not the host's end
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) return core::Error{p.name_, "cannot create a pipe"};
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    return core::Error{p.name_, "cannot create a pipe"};
  }
  std::vector<std::string> argv = command;
  argv.insert(argv.end(), {"--config", config.string(), "--craft", std::string(craft)});
  auto pid = spawn(argv, in[0], out[1], log);
  ::close(in[0]);
  ::close(out[1]);
  p.to_fsw_ = in[1];
  p.from_fsw_ = out[0];
  if (!pid.ok()) return core::Error{p.name_, pid.error().message};
  p.pid_ = pid.value();
  p.writer_ = std::make_unique<gnc::FrameWriter>(p.to_fsw_);
  p.reader_ = std::make_unique<gnc::FrameReader>(p.from_fsw_);
  p.frame_ = std::make_unique<gnc::RecordBuffer>();
  gnc::OutputRecords ready;
  if (auto ok = p.receive(ready, ready_timeout_ms); !ok) return ok.error();
  return p;
}

FswProcess::FswProcess(FswProcess&& other) noexcept { *this = std::move(other); }

FswProcess& FswProcess::operator=(FswProcess&& other) noexcept {
  if (this != &other) {
    stop();
    name_ = std::move(other.name_);
    log_ = std::move(other.log_);
    pid_ = std::exchange(other.pid_, -1);
    to_fsw_ = std::exchange(other.to_fsw_, -1);
    from_fsw_ = std::exchange(other.from_fsw_, -1);
    writer_ = std::move(other.writer_);
    reader_ = std::move(other.reader_);
    frame_ = std::move(other.frame_);
  }
  return *this;
}

FswProcess::~FswProcess() { stop(); }

// Closes its input (it ends at the end of its stream) and waits for it.
void FswProcess::stop() {
  if (to_fsw_ >= 0) ::close(std::exchange(to_fsw_, -1));
  if (from_fsw_ >= 0) ::close(std::exchange(from_fsw_, -1));
  if (pid_ > 0) {
    int status = 0;
    ::waitpid(std::exchange(pid_, -1), &status, 0);
  }
}

core::Error FswProcess::failure(std::string_view what) {
  std::string ended;
  if (pid_ > 0) {
    // A process that closed its output is ending: its status within 2 s, else it is killed (it
    // stopped answering).
    int status = 0;
    pid_t done = 0;
    for (int i = 0; i < 200 && (done = ::waitpid(pid_, &status, WNOHANG)) == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (done == 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
      ended = "killed";
    } else if (WIFEXITED(status)) {
      ended = fmt::format("exit status {}", WEXITSTATUS(status));
    } else if (WIFSIGNALED(status)) {
      ended = fmt::format("ended by signal {}", WTERMSIG(status));
    }
    pid_ = -1;
  }
  const std::string line = last_line(log_);
  return core::Error{name_, fmt::format("{} ({}; its log {}{}{})", what, ended, log_.string(), line.empty() ? "" : ": ", line)};
}

core::Result<bool> FswProcess::send(std::span<const gnc::RecordView> records) {
  for (const gnc::RecordView record : records) {
    if (!writer_->record(record)) return failure("the flight software stopped reading its records");
  }
  if (!writer_->end_batch()) return failure("the flight software stopped reading its records");
  return true;
}

core::Result<bool> FswProcess::receive(gnc::OutputRecords& out, int timeout_ms) {
  out.maneuver.size = out.observation.size = out.crosslink.size = out.telemetry.size = out.navigation.size = 0;
  for (;;) {
    std::size_t size = 0;
    switch (reader_->next(*frame_, size, timeout_ms)) {
      case gnc::FrameStatus::kEndOfBatch: return true;
      case gnc::FrameStatus::kRecord: break;
      case gnc::FrameStatus::kTooLong: return failure("the flight software wrote a frame longer than any record");
      case gnc::FrameStatus::kEndOfStream:
      case gnc::FrameStatus::kBroken:
        return failure(fmt::format("the flight software stopped or did not answer within {} s", timeout_ms / 1000));
    }
    const std::span<const std::uint8_t> record(frame_->data(), size);
    gnc::OutputRecords::Record* slot = output_slot(out, record);
    if (slot == nullptr) return failure("the flight software wrote a record of no output channel");
    if (slot->size != 0) return failure("the flight software wrote two records of one output channel in a step");
    std::copy(record.begin(), record.end(), slot->bytes.begin());
    slot->size = size;
  }
}

}  // namespace visors::sim
