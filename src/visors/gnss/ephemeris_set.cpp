#include "visors/gnss/ephemeris_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

const char* to_string(RecordStatus status) {
  switch (status) {
    case RecordStatus::kUsable: return "usable";
    case RecordStatus::kUnhealthy: return "unhealthy";
    case RecordStatus::kImplausible: return "implausible";
    case RecordStatus::kInconsistent: return "inconsistent";
  }
  return "?";
}

namespace {

std::string describe(const ScreenedEphemeris& other, const RecordDisagreement& d) {
  char text[160];
  std::snprintf(text, sizeof text, "%.0f km and %.0f m of clock from the record of t_oe %s (line %zu)",
                d.position_m / 1000.0, d.clock_m, other.ephemeris.toe.format(core::TimeScale::kGps, 0).c_str(),
                other.source_line);
  return text;
}

// Marks the records of one PRN, [begin, end), that disagree with their neighbours.
void mark_inconsistent(std::vector<ScreenedEphemeris>& records, std::size_t begin, std::size_t end) {
  std::vector<std::size_t> plausible;
  for (std::size_t k = begin; k < end; ++k) {
    if (records[k].status != RecordStatus::kImplausible) plausible.push_back(k);
  }
  const auto near = [&](std::size_t a, std::size_t b) {
    return std::abs(records[a].ephemeris.toe.seconds_since(records[b].ephemeris.toe)) <= EphemerisSet::kNeighbourWindowS;
  };
  std::vector<std::string> reasons(end - begin);  // of records [begin, end)
  for (std::size_t k : plausible) {
    std::vector<std::size_t> neighbours;
    bool agrees_with_one = false;
    std::string reason;
    for (std::size_t j : plausible) {
      if (j == k || !near(j, k)) continue;
      neighbours.push_back(j);
      const RecordDisagreement d = disagreement(records[k].ephemeris, records[j].ephemeris);
      if (d.agrees()) {
        agrees_with_one = true;
        break;
      }
      if (reason.empty()) reason = "disagrees with its neighbours: " + describe(records[j], d);
    }
    if (agrees_with_one || neighbours.empty()) continue;
    bool neighbours_agree = neighbours.size() == 1;  // a lone pair: both are suspect
    for (std::size_t a = 0; a < neighbours.size() && !neighbours_agree; ++a) {
      for (std::size_t b = a + 1; b < neighbours.size() && !neighbours_agree; ++b) {
        neighbours_agree = near(neighbours[a], neighbours[b]) &&
                           disagreement(records[neighbours[a]].ephemeris, records[neighbours[b]].ephemeris).agrees();
      }
    }
    if (neighbours_agree) reasons[k - begin] = std::move(reason);
  }
  for (std::size_t k = begin; k < end; ++k) {
    if (reasons[k - begin].empty()) continue;
    records[k].status = RecordStatus::kInconsistent;
    records[k].reason = std::move(reasons[k - begin]);
  }
}

}  // namespace

EphemerisSet EphemerisSet::screen(std::span<const BroadcastEphemeris> records, std::span<const std::size_t> source_lines) {
  EphemerisSet set;
  set.records_.reserve(records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    ScreenedEphemeris s{records[k], RecordStatus::kUsable, {}, k < source_lines.size() ? source_lines[k] : 0};
    if (const auto valid = validate(s.ephemeris); !valid) {
      s.status = RecordStatus::kImplausible;
      s.reason = valid.error().describe();
    }
    set.records_.push_back(std::move(s));
  }
  std::sort(set.records_.begin(), set.records_.end(), [](const ScreenedEphemeris& a, const ScreenedEphemeris& b) {
    const auto& x = a.ephemeris;
    const auto& y = b.ephemeris;
    if (x.prn != y.prn) return x.prn < y.prn;
    if (x.toe != y.toe) return x.toe < y.toe;
    return x.transmission < y.transmission;
  });
  set.first_of_prn_.assign(kMaxGpsPrn + 2, set.records_.size());
  for (std::size_t k = set.records_.size(); k-- > 0;) {
    const int prn = set.records_[k].ephemeris.prn;
    if (prn >= 0 && prn <= kMaxGpsPrn) set.first_of_prn_[static_cast<std::size_t>(prn)] = k;
  }
  for (std::size_t p = set.first_of_prn_.size() - 1; p-- > 0;) {
    set.first_of_prn_[p] = std::min(set.first_of_prn_[p], set.first_of_prn_[p + 1]);
  }
  for (int prn = 1; prn <= kMaxGpsPrn; ++prn) {
    mark_inconsistent(set.records_, set.first_of_prn_[static_cast<std::size_t>(prn)],
                      set.first_of_prn_[static_cast<std::size_t>(prn) + 1]);
  }
  for (auto& s : set.records_) {
    if (s.status == RecordStatus::kUsable && s.ephemeris.health != 0) {
      s.status = RecordStatus::kUnhealthy;
      s.reason = "SV health " + std::to_string(s.ephemeris.health);
    }
  }
  return set;
}

const BroadcastEphemeris* EphemerisSet::select(int prn, core::GpsTime t) const {
  const BroadcastEphemeris* best = nearest(prn, t);
  return best != nullptr && within_fit_interval(*best, t) ? best : nullptr;
}

const BroadcastEphemeris* EphemerisSet::nearest(int prn, core::GpsTime t) const {
  if (prn < 1 || prn > kMaxGpsPrn) return nullptr;
  const BroadcastEphemeris* best = nullptr;
  double best_distance = 0.0;
  for (std::size_t k = first_of_prn_[static_cast<std::size_t>(prn)]; k < first_of_prn_[static_cast<std::size_t>(prn) + 1];
       ++k) {
    const ScreenedEphemeris& s = records_[k];
    if (s.status != RecordStatus::kUsable) continue;
    const double distance = std::abs(t.seconds_since(s.ephemeris.toe));
    if (best == nullptr || distance <= best_distance) {  // sorted: on a tie the later transmission wins
      best = &s.ephemeris;
      best_distance = distance;
    }
  }
  return best;
}

std::size_t EphemerisSet::count(RecordStatus status) const {
  return static_cast<std::size_t>(
      std::count_if(records_.begin(), records_.end(), [status](const ScreenedEphemeris& s) { return s.status == status; }));
}

}  // namespace visors::gnss
