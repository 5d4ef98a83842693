#include "visors/gnss/files/sp3_file.hpp"

#include <algorithm>
#include <cmath>

#include "visors/gnss/files/text_file.hpp"

namespace visors::gnss::files {

namespace {

constexpr double kMissingClock = 999999.0;  // [us]; the file writes 999999.999999

// "*  2010  7  1  0  0  0.00000000" (SP3-d Table 2: year 4-7, month 9-10, day 12-13, hour 15-16,
// minute 18-19, second 21-31, 1-based columns).
constexpr CalendarColumns kEpochColumns{{3, 4}, {8, 2}, {11, 2}, {14, 2}, {17, 2}, {20, 11}};

}  // namespace

const Sp3Orbit::Sample* Sp3Orbit::sample(int prn, std::size_t index) const {
  if (prn < 1 || prn > kMaxGpsPrn || index >= epochs_.size()) return nullptr;
  return &samples_[index * kSlots + static_cast<std::size_t>(prn - 1)];
}

std::optional<Eigen::Vector3d> Sp3Orbit::position_m(int prn, std::size_t index) const {
  const Sample* s = sample(prn, index);
  if (s == nullptr || !s->has_position) return std::nullopt;
  return s->r_m;
}

std::optional<double> Sp3Orbit::clock_s(int prn, std::size_t index) const {
  const Sample* s = sample(prn, index);
  if (s == nullptr || !s->has_clock) return std::nullopt;
  return s->clock_s;
}

core::Result<Sp3Orbit> Sp3Orbit::read(const std::filesystem::path& path) {
  auto opened = TextFile::open(path, "SP3 file");
  if (!opened) return opened.error();
  TextFile file = std::move(opened).value();
  Sp3Orbit orbit;
  std::string line;
  long long announced_epochs = -1;
  bool time_system_seen = false, ended = false;
  while (file.next(line)) {
    if (file.line_number() == 1) {
      if (line.size() < 2 || line[0] != '#' || (line[1] != 'c' && line[1] != 'd')) {
        return file.error("the first line must start with #c or #d (SP3-c / SP3-d)");
      }
      orbit.version_ = line[1];
      const auto count = parse_integer(column(line, 32, 7), "number of epochs (columns 33-39)");
      if (!count) return file.error(count.error().describe());
      if (!*count || **count < 1) return file.error("number of epochs (columns 33-39) must be >= 1");
      announced_epochs = **count;
      orbit.coordinate_system_ = std::string(trim(column(line, 46, 5)));
      continue;
    }
    if (ended) {
      if (!trim(line).empty()) return file.error("text after the EOF line");
      continue;
    }
    if (line.rfind("%c", 0) == 0 && !time_system_seen) {
      time_system_seen = true;
      const std::string_view system = trim(column(line, 9, 3));
      if (system != "GPS") return file.error("time system (columns 10-12) '" + std::string(system) + "': only GPS is supported");
      continue;
    }
    if (line.rfind("EOF", 0) == 0) {
      ended = true;
      continue;
    }
    if (line.rfind("* ", 0) == 0) {
      const auto t = parse_gps_calendar(line, kEpochColumns);
      if (!t) return file.error("epoch line: " + t.error().describe());
      if (!orbit.epochs_.empty() && *t <= orbit.epochs_.back()) return file.error("epoch is not after the previous one");
      orbit.epochs_.push_back(*t);
      orbit.samples_.resize(orbit.epochs_.size() * kSlots);
      continue;
    }
    if (line.empty() || line[0] != 'P') continue;  // headers, comments, velocity and correlation records
    if (orbit.epochs_.empty()) return file.error("position record before the first epoch line");
    const char system = line.size() > 1 ? line[1] : ' ';
    if (system != 'G' && system != ' ') continue;
    const auto prn = parse_integer(column(line, 2, 2), "satellite number (columns 3-4)");
    if (!prn) return file.error(prn.error().describe());
    if (!*prn || **prn < 1 || **prn > kMaxGpsPrn) return file.error("satellite number (columns 3-4) must be in 1..32");
    if (line.size() < 46) return file.error("position record is truncated (the x, y, z fields end at column 46)");
    Eigen::Vector3d r_km;
    const char* names[] = {"x (columns 5-18)", "y (columns 19-32)", "z (columns 33-46)"};
    for (int k = 0; k < 3; ++k) {
      const auto value = parse_number(column(line, 4 + 14 * static_cast<std::size_t>(k), 14), names[k]);
      if (!value) return file.error(value.error().describe());
      if (!*value) return file.error(std::string(names[k]) + " is blank");
      r_km(k) = **value;
    }
    const auto clock = parse_number(column(line, 46, 14), "clock (columns 47-60)");
    if (!clock) return file.error(clock.error().describe());
    Sample& s = orbit.samples_[(orbit.epochs_.size() - 1) * kSlots + static_cast<std::size_t>(**prn - 1)];
    s.has_position = r_km.squaredNorm() > 0.0;
    s.r_m = 1000.0 * r_km;
    s.has_clock = *clock && **clock < kMissingClock;
    s.clock_s = s.has_clock ? **clock * 1e-6 : 0.0;
  }
  if (file.line_number() == 0) return file.file_error("empty file: not an SP3 file");
  if (!time_system_seen) return file.file_error("no %c line with the time system: the header is truncated");
  if (static_cast<long long>(orbit.epochs_.size()) != announced_epochs) {
    return file.file_error("the header announces " + std::to_string(announced_epochs) + " epochs, the file has " +
                           std::to_string(orbit.epochs_.size()) + " (truncated?)");
  }
  return orbit;
}

core::Result<Eigen::Vector3d> Sp3Orbit::interpolate_m(int prn, core::GpsTime t) const {
  constexpr std::size_t kPoints = 10;
  if (epochs_.size() < kPoints) return core::Error{"t", "interpolation needs at least 10 epochs"};
  if (t < epochs_.front() || t > epochs_.back()) return core::Error{"t", "outside the file's span"};
  const auto after = static_cast<std::size_t>(std::upper_bound(epochs_.begin(), epochs_.end(), t) - epochs_.begin());
  const std::size_t first = std::min(after > kPoints / 2 ? after - kPoints / 2 : 0, epochs_.size() - kPoints);
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t j = first; j < first + kPoints; ++j) {
    const Sample* s = sample(prn, j);
    if (s == nullptr || !s->has_position) {
      std::string message = "G";
      message += std::to_string(prn);
      message += " has no position at ";
      message += epochs_[j].format(core::TimeScale::kGps, 0);
      return core::Error{"prn", message};
    }
    double weight = 1.0;
    const double tj = epochs_[j].seconds_since(epochs_[first]);
    const double x = t.seconds_since(epochs_[first]);
    for (std::size_t m = first; m < first + kPoints; ++m) {
      if (m == j) continue;
      const double tm = epochs_[m].seconds_since(epochs_[first]);
      weight *= (x - tm) / (tj - tm);
    }
    r += weight * s->r_m;
  }
  return r;
}

Sp3Orbit Sp3Orbit::without_epoch(std::size_t index) const {
  Sp3Orbit copy = *this;
  if (index >= epochs_.size()) return copy;
  copy.epochs_.erase(copy.epochs_.begin() + static_cast<std::ptrdiff_t>(index));
  copy.samples_.erase(copy.samples_.begin() + static_cast<std::ptrdiff_t>(index * kSlots),
                      copy.samples_.begin() + static_cast<std::ptrdiff_t>((index + 1) * kSlots));
  return copy;
}

}  // namespace visors::gnss::files
