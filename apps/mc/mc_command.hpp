#pragma once
// `visors mc CAMPAIGN.toml [--out DIR] [--threads N] [--resume] [--keep-runs]`: a Monte Carlo
// campaign or parameter sweep (mc/campaign_file.hpp) into DIR/results.sqlite;
// `visors mc rerun DB RUN [--out DIR]`: one run of a stored campaign again, with its run directory
// and report; `visors mc report DB [--out DIR]`: the campaign's HTML report.
// Exit codes: 0 done (failed runs are results, not errors), 2 bad input, 1 an error of the store.

#include <cstdint>
#include <string>

namespace visors::mc_app {

struct McOptions {
  std::string campaign;
  std::string out;       // default out/mc/<campaign name>
  int threads = 0;       // runs at a time; 0: one per core
  bool resume = false;
  bool keep_runs = false;
};

int run_mc_command(const McOptions& options);
int run_mc_rerun_command(const std::string& database, std::int64_t run, const std::string& out);
int run_mc_report_command(const std::string& database, const std::string& out);

}  // namespace visors::mc_app
