// `mpirun -n 2 visors mc` (mc/mpi_campaign.hpp) on the tiny campaign stores what one local process
// stores: the runs depend on their index alone, not on the rank that ran them.
#include "visors/mc/mpi_campaign.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "visors/mc/campaign_runner.hpp"
#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

bool have_mpirun() { return std::system("command -v mpirun > /dev/null 2>&1") == 0; }

TEST(MpiCampaign, TwoRanksStoreWhatOneProcessStores) {
  if (!mpi_available()) GTEST_SKIP() << "built without MPI (libopenmpi-dev absent)";
  if (!have_mpirun()) GTEST_SKIP() << "mpirun is not installed (openmpi-bin)";
  const auto dir = test::campaign_folder("mpi");
  {
    auto campaign = load_campaign((dir / "campaign.toml").string()).value();
    auto store = ResultsStore::open(dir / "local.sqlite").value();
    PoolOptions pool;
    pool.scratch = dir / "runs";
    ASSERT_TRUE(run_into_store(campaign, store, pool).ok());
  }
  const std::string command = "mpirun --allow-run-as-root --oversubscribe -n 2 '" + std::string(VISORS_BINARY) + "' mc '" +
                              (dir / "campaign.toml").string() + "' --threads 1 --out '" + (dir / "mpi").string() +
                              "' > '" + (dir / "mpirun.log").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  const std::string local = test::database_content(dir / "local.sqlite");
  const std::string ranks = std::filesystem::exists(dir / "mpi" / "results.sqlite")
                                ? test::database_content(dir / "mpi" / "results.sqlite")
                                : std::string("no database");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(status, 0);
  EXPECT_EQ(local, ranks);
}

}  // namespace
}  // namespace visors::mc
