// The `visors` command-line program: one binary, subcommands. One page per command in docs/cli/.

#include <cstdio>
#include <iostream>
#include <iterator>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "apps/baseline/baseline_command.hpp"
#include "visors/core/version.hpp"
#include "apps/mc/mc_command.hpp"
#include "apps/nav/nav_command.hpp"
#include "apps/preview/preview_command.hpp"
#include "apps/propagate/propagate_command.hpp"
#include "apps/run/run_command.hpp"
#include "apps/report/report_command.hpp"
#include "apps/tools/tool.hpp"

namespace {

constexpr int kExitBadInput = 2;

int run_tool(const std::string& name) {
  const visors::tools::ToolEntry* entry = nullptr;
  for (const auto& t : visors::tools::tool_registry()) {
    if (t.name == name) entry = &t;
  }
  if (entry == nullptr) {
    fmt::print(stderr, "visors tool: unknown tool '{}' (see 'visors tool --help')\n", name);
    return kExitBadInput;
  }
  const std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  visors::tools::Json input;
  try {
    input = visors::tools::Json::parse(text);
  } catch (const visors::tools::Json::exception& e) {  // syntax, and numbers out of range (1e999)
    fmt::print(stderr, "visors tool {}: input: not valid JSON ({})\n", name, e.what());
    return kExitBadInput;
  }
  if (!input.is_object()) {
    fmt::print(stderr, "visors tool {}: input: must be one JSON object\n", name);
    return kExitBadInput;
  }
  try {
    const auto output = entry->run(input);
    std::cout << output.dump() << '\n';
    return 0;
  } catch (const visors::tools::ToolInputError& e) {
    fmt::print(stderr, "visors tool {}: {}\n", name, e.what());
    return kExitBadInput;
  } catch (const visors::tools::Json::exception& e) {  // a value of an unexpected JSON type
    fmt::print(stderr, "visors tool {}: input: {}\n", name, e.what());
    return kExitBadInput;
  }
}

std::string tool_list() {
  std::string text = "Tools (JSON object on stdin, JSON object on stdout):\n";
  for (const auto& t : visors::tools::tool_registry()) {
    text += fmt::format("  {:<10} {}\n", t.name, t.summary);
  }
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"visors: formation-flying GNC for the VISORS distributed telescope"};
  app.require_subcommand(1);

  std::string tool_name;
  auto* tool = app.add_subcommand("tool", "run a building block: JSON in, JSON out");
  tool->add_option("name", tool_name, "tool name")->required();
  tool->footer(tool_list());

  std::string scenario = "scenarios/formation_preview.toml";
  std::string out_dir = "out/preview";
  auto* preview = app.add_subcommand(
      "preview", "relative motion of the mission formations over a few orbits (no control yet)");
  preview->add_option("scenario", scenario,
                      "scenario TOML (a path, or relative to VISORS_DATA_PATH and data/)")
      ->capture_default_str();
  preview->add_option("--out", out_dir, "output folder")->capture_default_str();

  std::string propagate_scenario = "scenarios/propagate_chief.toml";
  std::string propagate_out = "out/propagate";
  auto* propagate = app.add_subcommand(
      "propagate", "propagate one spacecraft with a force model; ephemeris as CSV and CCSDS OEM");
  propagate->add_option("scenario", propagate_scenario,
                        "scenario TOML (a path, or relative to VISORS_DATA_PATH and data/)")
      ->capture_default_str();
  propagate->add_option("--out", propagate_out, "output folder")->capture_default_str();

