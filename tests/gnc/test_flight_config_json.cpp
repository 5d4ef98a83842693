// The flight configuration file (gnc/files/flight_config_json.hpp): what a visors-fsw process is
// created from must be what the simulator's in-process component is created from, bit for bit.
// The round trip is tested with every number and flag of a component's object changed to a
// value of its own (so a key read into the wrong field, or not read, shows), the doubles chosen
// to need all 17 significant digits.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "visors/gnc/files/flight_config_json.hpp"

namespace visors::gnc::files {
namespace {

ComponentSetup with_navigation() {
  ComponentSetup setup;
  NavigationSetup navigation;
  navigation.force_model = dynamics::ForceModelConfig::onboard();
  navigation.force_model.drag.activity.ap_history = std::array<double, 7>{1, 2, 3, 4, 5, 6, 7};
  setup.navigation = navigation;
  return setup;
}

// Every number and boolean of `j` replaced by one of its own: integers 1, 2, 3, ... (in the
// order of the walk), doubles k / 3 + 1e-9 k, booleans flipped.
void make_every_value_distinct(nlohmann::json& j, int& k) {
  if (j.is_object() || j.is_array()) {
    for (auto& child : j) make_every_value_distinct(child, k);
  } else if (j.is_boolean()) {
    j = !j.get<bool>();
  } else if (j.is_number_integer()) {
    j = ++k;
  } else if (j.is_number_float()) {
    ++k;
    j = k / 3.0 + 1e-9 * k;
  }
}

TEST(FlightConfigJson, EveryValueReadsBackToItsOwnField) {
  nlohmann::json written = to_json(with_navigation());
  int k = 0;
  make_every_value_distinct(written, k);
  auto read = component_setup_from_json(written);
  ASSERT_TRUE(read.ok()) << read.error().describe();
  EXPECT_EQ(to_json(read.value()).dump(), written.dump());
}

// The parts a component with navigation is created from: its GNC, navigation and force models.
TEST(FlightConfigJson, TheComponentObjectHoldsEveryPart) {
  const nlohmann::json j = to_json(with_navigation());
  EXPECT_TRUE(j.contains("gnc") && j.contains("navigation") && j.at("force_models").contains("config") &&
              j.at("force_models").contains("dsc") && j.at("force_models").contains("osc"));
}

// The doubles of the file are the shortest text that reads back to the same bits.
TEST(FlightConfigJson, ADoubleReadsBackBitForBit) {
  ComponentSetup setup;
  setup.gnc.mass_kg = 0.1 + 0.2;  // 0.30000000000000004
  const auto read = component_setup_from_json(nlohmann::json::parse(to_json(setup).dump()));
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.value().gnc.mass_kg, 0.1 + 0.2);
}

TEST(FlightConfigJson, WithoutNavigationTheComponentHasNone) {
  const auto read = component_setup_from_json(to_json(ComponentSetup{}));
  ASSERT_TRUE(read.ok());
  EXPECT_FALSE(read.value().navigation.has_value());
}

TEST(FlightConfigJson, AMissingKeyIsNamed) {
  nlohmann::json j = to_json(with_navigation());
  j["navigation"]["filter"].erase("gate_sigmas");
  const auto read = component_setup_from_json(j);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().field, "navigation");
  EXPECT_NE(read.error().message.find("gate_sigmas"), std::string::npos) << read.error().message;
}

TEST(FlightConfigJson, AValueOfTheWrongTypeIsRefused) {
  nlohmann::json j = to_json(ComponentSetup{});
  j["gnc"]["burn_latency_s"] = "ten";
  const auto read = component_setup_from_json(j);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().field, "gnc");
}

TEST(FlightConfigJson, AVectorOfTheWrongLengthIsRefused) {
  nlohmann::json j = to_json(with_navigation());
  j["navigation"]["antenna_arp_body_m"] = {0.0, 0.1};
  const auto read = component_setup_from_json(j);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find("3 numbers"), std::string::npos) << read.error().message;
}

TEST(FlightConfigJson, TooManyBurnTimesAreRefused) {
  nlohmann::json j = to_json(ComponentSetup{});
  j["gnc"]["science"]["least_squares_burns_before_s"] = std::vector<double>(control::kMaxLeastSquaresBurns + 1, 100.0);
  const auto read = component_setup_from_json(j);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find("least_squares_burns_before_s"), std::string::npos) << read.error().message;
}

class FlightConfigFile : public ::testing::Test {
 protected:
  std::filesystem::path path_ =
      std::filesystem::temp_directory_path() / ("flight_config_test_" + std::to_string(::getpid()) + ".json");
  void write(const std::string& text) { std::ofstream(path_) << text; }
  void TearDown() override { std::filesystem::remove(path_); }
};

TEST_F(FlightConfigFile, ReadsTheObjectOfTheSpacecraft) {
  ComponentSetup osc;
  osc.gnc.self = Spacecraft::kOsc;
  osc.gnc.mass_kg = 9.75;
  write(nlohmann::json{{"dsc", to_json(ComponentSetup{})}, {"osc", to_json(osc)}}.dump());
  const auto read = read_component_setup(path_, "osc");
  ASSERT_TRUE(read.ok()) << read.error().describe();
  EXPECT_EQ(read.value().gnc.mass_kg, 9.75);
}

TEST_F(FlightConfigFile, AMissingSpacecraftIsNamed) {
  write(nlohmann::json{{"dsc", to_json(ComponentSetup{})}}.dump());
  const auto read = read_component_setup(path_, "osc");
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find("\"osc\""), std::string::npos) << read.error().message;
}

TEST_F(FlightConfigFile, TextThatIsNotJsonIsRefused) {
  write("{\"dsc\": ");
  const auto read = read_component_setup(path_, "dsc");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().message, "is not valid JSON");
}

TEST_F(FlightConfigFile, AFileThatIsNotThereIsNamed) {
  const auto read = read_component_setup(path_, "dsc");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().field, path_.string());
}

// The error of a bad key names the file, the spacecraft and the part.
TEST_F(FlightConfigFile, AnErrorNamesTheFileTheSpacecraftAndThePart) {
  nlohmann::json dsc = to_json(ComponentSetup{});
  dsc["gnc"].erase("standby");
  write(nlohmann::json{{"dsc", dsc}}.dump());
  const auto read = read_component_setup(path_, "dsc");
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.error().field, path_.string());
  EXPECT_EQ(read.error().message.rfind("dsc.gnc: ", 0), 0U) << read.error().message;
}

}  // namespace
}  // namespace visors::gnc::files
