#include "visors/baseline/double_difference_system.hpp"

#include <cmath>

namespace visors::baseline {
namespace {

double residual(const SingleDifference& sd, Observable kind, int f) {
  const auto fi = static_cast<std::size_t>(f);
  return kind == Observable::kPhase ? sd.phase_m[fi] : sd.code_m[fi];
}

double variance(const SingleDifference& sd, Observable kind, int f) {
  const auto fi = static_cast<std::size_t>(f);
  return kind == Observable::kPhase ? sd.phase_var_m2[fi] : sd.code_var_m2[fi];
}

}  // namespace

std::vector<DdGroup> make_groups(const std::vector<SingleDifference>& sds, Observable kind,
                                 const std::function<bool(int, int)>& usable) {
  std::vector<DdGroup> groups;
  for (int f = 0; f < kFrequencies; ++f) {
    DdGroup g;
    g.kind = kind;
    g.frequency = f;
    std::vector<int> candidates;
    for (int i = 0; i < static_cast<int>(sds.size()); ++i) {
      if (std::isfinite(residual(sds[static_cast<std::size_t>(i)], kind, f)) && usable(i, f)) candidates.push_back(i);
    }
    if (candidates.size() < 2) continue;
    g.reference = candidates.front();
    for (int i : candidates) {
      if (sds[static_cast<std::size_t>(i)].elevation_rad > sds[static_cast<std::size_t>(g.reference)].elevation_rad) {
        g.reference = i;
      }
    }
    for (int i : candidates) {
      if (i != g.reference) g.members.push_back(i);
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

DdSystem build_dd_system(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& groups,
                         bool with_ambiguities) {
  Eigen::Index m = 0;
  for (const auto& g : groups) m += static_cast<Eigen::Index>(g.members.size());
  DdSystem s;
  s.y.setZero(m);
  s.H.setZero(m, with_ambiguities ? kStates : kPositionStates);
  s.R.setZero(m, m);
  Eigen::Index row = 0;
  for (const auto& g : groups) {
    const SingleDifference& ref = sds[static_cast<std::size_t>(g.reference)];
    const double ref_var = variance(ref, g.kind, g.frequency);
    const Eigen::Index first = row;
    for (int member : g.members) {
      const SingleDifference& sd = sds[static_cast<std::size_t>(member)];
      s.y(row) = residual(sd, g.kind, g.frequency) - residual(ref, g.kind, g.frequency);
      s.H.block<1, 3>(row, 0) = -(sd.los_rover - ref.los_rover).transpose();
      if (with_ambiguities && g.kind == Observable::kPhase) {
        s.H(row, ambiguity_index(g.frequency, sd.prn)) = wavelength_m(g.frequency);
        s.H(row, ambiguity_index(g.frequency, ref.prn)) = -wavelength_m(g.frequency);
      }
      s.R(row, row) = variance(sd, g.kind, g.frequency);
      s.rows.push_back({g.kind, g.frequency, sd.prn, ref.prn});
      ++row;
    }
    s.R.block(first, first, row - first, row - first).array() += ref_var;
  }
  return s;
}

}  // namespace visors::baseline
