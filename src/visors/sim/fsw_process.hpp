#pragma once
// One visors-fsw process as the host drives it (apps/fsw/main.cpp,
// docs/flight-software-process.md): started from its command (the program, or an emulator and the
// program: "qemu-arm -L /usr/arm-linux-gnueabihf build-cross/armhf/apps/fsw/visors-fsw"), with the
// run's flight configuration file and its spacecraft; a step's records written to its standard
// input as one batch, the step's output records read back from its standard output
// (gnc/record_stream.hpp), its standard error kept in a log file. Ground side (POSIX processes).
//
// Errors name the spacecraft ("fsw.dsc") and say what happened: the process could not start,
// stopped (its exit status and the last line of its log), broke the stream, or did not answer
// within the timeout (it is then killed). The process ends when this object does: its input is
// closed, and it is waited for.

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

#include "visors/core/result.hpp"
#include "visors/gnc/record_interface.hpp"
#include "visors/gnc/record_stream.hpp"

namespace visors::sim {

class FswProcess {
 public:
  /// Starts `command` + "--config <config> --craft <craft>" and waits for its ready batch.
  static core::Result<FswProcess> start(const std::vector<std::string>& command, const std::filesystem::path& config,
                                        std::string_view craft, const std::filesystem::path& log, int ready_timeout_ms);
  FswProcess(FswProcess&& other) noexcept;
  FswProcess& operator=(FswProcess&& other) noexcept;
  FswProcess(const FswProcess&) = delete;
  FswProcess& operator=(const FswProcess&) = delete;
  ~FswProcess();

  /// Writes one step's input records as a batch.
  core::Result<bool> send(std::span<const gnc::RecordView> records);
  /// Reads the step's output records into `out` by their channel (a channel without a record:
  /// size 0). An output of no output channel, or two of one, is an error.
  core::Result<bool> receive(gnc::OutputRecords& out, int timeout_ms);

 private:
  FswProcess() = default;
  /// What went wrong, with the process's exit status and its log's last line once it ended.
  core::Error failure(std::string_view what);
  void stop();

  std::string name_;  // "fsw.dsc"
  std::filesystem::path log_;
  pid_t pid_ = -1;
  int to_fsw_ = -1, from_fsw_ = -1;
  std::unique_ptr<gnc::FrameWriter> writer_;
  std::unique_ptr<gnc::FrameReader> reader_;
  std::unique_ptr<gnc::RecordBuffer> frame_;
};

}  // namespace visors::sim