  std::string run_scenario = "scenarios/campaign.toml";
  std::string run_out = "out/campaign";
  auto* run = app.add_subcommand(
      "run", "the mission campaign in closed loop (standby, transfer, 10 observations, back); run directory + report");
  run->add_option("scenario", run_scenario, "scenario TOML (a path, or relative to VISORS_DATA_PATH and data/)")
      ->capture_default_str();
  run->add_option("--out", run_out, "run directory")->capture_default_str();
  int run_threads = 2;
  run->add_option("--threads", run_threads,
                  "1: step the two flight components one after the other; 2: side by side (same results)")
      ->check(CLI::Range(1, 2))
      ->capture_default_str();
  visors::run::FswOptions run_fsw;
  run->add_option("--fsw", run_fsw.mode,
                  "in-process: the flight components in this program; process: each a visors-fsw process behind "
                  "its records (same results)")
      ->check(CLI::IsMember({"in-process", "process"}))
      ->capture_default_str();
  run->add_option("--fsw-command", run_fsw.command,
                  "with --fsw process: the command that starts one (default: the visors-fsw beside this program; "
                  "e.g. \"qemu-arm -L /usr/arm-linux-gnueabihf build-cross/armhf/apps/fsw/visors-fsw\")");

  std::string gnss_scenario = "scenarios/gnss_sim.toml";
  std::string gnss_out = "out/gnss";
  auto* gnss_sim = app.add_subcommand(
      "gnss-sim", "raw GPS measurements of both spacecraft: RINEX 3 observation and navigation files, truth files");
  gnss_sim->add_option("scenario", gnss_scenario, "scenario TOML (a path, or relative to VISORS_DATA_PATH and data/)")
      ->capture_default_str();
  gnss_sim->add_option("--out", gnss_out, "output folder")->capture_default_str();

  visors::baseline_app::BaselineOptions baseline_options;
  auto* baseline = app.add_subcommand(
      "baseline", "post-processed differential GPS between two ground receivers (RINEX), integer ambiguity resolution");
  baseline->add_option("rover", baseline_options.rover, "rover RINEX observation file (2.x or 3.x)")->required();
  baseline->add_option("base", baseline_options.base, "base RINEX observation file (2.x or 3.x)")->required();
  baseline->add_option("--nav", baseline_options.nav, "RINEX navigation file (repeatable)")->required();
  baseline->add_option("--base-ecef", baseline_options.base_ecef, "base position X Y Z, Earth-fixed [m]")
      ->expected(3)->required();
  baseline->add_option("--mode", baseline_options.mode, "static | kinematic")->capture_default_str();
  baseline->add_option("--freq", baseline_options.freq, "L1 | L1L2")->capture_default_str();
  baseline->add_option("--elevation-mask", baseline_options.elevation_mask_deg, "elevation mask [deg]")
      ->capture_default_str();
  baseline->add_option("--ar", baseline_options.ar, "ambiguity resolution: off | continuous | hold")
      ->capture_default_str();
  baseline->add_option("--out", baseline_options.out, "output folder")->capture_default_str();

  visors::nav_app::NavOptions nav_options;
  auto* nav = app.add_subcommand(
      "nav", "replay a gnss-sim run through both spacecraft's carrier-phase GPS filters, scored against its truth");
  nav->add_option("run_dir", nav_options.run_dir, "run directory written by 'visors gnss-sim'")->required();
  nav->add_option("--out", nav_options.out, "output folder")->capture_default_str();
  nav->add_option("--duration", nav_options.duration_s, "replay only the first S seconds (0: all)")->capture_default_str();
  nav->add_option("--crosslink-drop", nav_options.crosslink_drop, "probability that the other receiver's epoch is lost")
      ->capture_default_str();
  nav->add_flag("--elevation-weighting", nav_options.elevation_weighting,
                "weight code and phase by the elevation above the antenna plane (1/sin)");
  nav->add_option("--crosslink-delay", nav_options.crosslink_delay_s,
                  "the other receiver's epochs arrive S s late: each solution is also scored when it is in use")
      ->capture_default_str();
  nav->add_flag("--float", nav_options.float_only, "no integer ambiguity resolution: the float filter alone");
  nav->add_flag("--no-laser", nav_options.no_laser, "do not fuse the run's laser ranges (lrf.csv)");
  nav->add_option("--settings", nav_options.settings_file,
                  "TOML file with a [nav] table of filter settings (CdgpsSettings field names)");
  std::vector<double> outage;
  nav->add_option("--outage", outage, "GPS outage of both receivers: START DURATION [s]")->expected(2);
  nav->callback([&] {
    if (outage.size() == 2) {
      nav_options.outage_start_s = outage[0];
      nav_options.outage_s = outage[1];
    }
  });

