#include "visors/sim/data_provenance.hpp"

#include <fstream>
#include <utility>

#include <fmt/format.h>

#include "visors/core/files/data_path.hpp"

namespace visors::sim {

core::Result<DataFileUse> describe_data_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return core::Error{path.string(), "cannot be read"};
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  std::int64_t size = 0;
  std::vector<char> buffer(1 << 16);
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash = (hash ^ static_cast<unsigned char>(buffer[static_cast<std::size_t>(i)])) * 0x100000001b3ULL;
    }
    size += in.gcount();
  }
  DataFileUse use;
  use.path = path.string();
  use.size = size;
  use.checksum = fmt::format("{:016x}", hash);
  return use;
}

std::vector<DataFileUse> data_files_of(const CampaignScenario& s) {
  // The NRLMSISE-00 tables are read only when the truth's drag uses that model.
  const std::string none;
  const bool msis = s.forces.drag.enabled && s.forces.drag.atmosphere == dynamics::AtmosphereKind::kNrlmsise00;
  const std::pair<const char*, const std::string*> keys[] = {
      {"gnss.nav_file", &s.gnss.nav_file},
      {"forces.gravity.model", &s.forces.gravity.model},
      {"forces.drag.nrlmsise00_coefficients", msis ? &s.forces.drag.nrlmsise00_coefficients : &none},
      {"forces.drag.space_weather", &s.forces.drag.space_weather},
      {"forces.earth_frame.eop", &s.forces.earth_frame.eop},
      {"flight.eop_file", s.navigation_mode == NavigationMode::kCdgps ? &s.flight.eop_file : &none}};
  std::vector<DataFileUse> out;
  for (const auto& [key, name] : keys) {
    if (name->empty()) continue;
    DataFileUse use;
    if (const auto path = core::files::find_data_file(*name)) {
      if (auto described = describe_data_file(*path); described.ok()) use = *described;
    }
    use.key = key;
    use.name = *name;
    out.push_back(use);
  }
  return out;
}

}  // namespace visors::sim
