// The navigation filter's settings from a [nav] TOML table (config/cdgps_settings_toml.hpp), as
// `visors nav --settings FILE` reads them: keys are CdgpsSettings' field names, errors name
// "nav.<key>".
#include <gtest/gtest.h>

#include "visors/config/cdgps_settings_toml.hpp"
#include "visors/config/toml_fields.hpp"

namespace visors::config {
namespace {

core::Result<nav::CdgpsSettings> read(const std::string& text) {
  auto table = toml_fields::parse(text);
  EXPECT_TRUE(table.ok());
  nav::CdgpsSettings s;
  if (auto ok = read_cdgps_settings(table.value(), s); !ok) return ok.error();
  return s;
}

TEST(CdgpsSettingsToml, WithoutANavTableTheDefaultsStay) {
  const auto s = read("[other]\nx = 1\n");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.value().sdcp_sigma_m, nav::CdgpsSettings{}.sdcp_sigma_m);
}

TEST(CdgpsSettingsToml, ReadsANumber) {
  const auto s = read("[nav]\nsdcp_sigma_m = 0.004\n");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.value().sdcp_sigma_m, 0.004);
}

TEST(CdgpsSettingsToml, ReadsAFlag) {
  const auto s = read("[nav]\nsd_code = false\n");
  ASSERT_TRUE(s.ok());
  EXPECT_FALSE(s.value().sd_code);
}

TEST(CdgpsSettingsToml, ReadsTheAcceptanceTable) {
  const auto s = read("[nav.acceptance]\nmin_ratio = 2.5\nmin_partial = 6\n");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.value().acceptance.min_ratio, 2.5);
  EXPECT_EQ(s.value().acceptance.min_partial, 6);
}

TEST(CdgpsSettingsToml, UnknownKeyIsNamed) {
  const auto s = read("[nav]\nsdcp_sigma = 0.004\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "nav.sdcp_sigma");
}

TEST(CdgpsSettingsToml, WrongTypeIsNamed) {
  const auto s = read("[nav]\nhold = 1\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "nav.hold");
}

// The filter's own check (nav::check) with the table's prefix.
TEST(CdgpsSettingsToml, ValueTheFilterRefusesIsNamed) {
  const auto s = read("[nav]\ngate_sigmas = -1.0\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "nav.gate_sigmas");
}

TEST(CdgpsSettingsToml, AcceptanceValueTheFilterRefusesIsNamed) {
  const auto s = read("[nav.acceptance]\nmin_ratio = 0.5\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "nav.acceptance.min_ratio");
}

}  // namespace
}  // namespace visors::config
