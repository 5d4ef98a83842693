// The compiled part of the Python package `visors` (visors/__init__.py wraps it): the program's
// entry points (a run, the GNSS simulation, the navigation replay, a Monte Carlo campaign, every
// `visors tool`) and the integer least-squares search, each releasing the GIL while it computes.
// Bad input raises ValueError with the field and the problem, as the CLI prints them.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <toml++/toml.h>

#include "apps/mc/mc_command.hpp"
#include "apps/nav/nav_command.hpp"
#include "apps/tools/tool.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/text_file.hpp"
#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/control/stochastic_mpc.hpp"
#include "visors/core/version.hpp"
#include "visors/nav/integer_least_squares.hpp"
#include "visors/report/report.hpp"
#include "visors/sim/campaign_simulation.hpp"
#include "visors/sim/gnss_simulation.hpp"

namespace py = pybind11;
using Json = nlohmann::json;

namespace {

// What a command prints on stderr while it runs, kept for the exception it may become (the
// commands report bad input there, naming the option or the file and field).
class CapturedStderr {
 public:
  CapturedStderr() : file_(std::tmpfile()) {
    std::fflush(stderr);
    saved_ = ::dup(STDERR_FILENO);
    if (file_ != nullptr && saved_ >= 0) ::dup2(::fileno(file_), STDERR_FILENO);
  }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;
  ~CapturedStderr() { restore(); }
  /// Restores stderr and returns what was written to it meanwhile.
  std::string restore() {
    if (saved_ < 0) return text_;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
    if (file_ != nullptr) {
      std::rewind(file_);
      char buffer[4096];
      for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file_)) > 0;) text_.append(buffer, n);
      std::fclose(file_);
      file_ = nullptr;
    }
    while (!text_.empty() && text_.back() == '\n') text_.pop_back();
    return text_;
  }

 private:
  std::FILE* file_;
  int saved_ = -1;
  std::string text_;
};

// A command's exit code as Python sees it: 2 (bad input) ValueError, 1 RuntimeError.
void raise_on_exit_code(int code, const std::string& command, const std::string& stderr_text) {
  if (code == 0) return;
  const std::string message = stderr_text.empty() ? command + " failed (exit code " + std::to_string(code) + ")" : stderr_text;
  if (code == 2) throw py::value_error(message);
  throw std::runtime_error(message);
}

// JSON (the scenario given as a dict, serialised by the Python side) -> a TOML table.
toml::table to_toml_table(const Json& object, const std::string& path);
toml::array to_toml_array(const Json& array, const std::string& path);

// Passes `add` the TOML value of one JSON value (tables and arrays converted recursively).
template <typename Add>
void add_toml_value(const Json& v, const std::string& field, Add add) {
  if (v.is_object()) add(to_toml_table(v, field));
  else if (v.is_array()) add(to_toml_array(v, field));
  else if (v.is_boolean()) add(v.get<bool>());
  else if (v.is_number_integer()) add(v.get<std::int64_t>());
  else if (v.is_number()) add(v.get<double>());
  else if (v.is_string()) add(v.get<std::string>());
  else throw py::value_error(field + ": must be a number, a string, a bool, a list or a dict");
}

toml::array to_toml_array(const Json& array, const std::string& path) {
  toml::array out;
  for (std::size_t k = 0; k < array.size(); ++k) {
    add_toml_value(array[k], path + "[" + std::to_string(k) + "]", [&](auto&& value) { out.push_back(std::move(value)); });
  }
  return out;
}

toml::table to_toml_table(const Json& object, const std::string& path) {
  toml::table out;
  for (const auto& [key, v] : object.items()) {
    add_toml_value(v, path.empty() ? key : path + "." + key, [&](auto&& value) { out.insert(key, std::move(value)); });
  }
  return out;
}

