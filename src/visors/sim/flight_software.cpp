#include "visors/sim/flight_software.hpp"

#include <chrono>
#include <utility>

#include "visors/gnc/files/flight_config_json.hpp"

namespace visors::sim {
namespace {

constexpr std::array<const char*, 2> kNames{"dsc", "osc"};

float microseconds_since(std::chrono::steady_clock::time_point start) {
  return static_cast<float>(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

core::Result<FlightSoftware> FlightSoftware::create(const nlohmann::json& config, const std::filesystem::path& config_file,
                                                    const std::filesystem::path& log_dir, const FlightSoftwareOptions& options) {
  FlightSoftware software;
  software.step_timeout_ms_ = options.step_timeout_ms;
  software.command_ = options.process_command;
  for (std::size_t k = 0; k < 2; ++k) {
    if (!options.process_command.empty()) {
      auto process = FswProcess::start(options.process_command, config_file, kNames[k],
                                       log_dir / (std::string("fsw_") + kNames[k] + ".log"), options.ready_timeout_ms);
      if (!process.ok()) return process.error();
      software.processes_[k].emplace(std::move(process).value());
      continue;
    }
    auto setup = gnc::files::component_setup_from_json(config.at(kNames[k]));
    if (!setup.ok()) {
      return core::Error{std::string("flight_config.") + kNames[k] + "." + setup.error().field, setup.error().message};
    }
    auto component = gnc::files::make_component(setup.value());
    if (!component.ok()) return component.error();
    software.components_[k].emplace(std::move(component).value());
  }
  if (software.in_processes()) software.received_ = std::make_unique<std::array<gnc::OutputRecords, 2>>();
  else software.worker_ = std::make_unique<PairedWorker>(options.parallel_components);
  return software;
}

std::string FlightSoftware::describe() const {
  if (!in_processes()) return "in-process";
  std::string text = "process:";
  for (const std::string& word : command_) text += " " + word;
  return text;
}

core::Result<bool> FlightSoftware::step(core::GpsTime t, const std::array<bool, 2>& stepped,
                                        const std::array<std::span<const gnc::RecordView>, 2>& inputs,
                                        std::array<float, 2>& step_us) {
  if (!in_processes()) {
    const auto one = [&](std::size_t k) {
      if (!stepped[k]) return;
      const auto start = std::chrono::steady_clock::now();
      outputs_[k] = &components_[k]->step(t, inputs[k]);
      step_us[k] = microseconds_since(start);
    };
    worker_->run([&] { one(0); }, [&] { one(1); });
    return true;
  }
  // Both processes get their records before either is read, so they step side by side.
  std::array<std::chrono::steady_clock::time_point, 2> start{};
  for (std::size_t k = 0; k < 2; ++k) {
    if (!stepped[k]) continue;
    start[k] = std::chrono::steady_clock::now();
    if (auto ok = processes_[k]->send(inputs[k]); !ok) return ok.error();
  }
  for (std::size_t k = 0; k < 2; ++k) {
    if (!stepped[k]) continue;
    if (auto ok = processes_[k]->receive((*received_)[k], step_timeout_ms_); !ok) return ok.error();
    step_us[k] = microseconds_since(start[k]);
    outputs_[k] = &(*received_)[k];
  }
  return true;
}

}  // namespace visors::sim
