// libFuzzer target of the flight component's input handling (gnc/record_interface.hpp): the
// input is cut into records (each a length byte, then that many bytes, sealed as a record of the
// channel its first byte names, so that the payload and value checks are reached), and one step
// of a component is run with them after a valid warm-up (standby, a navigation solution, so the
// control stack and the safety check run on whatever gets through). The step must return a
// telemetry record that decodes, with finite values; sanitizers catch the rest. Built with clang
// only (CMake option VISORS_FUZZ); run by scripts/fuzz.sh.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "visors/gnc/crc32c.hpp"
#include "visors/gnc/record_interface.hpp"

namespace {

using namespace visors::gnc;
using visors::core::GpsTime;

const GpsTime kT0 = GpsTime::from_seconds(1.4e9);

// A navigation solution of the 200 m standby formation (values only need to be plausible).
NavigationSolution standby_solution(GpsTime t) {
  NavigationSolution s;
  s.t = t;
  s.chief_gcrf = {Eigen::Vector3d(6878137.0, 0.0, 0.0), Eigen::Vector3d(0.0, -1007.0, 7546.0)};
  s.deputy_gcrf = {Eigen::Vector3d(6878137.0, 150.0, 200.0), Eigen::Vector3d(0.1, -1007.0, 7546.0)};
  s.relative_covariance_rtn = Eigen::Matrix<double, 6, 6>::Identity() * 1e-4;
  return s;
}

struct Sealed {
  RecordBuffer bytes{};
  std::size_t size = 0;
};

Sealed seal(const std::uint8_t* data, std::size_t length) {
  Sealed r;
  const auto channel = static_cast<Channel>(1 + (length > 0 ? data[0] % kChannels : 0));
  r.size = record_size(channel);
  for (std::size_t i = 0; i < r.size && i < length; ++i) r.bytes[i] = data[i];
  r.bytes[0] = 'V';
  r.bytes[1] = 'G';
  r.bytes[2] = static_cast<std::uint8_t>(channel);
  r.bytes[3] = kRecordVersion;
  r.bytes[4] = static_cast<std::uint8_t>(r.size);
  r.bytes[5] = static_cast<std::uint8_t>(r.size >> 8);
  const std::uint32_t crc = crc32c(std::span<const std::uint8_t>(r.bytes).first(r.size - kChecksumBytes));
  for (std::size_t i = 0; i < 4; ++i) r.bytes[r.size - 4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  RecordInterface gnc = RecordInterface::create(GncConfig{}).value();  // the same warm start for every input
  {
    RecordBuffer a{}, b{};
    const RecordView warm[2] = {RecordView(a.data(), encode(standby_solution(kT0), 0, a)),
                                RecordView(b.data(), encode(GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0}, 0, b))};
    (void)gnc.step(kT0, warm);
  }
  std::vector<Sealed> records;
  std::vector<RecordView> views;
  for (std::size_t pos = 0; pos < size && records.size() < 16;) {
    const std::size_t length = std::min<std::size_t>(data[pos], size - pos - 1);
    records.push_back(seal(data + pos + 1, length));
    pos += 1 + length;
  }
  for (const Sealed& r : records) views.emplace_back(r.bytes.data(), r.size);
  const OutputRecords& out = gnc.step(kT0 + 1.0, views);
  Telemetry tm;
  RecordHeader header;
  if (decode(out.telemetry.view(), tm, header) != RecordStatus::kAccepted) std::abort();
  if (!tm.roe_mean_m.allFinite() || !std::isfinite(tm.safety_margin_m)) std::abort();
  return 0;
}
