#include "visors/core/eop.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace visors::core {
std::string mjd_text(double mjd) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", mjd);
  return buf;
}

Result<EopTable> EopTable::create(std::vector<Row> rows) {
  if (rows.empty()) return Error{"rows", "needs at least one row"};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& r = rows[k];
    const std::string field = "rows[" + std::to_string(k) + "]";
    for (const double value : {r.mjd, r.xp, r.yp, r.ut1_minus_tai, r.lod, r.dx, r.dy}) {
      if (!std::isfinite(value)) return Error{field, "every value must be finite"};
    }
    if (k > 0 && r.mjd != rows[k - 1].mjd + 1.0) {
      return Error{field, "MJD " + mjd_text(r.mjd) + " does not follow " + mjd_text(rows[k - 1].mjd) +
                              " (rows must be consecutive days)"};
    }
  }
  return EopTable(std::move(rows));
}

Result<EarthOrientation> EopTable::at(GpsTime t) const {
  const double mjd = t.jd_utc().mjd();
  if (!(mjd >= first_mjd() && mjd <= last_mjd())) {
    return Error{"time", t.format(TimeScale::kUtc) + " UTC (MJD " + mjd_text(mjd) +
                             ") is outside the EOP table, MJD " + mjd_text(first_mjd()) + " to " +
                             mjd_text(last_mjd())};
  }
  std::size_t i = static_cast<std::size_t>(mjd - first_mjd());
  if (i + 1 >= rows_.size()) i = rows_.size() >= 2 ? rows_.size() - 2 : 0;
  const Row& a = rows_[i];
  const Row& b = rows_.size() >= 2 ? rows_[i + 1] : rows_[i];
  const double f = b.mjd > a.mjd ? (mjd - a.mjd) / (b.mjd - a.mjd) : 0.0;
  const auto lerp = [f](double u, double v) { return u + f * (v - u); };
  EarthOrientation eop;
  eop.xp = lerp(a.xp, b.xp);
  eop.yp = lerp(a.yp, b.yp);
  eop.dut1 = lerp(a.ut1_minus_tai, b.ut1_minus_tai) + t.tai_minus_utc();
  eop.lod = lerp(a.lod, b.lod);
  eop.dx = lerp(a.dx, b.dx);
  eop.dy = lerp(a.dy, b.dy);
  return eop;
}

}  // namespace visors::core
