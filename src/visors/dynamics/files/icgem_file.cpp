#include "visors/dynamics/files/icgem_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <system_error>
#include <vector>

#include "visors/core/files/data_path.hpp"

namespace visors::dynamics::files {
namespace {

// Degree above which a file is refused outright: the flat arrays would exceed ~40 MB, far above
// any use in this project (truth 90, on-board 20), so a larger value means a corrupt header.
constexpr int kMaxReadableDegree = 2190;

std::vector<std::string_view> split_tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// A real number with an e, E, d or D exponent (Fortran files use D), whole token, finite.
std::optional<double> parse_real(std::string_view token) {
  if (token.empty() || token.size() > 64) return std::nullopt;
  char buffer[65];
  std::size_t length = 0;
  for (const char ch : token) buffer[length++] = (ch == 'D' || ch == 'd') ? 'e' : ch;
  const char* begin = buffer;
  if (*begin == '+') ++begin;  // from_chars rejects a leading '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(begin, buffer + length, value);
  if (ec != std::errc() || end != buffer + length || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> parse_int(std::string_view token) {
  int value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// Normalisation factor N_nm = sqrt((2 - δ_0m)(2n+1)(n-m)!/(n+m)!)
// (docs/algorithms/dynamics.md#potential-and-normalisation), so that
// C̄ = C / N_nm. Long double keeps (n+m)!/(n-m)! in range and exact to ~1e-18 per factor.
double inverse_normalisation(int n, int m) {
  long double ratio = 1.0L;  // (n+m)!/(n-m)!
  for (int i = n - m + 1; i <= n + m; ++i) ratio *= static_cast<long double>(i);
  const long double k = (m == 0 ? 1.0L : 2.0L) * static_cast<long double>(2 * n + 1);
  return static_cast<double>(std::sqrt(ratio / k));
}

TideSystem parse_tide_system(std::string_view value) {
  if (value == "zero_tide") return TideSystem::kZeroTide;
  if (value == "tide_free") return TideSystem::kTideFree;
  if (value == "mean_tide") return TideSystem::kMeanTide;
  return TideSystem::kUnknown;
}

class IcgemReader {
 public:
  IcgemReader(const std::filesystem::path& file, int requested_degree)
      : file_(file), requested_(requested_degree) {}

  core::Result<GravityField> read() {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file_, ec)) return file_error("file not found or not a regular file");
    std::ifstream in(file_);
    if (!in) return file_error("cannot open the file for reading");
    if (requested_ < -1) return file_error("requested degree " + std::to_string(requested_) + " must be >= 0 (or -1 for all)");

    std::string line;
    bool in_header = true;
    while (std::getline(in, line)) {
      ++line_number_;
      const std::vector<std::string_view> tokens = split_tokens(line);
      if (tokens.empty()) continue;
      if (in_header) {
        if (tokens[0] == "end_of_head") {
          in_header = false;
          if (auto error = finish_header()) return *error;
          continue;
        }
        if (auto error = header_line(tokens)) return *error;
        continue;
      }
      if (tokens[0] == "end_of_head") continue;  // GGM01S/GGM05S repeat the marker line
      if (auto error = data_line(tokens)) return *error;
    }
    if (in_header) return file_error("no 'end_of_head' line: not an ICGEM .gfc file, or the header is truncated");
    return finish_data();
  }

 private:
  core::Error file_error(const std::string& problem) const { return {file_.string(), problem}; }
  core::Error line_error(const std::string& problem) const {
    return {file_.string() + ":" + std::to_string(line_number_), problem};
  }

  std::optional<core::Error> header_line(const std::vector<std::string_view>& tokens) {
    const std::string_view key = tokens[0];
    const bool numeric_key = key == "earth_gravity_constant" || key == "radius" || key == "max_degree";
    const bool text_key = key == "modelname" || key == "norm" || key == "tide_system";
    if (!numeric_key && !text_key) return std::nullopt;  // free text or a key we do not use
    if (tokens.size() < 2) return line_error("header key '" + std::string(key) + "' has no value");
    const std::string_view value = tokens[1];
    if (key == "earth_gravity_constant" || key == "radius") {
      const std::optional<double> x = parse_real(value);
      if (!x) return line_error("malformed number '" + std::string(value) + "' for header key " + std::string(key));
      if (*x <= 0.0) return line_error("header key " + std::string(key) + " must be > 0");
      (key == "radius" ? radius_ : gm_) = *x;
    } else if (key == "max_degree") {
      const std::optional<int> n = parse_int(value);
      if (!n) return line_error("malformed integer '" + std::string(value) + "' for header key max_degree");
      if (*n < 0 || *n > kMaxReadableDegree) {
        return line_error("header max_degree " + std::to_string(*n) + " outside [0, " +
                          std::to_string(kMaxReadableDegree) + "]");
      }
      header_degree_ = *n;
    } else if (key == "modelname") {
      field_.model_name = std::string(value);
    } else if (key == "norm") {
      if (value == "fully_normalized") {
        unnormalized_ = false;
      } else if (value == "unnormalized") {
        unnormalized_ = true;
      } else {
        return line_error("unknown norm '" + std::string(value) + "' (fully_normalized or unnormalized)");
      }
    } else {
      field_.tide_system = parse_tide_system(value);
    }
    return std::nullopt;
  }

  std::optional<core::Error> finish_header() {
    if (!gm_) return line_error("header key earth_gravity_constant missing before end_of_head");
    if (!radius_) return line_error("header key radius missing before end_of_head");
    if (!header_degree_) return line_error("header key max_degree missing before end_of_head");
    if (requested_ > *header_degree_) {
      return file_error("requested degree " + std::to_string(requested_) + " is above the file's max_degree " +
                        std::to_string(*header_degree_));
    }
    degree_ = requested_ < 0 ? *header_degree_ : requested_;
    field_.gm = *gm_;
    field_.radius = *radius_;
    field_.max_degree = degree_;
    const std::size_t count = GravityField::coefficient_count(degree_);
    field_.c_bar.assign(count, 0.0);
    field_.s_bar.assign(count, 0.0);
    seen_.assign(count, false);
    return std::nullopt;
  }

  std::optional<core::Error> data_line(const std::vector<std::string_view>& tokens) {
    const std::string_view kind = tokens[0];
    if (kind == "gfct" || kind == "trnd" || kind == "acos" || kind == "asin" || kind == "dot") {
      return line_error("time-variable record '" + std::string(kind) +
                        "' is not supported (static fields only; use a static model file)");
    }
    if (kind != "gfc") return line_error("unknown record type '" + std::string(kind) + "' (expected gfc)");
    if (tokens.size() < 5) return line_error("gfc line has " + std::to_string(tokens.size()) + " fields, expected 'gfc n m C S [sigmas]'");
    const std::optional<int> n = parse_int(tokens[1]);
    const std::optional<int> m = parse_int(tokens[2]);
    if (!n) return line_error("malformed degree n '" + std::string(tokens[1]) + "'");
    if (!m) return line_error("malformed order m '" + std::string(tokens[2]) + "'");
    if (*n < 0 || *m < 0) return line_error("negative degree or order (n=" + std::to_string(*n) + ", m=" + std::to_string(*m) + ")");
    if (*m > *n) return line_error("order m=" + std::to_string(*m) + " greater than degree n=" + std::to_string(*n));
    if (*n > *header_degree_) {
      return line_error("degree n=" + std::to_string(*n) + " above the header max_degree " + std::to_string(*header_degree_));
    }
    const std::optional<double> c = parse_real(tokens[3]);
    const std::optional<double> s = parse_real(tokens[4]);
    if (!c) return line_error("malformed number '" + std::string(tokens[3]) + "' for C");
    if (!s) return line_error("malformed number '" + std::string(tokens[4]) + "' for S");
    if (*n > degree_) return std::nullopt;  // truncated away (validated all the same)
    const std::size_t k = GravityField::index(*n, *m);
    if (seen_[k]) return line_error("duplicate coefficient (n=" + std::to_string(*n) + ", m=" + std::to_string(*m) + ")");
    seen_[k] = true;
    const double scale = unnormalized_ ? inverse_normalisation(*n, *m) : 1.0;
    field_.c_bar[k] = *c * scale;
    field_.s_bar[k] = *m == 0 ? 0.0 : *s * scale;  // S_n0 multiplies sin(0) = 0
    return std::nullopt;
  }

  core::Result<GravityField> finish_data() {
    // Degrees 0 and 1 may be absent (GGM01S, JGM3): C̄00 = 1 and the origin is the centre of mass.
    if (degree_ >= 0 && !seen_[0]) field_.c_bar[0] = 1.0;
    for (int n = 2; n <= degree_; ++n) {
      for (int m = 0; m <= n; ++m) {
        if (!seen_[GravityField::index(n, m)]) {
          return file_error("coefficients missing for degree " + std::to_string(n) + " (first missing: n=" +
                            std::to_string(n) + ", m=" + std::to_string(m) + ") after " +
                            std::to_string(line_number_) + " lines: truncated file? (needed to degree " +
                            std::to_string(degree_) + ")");
        }
      }
    }
    return std::move(field_);
  }

  std::filesystem::path file_;
  int requested_;
  int line_number_ = 0;
  std::optional<double> gm_;
  std::optional<double> radius_;
  std::optional<int> header_degree_;
  bool unnormalized_ = false;
  int degree_ = -1;
  std::vector<bool> seen_;
  GravityField field_;
};

}  // namespace

core::Result<GravityField> read_icgem(const std::filesystem::path& file, int max_degree) {
  return IcgemReader(file, max_degree).read();
}

core::Result<GravityField> load_gravity_field(const std::string& name_or_path, int degree) {
  const std::optional<std::filesystem::path> file = core::files::find_data_file(name_or_path);
  if (!file) {
    return core::Error{name_or_path,
                       "gravity model file not found (searched as given, then VISORS_DATA_PATH and the "
                       "repository data/ folder)"};
  }
  // Parsed once per (file, degree) for the life of the process: a campaign sets up five force
  // models from one file (the truth's, and two per on-board filter), and a Monte Carlo campaign's
  // runs, forked from a parent that loaded them, then parse none (~25 % of a run's set-up time).
  // The file is assumed unchanged while the process runs.
  static std::mutex mutex;
  static std::map<std::pair<std::string, int>, GravityField> parsed;
  const std::lock_guard lock(mutex);
  const auto key = std::make_pair(file->string(), degree);
  if (const auto it = parsed.find(key); it != parsed.end()) return it->second;
  auto field = read_icgem(*file, degree);
  if (field.ok()) parsed.emplace(key, field.value());
  return field;
}

}  // namespace visors::dynamics::files