  std::string report_dir;
  auto* report = app.add_subcommand(
      "report", "render DIR/report.html (self-contained HTML, inline SVG) from a run directory");
  report->add_option("dir", report_dir, "run directory written by 'visors run'")->required();

  visors::mc_app::McOptions mc_options;
  auto* mc = app.add_subcommand("mc", "a Monte Carlo campaign or parameter sweep (CAMPAIGN.toml) into DIR/results.sqlite");
  mc->add_option("campaign", mc_options.campaign, "campaign TOML (a path, or relative to VISORS_DATA_PATH and data/)");
  mc->add_option("--out", mc_options.out, "output folder (default out/mc/<campaign name>)");
  mc->add_option("--threads", mc_options.threads, "runs at a time, each in its own process (0: one per core)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  mc->add_flag("--resume", mc_options.resume, "go on with the results database in the output folder");
  mc->add_flag("--keep-runs", mc_options.keep_runs, "keep each run's directory (DIR/runs/runNNNNNN)");
  std::string mc_database, mc_out;
  std::int64_t mc_run = 0;
  auto* mc_rerun = mc->add_subcommand("rerun", "one run of a stored campaign again, with its run directory and report");
  mc_rerun->add_option("database", mc_database, "results.sqlite of the campaign")->required();
  mc_rerun->add_option("run", mc_run, "the run's index")->required();
  mc_rerun->add_option("--out", mc_out, "run directory (default out/mc-rerun/runNNNNNN)");
  std::string mc_report_database, mc_report_out;
  auto* mc_report = mc->add_subcommand("report", "the campaign's HTML report (sensitivity figures, failed runs, provenance)");
  mc_report->add_option("database", mc_report_database, "results.sqlite of the campaign")->required();
  mc_report->add_option("--out", mc_report_out, "output folder (default: the database's)");

  app.set_version_flag("--version", std::string("visors ") + std::string(visors::core::kVersion), "print the version and exit");
  app.add_subcommand("version", "print the version")->callback([] { fmt::print("visors {}\n", visors::core::kVersion); });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  }
  if (tool->parsed()) return run_tool(tool_name);
  if (gnss_sim->parsed()) return visors::run::run_gnss_sim_command(gnss_scenario, gnss_out);
  if (preview->parsed()) return visors::preview::run_preview_command(scenario, out_dir);
  if (propagate->parsed()) {
    return visors::propagate::run_propagate_command(propagate_scenario, propagate_out);
  }
  if (run->parsed()) return visors::run::run_campaign_command(run_scenario, run_out, run_threads, run_fsw);
  if (mc_rerun->parsed()) return visors::mc_app::run_mc_rerun_command(mc_database, mc_run, mc_out);
  if (mc_report->parsed()) return visors::mc_app::run_mc_report_command(mc_report_database, mc_report_out);
  if (mc->parsed()) {
    if (mc_options.campaign.empty()) {
      fmt::print(stderr, "visors mc: a campaign file is required (or: mc rerun DB RUN)\n");
      return kExitBadInput;
    }
    return visors::mc_app::run_mc_command(mc_options);
  }
  if (baseline->parsed()) return visors::baseline_app::run_baseline_command(baseline_options);
  if (nav->parsed()) return visors::nav_app::run_nav_command(nav_options);
  if (report->parsed()) return visors::report::run_report_command(report_dir);
  return 0;
}
