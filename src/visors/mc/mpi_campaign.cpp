#include "visors/mc/mpi_campaign.hpp"

#include <cstdint>
#include <cstdlib>
#include <vector>

#ifdef VISORS_HAVE_MPI
#include <mpi.h>
#endif

namespace visors::mc {

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr; }

#ifdef VISORS_HAVE_MPI

namespace {

constexpr int kRequestTag = 1;
constexpr int kWorkTag = 2;

class MpiWorkers final : public RemoteWorkers {
 public:
  explicit MpiWorkers(int ranks) : workers_(ranks - 1) {}

  core::Result<bool> serve(const Next& next, const Done& done) override {
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &arrived, &status);
      if (arrived == 0) return true;
      const std::string payload = receive(status);
      if (!payload.empty()) {
        --outstanding_;
        auto record = run_record_from_json_text(payload);
        if (!record.ok()) return record.error();
        if (auto ok = done(*record); !ok) return ok;
      }
      const std::optional<std::int64_t> index = next();
      reply(status.MPI_SOURCE, index.value_or(-1));
      if (index) ++outstanding_;
      else ++stopped_;
    }
  }

  [[nodiscard]] std::int64_t outstanding() const override { return outstanding_; }

  void finish() override {
    while (stopped_ < workers_) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &status);
      (void)receive(status);  // a run finished after an error stopped the campaign: not stored
      reply(status.MPI_SOURCE, -1);
      ++stopped_;
    }
  }

 private:
  static std::string receive(const MPI_Status& status) {
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    std::string text(static_cast<std::size_t>(bytes), '\0');
    MPI_Recv(text.data(), bytes, MPI_CHAR, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return text;
  }
  static void reply(int rank, std::int64_t index) { MPI_Send(&index, 1, MPI_INT64_T, rank, kWorkTag, MPI_COMM_WORLD); }

  int workers_;
  int stopped_ = 0;
  std::int64_t outstanding_ = 0;
};

void broadcast(std::string& text) {
  std::uint64_t size = text.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  text.resize(size);
  MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
}

}  // namespace

bool mpi_available() { return true; }

core::Result<std::unique_ptr<MpiSession>> MpiSession::start() {
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) return core::Error{"mpi", "MPI_Init failed"};
  std::unique_ptr<MpiSession> session(new MpiSession());
  MPI_Comm_rank(MPI_COMM_WORLD, &session->rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &session->size_);
  return session;
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void MpiSession::share_campaign(std::string& campaign_text, std::string& scenario_text) const {
  broadcast(campaign_text);
  broadcast(scenario_text);
}

std::unique_ptr<RemoteWorkers> mpi_remote_workers(const MpiSession& session) {
  return std::make_unique<MpiWorkers>(session.size());
}

void serve_as_worker(const MpiSession&, const std::function<RunRecord(std::int64_t)>& execute) {
  std::string payload;  // the previous run's record (empty: the first request)
  for (;;) {
    MPI_Send(payload.data(), static_cast<int>(payload.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD);
    std::int64_t index = -1;
    MPI_Recv(&index, 1, MPI_INT64_T, 0, kWorkTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    payload = to_json_text(execute(index));
  }
}

#else  // no MPI in this build

bool mpi_available() { return false; }

core::Result<std::unique_ptr<MpiSession>> MpiSession::start() {
  return core::Error{"mpi", "this visors was built without MPI (install libopenmpi-dev and rebuild)"};
}

MpiSession::~MpiSession() = default;
void MpiSession::share_campaign(std::string&, std::string&) const {}
std::unique_ptr<RemoteWorkers> mpi_remote_workers(const MpiSession&) { return nullptr; }
void serve_as_worker(const MpiSession&, const std::function<RunRecord(std::int64_t)>&) {}

#endif

}  // namespace visors::mc
