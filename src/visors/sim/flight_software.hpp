#pragma once
// The two spacecraft's flight software as the host application reaches it
// (docs/flight-software-process.md): both components in this process, stepped side by side
// (sim/paired_worker.hpp), or two visors-fsw processes behind pipes (`visors run --fsw process`,
// sim/fsw_process.hpp). Either way each is created from its object of the run's flight
// configuration (gnc/files/flight_config_json.hpp) and the host exchanges only records with it,
// so the results are the same bit for bit. Ground side.

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnc/record_interface.hpp"
#include "visors/sim/fsw_process.hpp"
#include "visors/sim/paired_worker.hpp"

namespace visors::sim {

struct FlightSoftwareOptions {
  /// Step the in-process components on two threads (RunOptions::parallel_components).
  bool parallel_components = false;
  /// The command that starts a flight software process (`visors run --fsw process`, the
  /// program and the arguments before visors-fsw's own); empty: the components run in process.
  std::vector<std::string> process_command;
  /// The processes' waits: for the ready batch (creation loads the gravity field; minutes under
  /// an emulator) and for a step's outputs [ms].
  int ready_timeout_ms = 600'000;
  int step_timeout_ms = 60'000;
};

class FlightSoftware {
 public:
  /// Both components ("dsc", "osc" of `config`, the content of `config_file`, which a process
  /// reads); a process's standard error goes to fsw_<name>.log in `log_dir`. Errors name the part
  /// ("gnc.", "nav.", "fsw.dsc", ...).
  static core::Result<FlightSoftware> create(const nlohmann::json& config, const std::filesystem::path& config_file,
                                             const std::filesystem::path& log_dir, const FlightSoftwareOptions& options);

  /// One step at t of the components `stepped` says, each with its records: its outputs in
  /// outputs(k), its wall time [us] in step_us[k] (in process: the step; as a process: the round
  /// trip from the first record written to the last output read, the OSC's read after the DSC's).
  core::Result<bool> step(core::GpsTime t, const std::array<bool, 2>& stepped,
                          const std::array<std::span<const gnc::RecordView>, 2>& inputs, std::array<float, 2>& step_us);
  [[nodiscard]] const gnc::OutputRecords& outputs(std::size_t k) const { return *outputs_[k]; }
  [[nodiscard]] bool in_processes() const { return processes_[0].has_value(); }
  /// "in-process", or "process: " and the command (the run's summary, `flight_software`).
  [[nodiscard]] std::string describe() const;

 private:
  std::array<std::optional<gnc::RecordInterface>, 2> components_;  // in process
  std::unique_ptr<PairedWorker> worker_;
  std::array<std::optional<FswProcess>, 2> processes_;  // or as processes
  std::unique_ptr<std::array<gnc::OutputRecords, 2>> received_;  // the processes' outputs
  std::vector<std::string> command_;
  int step_timeout_ms_ = 0;
  std::array<const gnc::OutputRecords*, 2> outputs_{};
};

}  // namespace visors::sim
