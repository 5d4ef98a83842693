#include "visors/mc/run_record.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "visors/sim/campaign_simulation.hpp"

namespace visors::mc {
namespace {

// The injected fault of VISORS_MC_INJECT for this run, if any (record header).
void inject_fault(std::int64_t run) {
  const char* spec = std::getenv("VISORS_MC_INJECT");
  if (spec == nullptr) return;
  const std::string text = spec;
  const auto at = text.find('@');
  if (at == std::string::npos || text.substr(at + 1) != std::to_string(run)) return;
  const std::string kind = text.substr(0, at);
  if (kind == "throw") throw std::runtime_error("injected exception (VISORS_MC_INJECT)");
  if (kind == "crash") std::abort();
  if (kind == "hang") std::this_thread::sleep_for(std::chrono::hours(1));
}

}  // namespace

std::string to_json_text(const RunRecord& r) {
  nlohmann::json j;
  j["run"] = r.run;
  j["ok"] = r.ok;
  j["wall_s"] = r.wall_s;
  j["error"] = r.error;
  j["summary"] = r.summary;
  return j.dump();
}

core::Result<RunRecord> run_record_from_json_text(const std::string& text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    RunRecord r;
    r.run = j.at("run").get<std::int64_t>();
    r.ok = j.at("ok").get<bool>();
    r.wall_s = j.at("wall_s").get<double>();
    r.error = j.at("error").get<std::string>();
    r.summary = j.at("summary");
    return r;
  } catch (const nlohmann::json::exception& e) {
    return core::Error{"run record", std::string("not a run record: ") + e.what()};
  }
}

RunRecord execute_run(const Campaign& campaign, const RunSpec& run, const std::filesystem::path& scratch, bool keep) {
  const auto start = std::chrono::steady_clock::now();
  RunRecord record;
  record.run = run.index;
  const std::filesystem::path dir = scratch / fmt::format("run{:06d}", run.index);
  try {
    inject_fault(run.index);
    auto scenario = scenario_for(campaign, run);
    if (!scenario.ok()) {
      record.error = scenario.error().describe();
    } else if (auto result = sim::run_campaign(*scenario, dir); !result.ok()) {
      record.error = result.error().describe();
    } else {
      record.ok = true;
      record.summary = std::move(result->summary);
    }
  } catch (const std::exception& e) {
    record.error = std::string("exception: ") + e.what();
  } catch (...) {
    record.error = "exception of an unknown type";
  }
  std::error_code ignored;
  if (!keep) std::filesystem::remove_all(dir, ignored);
  record.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return record;
}

}  // namespace visors::mc