// The scenario from its TOML text (a file found on the data search path, or the dict's TOML),
// with the seed replaced when one is given.
visors::sim::CampaignScenario scenario_from(const std::string& path, const std::string& dict_json,
                                            std::optional<std::uint64_t> seed) {
  std::string text;
  std::string source = "scenario";
  if (!dict_json.empty()) {
    std::ostringstream toml_text;
    toml_text << to_toml_table(Json::parse(dict_json), "");
    text = toml_text.str();
  } else {
    const auto found = visors::core::files::find_data_file(path);
    if (!found) throw py::value_error("scenario: '" + path + "' not found (nor in VISORS_DATA_PATH or data/)");
    auto content = visors::core::files::read_text_file(*found);
    if (!content) throw py::value_error("scenario: " + found->string() + ": cannot be read");
    text = std::move(*content);
    source = found->string();
  }
  auto scenario = visors::sim::campaign_from_toml(text);
  if (!scenario.ok()) throw py::value_error(source + ": " + scenario.error().describe());
  visors::sim::CampaignScenario resolved = std::move(scenario).value();
  if (seed) resolved.seed = *seed;
  return resolved;
}

// A closed-loop run: the run directory (and its report when asked), its summary as JSON text.
std::pair<std::string, std::string> run_campaign(const std::string& path, const std::string& dict_json,
                                                 const std::string& out, std::optional<std::uint64_t> seed,
                                                 bool parallel, bool report) {
  const auto scenario = scenario_from(path, dict_json, seed);
  visors::core::Result<visors::sim::RunResult> result = visors::core::Error{"", ""};
  {
    py::gil_scoped_release release;
    const visors::sim::RunOptions options{.parallel_components = parallel, .fsw_command = {}};
    result = visors::sim::run_campaign(scenario, out, {}, options);
    if (result.ok() && report) {
      if (auto written = visors::report::write_report(result->dir); !written.ok()) result = written.error();
    }
  }
  if (!result.ok()) throw std::runtime_error("run: " + result.error().describe());
  return {result->summary.dump(), result->dir.string()};
}

std::pair<std::string, std::string> gnss_sim(const std::string& path, const std::string& dict_json,
                                             const std::string& out, std::optional<std::uint64_t> seed) {
  const auto scenario = scenario_from(path, dict_json, seed);
  visors::core::Result<visors::sim::GnssRunResult> result = visors::core::Error{"", ""};
  {
    py::gil_scoped_release release;
    result = visors::sim::run_gnss_simulation(scenario, out);
  }
  if (!result.ok()) {
    const auto& e = result.error();
    if (e.field.rfind("gnss", 0) == 0) throw py::value_error("gnss_sim: " + e.describe());
    throw std::runtime_error("gnss_sim: " + e.describe());
  }
  return {result->summary.dump(), result->dir.string()};
}

// A command of the program run in-process without the GIL, its stderr kept for the exception.
template <typename Command>
void run_command(const char* name, Command command) {
  int code = 0;
  std::string errors;
  {
    py::gil_scoped_release release;
    CapturedStderr captured;
    code = command();
    errors = captured.restore();
  }
  raise_on_exit_code(code, name, errors);
}

void nav_replay(const visors::nav_app::NavOptions& options) {
  run_command("nav_replay", [&] { return visors::nav_app::run_nav_command(options); });
}

void monte_carlo(const visors::mc_app::McOptions& options) {
  run_command("mc", [&] { return visors::mc_app::run_mc_command(options); });
}

// `visors tool NAME`: the request and the answer as JSON text (the Python side converts dicts).
std::string tool(const std::string& name, const std::string& request_json) {
  for (const auto& entry : visors::tools::tool_registry()) {
    if (entry.name != name) continue;
    Json request;
    try {
      request = Json::parse(request_json);
    } catch (const Json::parse_error& e) {
      throw py::value_error(std::string("request: not JSON: ") + e.what());
    }
    try {
      return entry.run(request).dump();
    } catch (const visors::tools::ToolInputError& e) {
      throw py::value_error(e.what());
    } catch (const Json::exception& e) {
      throw py::value_error(std::string("request: ") + e.what());
    }
  }
  throw py::value_error("name: no tool '" + name + "' (visors.tool_names() lists them)");
}

std::vector<std::string> tool_names() {
  std::vector<std::string> names;
  for (const auto& entry : visors::tools::tool_registry()) names.emplace_back(entry.name);
  return names;
}

