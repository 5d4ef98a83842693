#include "visors/mc/results_store.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>

#include <fmt/format.h>

// Unwraps a Result into a mutable `var`, or returns its error from the enclosing function.
#define VISORS_MC_TAKE(var, expr)                  \
  auto var##_result = (expr);                      \
  if (!var##_result.ok()) return var##_result.error(); \
  auto var = std::move(var##_result).value()

namespace visors::mc {
namespace {

using core::Error;

constexpr const char* kSchema = R"sql(
PRAGMA journal_mode = WAL;
PRAGMA synchronous = NORMAL;
CREATE TABLE IF NOT EXISTS campaign (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  name TEXT NOT NULL,
  file_text TEXT NOT NULL,
  scenario_path TEXT NOT NULL,
  scenario_text TEXT NOT NULL,
  base_scenario TEXT NOT NULL,
  program_version TEXT NOT NULL,
  total_runs INTEGER NOT NULL,
  created_utc TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS data_files (
  path TEXT PRIMARY KEY,
  size INTEGER NOT NULL,
  checksum TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS runs (
  run INTEGER PRIMARY KEY,
  sweep_key TEXT,
  sweep_value REAL,
  sweep_value_text TEXT,
  replicate INTEGER NOT NULL,
  seed INTEGER NOT NULL,
  parameters TEXT NOT NULL,
  status TEXT NOT NULL CHECK (status IN ('ok', 'failed')),
  error TEXT,
  wall_s REAL NOT NULL,
  timings TEXT,
  finished_utc TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS observations (
  run INTEGER NOT NULL REFERENCES runs (run),
  attempt INTEGER NOT NULL,
  t_s REAL,
  lateral_error_m REAL,
  lateral_velocity_mps REAL,
  focus_error_m REAL,
  lateral_x_m REAL,
  lateral_y_m REAL,
  focus_signed_m REAL,
  success INTEGER NOT NULL,
  PRIMARY KEY (run, attempt));
CREATE TABLE IF NOT EXISTS summaries (
  run INTEGER PRIMARY KEY REFERENCES runs (run),
  attempts INTEGER NOT NULL,
  success_rate REAL,
  dv_dsc_mps REAL,
  dv_osc_mps REAL,
  min_separation_rn_m REAL,
  min_separation_3d_m REAL,
  safety_violations INTEGER,
  final_mode TEXT,
  navigation_mode TEXT,
  summary TEXT NOT NULL);
)sql";

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

SqlValue number_or_null(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::monostate{};
  return it->get<double>();
}

// The host-dependent parts of a summary (wall times) go to runs.timings, not into summaries.
constexpr const char* kTimingKeys[] = {"wall_s", "flight_step_us"};

core::Result<bool> run_all(SqlStatement& s) {
  for (;;) {
    auto row = s.step();
    if (!row.ok()) return row.error();
    if (!*row) return true;
  }
}

}  // namespace

core::Result<ResultsStore> ResultsStore::open(const std::filesystem::path& path) {
  VISORS_MC_TAKE(db, SqlDatabase::open(path));
  if (auto ok = db.execute(kSchema); !ok) return Error{path.string(), ok.error().message};
  return ResultsStore(std::move(db));
}

core::Result<bool> ResultsStore::record_campaign(const Campaign& c, const std::string& base_scenario_toml,
                                                 const std::vector<DataFileUse>& data_files) {
  auto existing = campaign_file();
  if (existing.ok()) {
    if (existing->first != c.text) return Error{"results", "the database holds another campaign (its file differs)"};
    return true;
  }
  if (auto ok = db_.execute("BEGIN IMMEDIATE"); !ok) return ok;
  if (auto ok = insert_campaign(c, base_scenario_toml, data_files); !ok) {
    (void)db_.execute("ROLLBACK");
    return ok;
  }
  return db_.execute("COMMIT");
}

core::Result<bool> ResultsStore::insert_campaign(const Campaign& c, const std::string& base_scenario_toml,
                                                 const std::vector<DataFileUse>& data_files) {
  VISORS_MC_TAKE(statement, db_.prepare("INSERT INTO campaign VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?)"));
  statement.bind(1, c.name).bind(2, c.text).bind(3, c.scenario_path.string()).bind(4, c.scenario_text);
  statement.bind(5, base_scenario_toml).bind(6, program_version()).bind(7, c.total_runs()).bind(8, utc_now());
  if (auto ok = run_all(statement); !ok) return ok;
  VISORS_MC_TAKE(files, db_.prepare("INSERT OR REPLACE INTO data_files VALUES (?, ?, ?)"));
  for (const DataFileUse& f : data_files) {
    if (f.path.empty()) continue;  // not found: the runs use an embedded default (their events say so)
    files.bind(1, f.path).bind(2, f.size).bind(3, f.checksum);
    if (auto ok = run_all(files); !ok) return ok;
  }
  return true;
}

core::Result<std::pair<std::string, std::string>> ResultsStore::campaign_file() const {
  VISORS_MC_TAKE(s, db_.prepare("SELECT file_text, scenario_text FROM campaign WHERE id = 1"));
  VISORS_MC_TAKE(row, s.step());
  if (!row) return Error{"results", "no campaign recorded"};
  return std::pair<std::string, std::string>{s.text(0), s.text(1)};
}

core::Result<std::vector<std::int64_t>> ResultsStore::stored_runs() {
  VISORS_MC_TAKE(s, db_.prepare("SELECT run FROM runs ORDER BY run"));
  std::vector<std::int64_t> out;
  for (;;) {
    VISORS_MC_TAKE(row, s.step());
    if (!row) return out;
    out.push_back(s.integer(0));
  }
}

core::Result<bool> ResultsStore::insert_run(const RunSpec& spec, const RunRecord& r) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [key, value] : spec.parameters) parameters[key] = to_text(value);
  nlohmann::json timings = nlohmann::json::object();
  if (r.summary.is_object()) {
    for (const char* key : kTimingKeys) {
      if (r.summary.contains(key)) timings[key] = r.summary.at(key);
    }
  }
  VISORS_MC_TAKE(s, db_.prepare("INSERT INTO runs VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  s.bind(1, spec.index);
  if (spec.sweep >= 0) {
    const ScenarioValue& v = spec.parameters.front().second;
    const double number = to_number(v);
    s.bind(2, spec.parameters.front().first).bind(3, std::isnan(number) ? SqlValue{} : SqlValue{number}).bind(4, to_text(v));
  }
  s.bind(5, spec.replicate).bind(6, static_cast<std::int64_t>(spec.seed)).bind(7, parameters.dump());
  s.bind(8, std::string(r.ok ? "ok" : "failed")).bind(9, r.ok ? SqlValue{} : SqlValue{r.error}).bind(10, r.wall_s);
  s.bind(11, timings.dump()).bind(12, utc_now());
  return run_all(s);
}

core::Result<bool> ResultsStore::insert_observations(const RunRecord& r) {
  const auto it = r.summary.find("observations");
  if (it == r.summary.end() || !it->is_array()) return true;
  VISORS_MC_TAKE(s, db_.prepare("INSERT INTO observations VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  for (const auto& o : *it) {
    s.bind(1, r.run).bind(2, o.value("index", std::int64_t{0})).bind(3, number_or_null(o, "t_s"));
    s.bind(4, number_or_null(o, "lateral_error_m")).bind(5, number_or_null(o, "lateral_velocity_mps"));
    s.bind(6, number_or_null(o, "focus_error_m")).bind(7, number_or_null(o, "lateral_x_m"));
    s.bind(8, number_or_null(o, "lateral_y_m")).bind(9, number_or_null(o, "focus_signed_m"));
    s.bind(10, std::int64_t{o.value("success", false) ? 1 : 0});
    if (auto ok = run_all(s); !ok) return ok;
  }
  return true;
}

core::Result<bool> ResultsStore::insert_summary(const RunRecord& r) {
  const nlohmann::json& j = r.summary;
  const nlohmann::json kept = without_timings(j);
  const auto dv = [&](const char* craft) -> SqlValue {
    const auto p = nlohmann::json::json_pointer(std::string("/delta_v_mps/") + craft + "/total");
    return j.contains(p) && j.at(p).is_number() ? SqlValue{j.at(p).get<double>()} : SqlValue{};
  };
  const auto text = [&](const char* key) -> SqlValue {
    return j.contains(key) && j.at(key).is_string() ? SqlValue{j.at(key).get<std::string>()} : SqlValue{};
  };
  VISORS_MC_TAKE(s, db_.prepare("INSERT INTO summaries VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  const auto attempts = j.contains("observations") ? static_cast<std::int64_t>(j.at("observations").size()) : 0;
  const SqlValue violations = j.contains("safety_violations") ? SqlValue{j.at("safety_violations").get<std::int64_t>()} : SqlValue{};
  s.bind(1, r.run).bind(2, attempts).bind(3, number_or_null(j, "success_rate")).bind(4, dv("dsc")).bind(5, dv("osc"));
  s.bind(6, number_or_null(j, "min_separation_rn_m")).bind(7, number_or_null(j, "min_separation_3d_m")).bind(8, violations);
  s.bind(9, text("final_mode")).bind(10, text("navigation_mode")).bind(11, kept.dump());
  return run_all(s);
}

core::Result<bool> ResultsStore::store(const RunSpec& spec, const RunRecord& record) {
  if (auto ok = db_.execute("BEGIN IMMEDIATE"); !ok) return ok;
  auto stored = insert_run(spec, record);
  if (stored.ok() && record.ok) stored = insert_observations(record);
  if (stored.ok() && record.ok) stored = insert_summary(record);
  if (!stored.ok()) {
    (void)db_.execute("ROLLBACK");
    return Error{fmt::format("run {}", spec.index), stored.error().message};
  }
  return db_.execute("COMMIT");
}

core::Result<CampaignInfo> ResultsStore::info() {
  CampaignInfo out;
  {
    VISORS_MC_TAKE(s, db_.prepare("SELECT name, program_version, created_utc, total_runs FROM campaign WHERE id = 1"));
    VISORS_MC_TAKE(row, s.step());
    if (!row) return Error{"results", "no campaign recorded"};
    out.name = s.text(0);
    out.program_version = s.text(1);
    out.created_utc = s.text(2);
    out.total_runs = s.integer(3);
  }
  VISORS_MC_TAKE(s, db_.prepare("SELECT path, size, checksum FROM data_files ORDER BY path"));
  for (;;) {
    VISORS_MC_TAKE(row, s.step());
    if (!row) return out;
    DataFileUse f;
    f.path = s.text(0);
    f.size = s.integer(1);
    f.checksum = s.text(2);
    out.data_files.push_back(f);
  }
}

core::Result<std::vector<StoredRun>> ResultsStore::runs() {
  VISORS_MC_TAKE(s, db_.prepare("SELECT r.run, r.sweep_key, r.sweep_value, r.sweep_value_text, r.replicate, r.seed, "
                                "r.parameters, r.status, r.error, r.wall_s, s.summary FROM runs r "
                                "LEFT JOIN summaries s ON s.run = r.run ORDER BY r.run"));
  std::vector<StoredRun> out;
  for (;;) {
    VISORS_MC_TAKE(row, s.step());
    if (!row) return out;
    StoredRun r;
    r.run = s.integer(0);
    r.sweep_key = s.text(1);
    r.sweep_value = s.real(2);
    r.sweep_value_text = s.text(3);
    r.replicate = s.integer(4);
    r.seed = s.integer(5);
    r.parameters = nlohmann::json::parse(s.text(6), nullptr, false);
    r.ok = s.text(7) == "ok";
    r.error = s.text(8);
    r.wall_s = s.real(9);
    if (!s.is_null(10)) r.summary = nlohmann::json::parse(s.text(10), nullptr, false);
    out.push_back(std::move(r));
  }
}

nlohmann::json without_timings(const nlohmann::json& summary) {
  nlohmann::json kept = summary;
  if (kept.is_object()) {
    for (const char* key : kTimingKeys) kept.erase(key);
  }
  return kept;
}

std::string program_version() { return "visors " VISORS_VERSION; }

}  // namespace visors::mc