// Integer least squares (LAMBDA reduction and MLAMBDA search): the m best integer vectors of the
// float ambiguities a [cycles] with covariance Q [cycles^2].
py::dict integer_least_squares(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, int candidates) {
  visors::nav::IlsSettings settings;
  settings.candidates = candidates;
  auto created = visors::nav::IntegerLeastSquares::create(settings);
  if (!created.ok()) throw py::value_error(created.error().describe());
  visors::nav::IntegerLeastSquares ils = std::move(created).value();
  using visors::nav::IlsStatus;
  switch (ils.resolve(a, Q)) {
    case IlsStatus::kOk: break;
    case IlsStatus::kEmpty: throw py::value_error("a: is empty");
    case IlsStatus::kTooManyAmbiguities:
      throw py::value_error("a: more than " + std::to_string(visors::nav::kMaxAmbiguities) + " ambiguities");
    case IlsStatus::kSizeMismatch: throw py::value_error("Q: its size differs from a's");
    case IlsStatus::kNotFinite: throw py::value_error("a, Q: hold a NaN or an infinity");
    case IlsStatus::kNotSymmetric: throw py::value_error("Q: is not symmetric");
    case IlsStatus::kNotPositiveDefinite: throw py::value_error("Q: is not positive definite");
    case IlsStatus::kSearchLimit: throw std::runtime_error("integer_least_squares: the search reached its step limit");
  }
  const auto& s = ils.solution();
  py::dict out;
  out["candidates"] = Eigen::MatrixXd(s.a.leftCols(s.found).transpose());
  out["squared_norms"] = Eigen::VectorXd(s.sqnorm.head(s.found));
  out["ratio"] = s.ratio;
  out["success_rate"] = s.success_rate;
  out["transformation"] = Eigen::MatrixXd(ils.transformation());
  return out;
}

// Keplerian elements {a, e, i, raan, argp, M} [m, rad] as JSON text (the Python side serialises
// the dict), read and validated as the tools read them (errors name "<name>.<field>").
visors::astro::KeplerianElements elements_from(const std::string& elements_json, const std::string& name) {
  try {
    return visors::tools::take(visors::astro::validate_keplerian(
                                   visors::tools::require_keplerian(Json::parse(elements_json), name)),
                               name);
  } catch (const visors::tools::ToolInputError& e) {
    throw py::value_error(e.what());
  }
}

template <typename T>
T value_or_raise(visors::core::Result<T> result) {
  if (!result.ok()) throw py::value_error(result.error().describe());
  return std::move(result).value();
}

void value_or_raise(visors::core::Status status) {
  if (!status.ok()) throw py::value_error(status.error().describe());
}

visors::astro::RelativeOrbitalElements finite_roe(const Eigen::Matrix<double, 6, 1>& roe, const std::string& name) {
  if (!roe.allFinite()) throw py::value_error(name + ": must be finite");
  return roe;
}

// The stochastic MPC (control/stochastic_mpc.hpp) for Python: dimensionless mean ROE, times in
// seconds on the caller's clock, the plan's impulses as (t, dv_rtn) pairs.
class PyStochasticMpc {
 public:
  PyStochasticMpc(double mahalanobis_threshold, double execution_sigma_fraction, double execution_sigma_floor_mps,
                  double freeze_time_s, double burn_latency_s) {
    visors::control::StochasticMpcSettings settings;
    settings.mahalanobis_threshold = mahalanobis_threshold;
    settings.execution_sigma_fraction = execution_sigma_fraction;
    settings.execution_sigma_floor_mps = execution_sigma_floor_mps;
    settings.freeze_time_s = freeze_time_s;
    settings.burn_latency_s = burn_latency_s;
    mpc_ = std::make_unique<visors::control::StochasticMpc>(value_or_raise(visors::control::StochasticMpc::create(settings)));
  }
  void set_target(const Eigen::Matrix<double, 6, 1>& roe_target, double tf) {
    value_or_raise(mpc_->set_target(finite_roe(roe_target, "roe_target"), tf));
  }
  py::dict step(double t, const std::string& chief_mean, const Eigen::Matrix<double, 6, 1>& roe_estimate,
                const Eigen::Matrix<double, 6, 6>& covariance) {
    const auto chief = elements_from(chief_mean, "chief_mean");
    const auto result = value_or_raise(mpc_->step(t, chief, roe_estimate, covariance));
    py::list impulses;
    for (const auto& impulse : result.remaining) impulses.append(py::make_tuple(impulse.t, Eigen::Vector3d(impulse.dv_rtn)));
    py::dict out;
    out["replanned"] = result.replanned;
    out["mahalanobis"] = result.mahalanobis;
    out["remaining"] = impulses;
    out["roe_final_predicted"] = Eigen::Matrix<double, 6, 1>(result.roe_final_predicted);
    return out;
  }
  int replan_count() const { return mpc_->replan_count(); }

 private:
  std::unique_ptr<visors::control::StochasticMpc> mpc_;
};

}  // namespace

PYBIND11_MODULE(_visors, m) {
  m.doc() = "VISORS GNC: the compiled core of the visors package (use the package, not this module)";
  m.attr("__version__") = std::string(visors::core::kVersion);

  m.def("run_campaign", &run_campaign, py::arg("path"), py::arg("dict_json"), py::arg("out"), py::arg("seed"),
        py::arg("parallel"), py::arg("report"));
  m.def("gnss_sim", &gnss_sim, py::arg("path"), py::arg("dict_json"), py::arg("out"), py::arg("seed"));

  py::class_<visors::nav_app::NavOptions>(m, "NavOptions")
      .def(py::init<>())
      .def_readwrite("run_dir", &visors::nav_app::NavOptions::run_dir)
      .def_readwrite("out", &visors::nav_app::NavOptions::out)
      .def_readwrite("duration_s", &visors::nav_app::NavOptions::duration_s)
      .def_readwrite("elevation_weighting", &visors::nav_app::NavOptions::elevation_weighting)
      .def_readwrite("float_only", &visors::nav_app::NavOptions::float_only)
      .def_readwrite("no_laser", &visors::nav_app::NavOptions::no_laser)
      .def_readwrite("settings_file", &visors::nav_app::NavOptions::settings_file)
      .def_readwrite("crosslink_drop", &visors::nav_app::NavOptions::crosslink_drop)
      .def_readwrite("crosslink_delay_s", &visors::nav_app::NavOptions::crosslink_delay_s)
      .def_readwrite("outage_start_s", &visors::nav_app::NavOptions::outage_start_s)
      .def_readwrite("outage_s", &visors::nav_app::NavOptions::outage_s);
  m.def("nav_replay", &nav_replay, py::arg("options"));

  py::class_<visors::mc_app::McOptions>(m, "McOptions")
      .def(py::init<>())
      .def_readwrite("campaign", &visors::mc_app::McOptions::campaign)
      .def_readwrite("out", &visors::mc_app::McOptions::out)
      .def_readwrite("threads", &visors::mc_app::McOptions::threads)
      .def_readwrite("resume", &visors::mc_app::McOptions::resume)
      .def_readwrite("keep_runs", &visors::mc_app::McOptions::keep_runs);
  m.def("mc", &monte_carlo, py::arg("options"));

  m.def("find_data_file", [](const std::string& relative) -> std::optional<std::string> {
    const auto found = visors::core::files::find_data_file(relative);
    return found ? std::optional<std::string>(found->string()) : std::nullopt;
  }, py::arg("relative"));
  m.def("tool", &tool, py::arg("name"), py::arg("request_json"));
  m.def("tool_names", &tool_names);
  m.def("integer_least_squares", &integer_least_squares, py::arg("a"), py::arg("Q"), py::arg("candidates"));
  m.def("control_input_matrix", [](const std::string& chief, double mu) {
    return Eigen::Matrix<double, 6, 3>(visors::astro::control_input_matrix(elements_from(chief, "chief"), mu));
  }, py::arg("chief"), py::arg("mu"));
  py::class_<PyStochasticMpc>(m, "StochasticMpc")
      .def(py::init<double, double, double, double, double>(), py::arg("mahalanobis_threshold"),
           py::arg("execution_sigma_fraction"), py::arg("execution_sigma_floor_mps"), py::arg("freeze_time_s"),
           py::arg("burn_latency_s"))
      .def("set_target", &PyStochasticMpc::set_target, py::arg("roe_target"), py::arg("tf"))
      .def("step", &PyStochasticMpc::step, py::arg("t"), py::arg("chief_mean"), py::arg("roe_estimate"),
           py::arg("covariance"))
      .def_property_readonly("replan_count", &PyStochasticMpc::replan_count);
}
