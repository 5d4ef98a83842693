// The records' field lists (gnc/record_schema.hpp) against what they promise, channel by channel:
// the layout's rows tile the record exactly; each channel's record of its fixture message equals
// its golden bytes (tests/gnc/golden/, every field annotated; the same file on every target:
// scripts/cross_test.sh runs this test under qemu); a changed byte, resealed with a valid
// checksum, is either refused or decodes to a message that encodes back to exactly those bytes
// (one message per record); padding, flags and enumerations refused with their reason; the
// tables of docs/record-layout.md are the lists'.
//
// Regenerate the golden files and the table after a deliberate change of the format (with a new
// kRecordVersion): VISORS_UPDATE_GOLDEN=1 build/tests/test_gnc --gtest_filter='RecordSchema*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "gnc/record_fixtures.hpp"
#include "visors/gnc/channel_record.hpp"
#include "visors/gnc/crc32c.hpp"
#include "visors/gnc/files/record_layout.hpp"

namespace visors::gnc {
namespace {

namespace fs = std::filesystem;

bool updating() { return std::getenv("VISORS_UPDATE_GOLDEN") != nullptr; }

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

template <class Message>
std::vector<std::uint8_t> record_of(const Message& m) {
  RecordBuffer buffer{};
  const std::size_t n = encode(m, 1, buffer);
  return {buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n)};
}

// The record with byte `offset` set to `value` and its checksum recomputed.
std::vector<std::uint8_t> resealed(std::vector<std::uint8_t> bytes, std::size_t offset, std::uint8_t value) {
  bytes[offset] = value;
  const std::size_t n = bytes.size();
  const std::uint32_t crc = crc32c(std::span<const std::uint8_t>(bytes).first(n - kChecksumBytes));
  for (std::size_t i = 0; i < 4; ++i) bytes[n - 4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  return bytes;
}

template <class Message>
RecordStatus decode_bytes(const std::vector<std::uint8_t>& bytes) {
  Message out{};
  RecordHeader h;
  return decode(std::span<const std::uint8_t>(bytes), out, h);
}

std::vector<files::LayoutRow> leaves(std::vector<files::LayoutRow> rows) {
  std::erase_if(rows, [](const files::LayoutRow& row) { return !row.leaf; });
  return rows;
}

// The golden file's text: a line per field of the record, its offset, its bytes in hex, its name.
template <class Message>
std::string golden_text(const Message& m) {
  using Schema = RecordSchema<Message>;
  const std::vector<std::uint8_t> bytes = record_of(m);
  std::ostringstream out;
  out << "# Channel " << static_cast<int>(Schema::kChannel) << ", " << Schema::kTitle << ": " << bytes.size()
      << " bytes, format version " << static_cast<int>(kRecordVersion) << ". The record of tests/gnc/record_fixtures.hpp's\n"
      << "# message, sequence 1 (tests/gnc/test_record_schema.cpp says how to regenerate it).\n"
      << "# offset | bytes | field\n";
  for (const files::LayoutRow& row : leaves(files::record_layout<Message>())) {
    char offset[16];
    std::snprintf(offset, sizeof offset, "%6zu", row.offset);
    out << offset << " |";
    for (std::size_t i = row.offset; i < row.offset + row.bytes && i < bytes.size(); ++i) {
      char hex[4];
      std::snprintf(hex, sizeof hex, " %02x", bytes[i]);
      out << hex;
    }
    out << " | " << row.instance << "\n";
  }
  return out.str();
}

template <class Message>
class RecordSchemaTest : public ::testing::Test {};

using Messages = ::testing::Types<TimeAtTone, NavigationSolution, CrosslinkMessage, GroundCommand, PropulsionTelemetry, GpsMessage,
                                  LaserRange, ManeuverCommand, ObservationCommand, Telemetry, NavigationTelemetry>;
TYPED_TEST_SUITE(RecordSchemaTest, Messages);

// The layout's fields follow each other without gap or overlap from the header to the checksum,
// and end at the channel's record size: the describe() offsets are the encoder's.
TYPED_TEST(RecordSchemaTest, TheFieldsTileTheRecord) {
  const std::vector<files::LayoutRow> rows = leaves(files::record_layout<TypeParam>());
  std::size_t next = 0;
  for (const files::LayoutRow& row : rows) {
    EXPECT_EQ(row.offset, next) << row.instance;
    next = row.offset + row.bytes;
  }
  EXPECT_EQ(next, record_size(RecordSchema<TypeParam>::kChannel));
}

// The record of the fixture message, byte for byte, against its golden file (written on x86-64,
// 2026-12-07, whose bytes the per-channel checksums of test_channel_record.cpp pinned before the
// codec was made from the field lists).
TYPED_TEST(RecordSchemaTest, TheRecordEqualsItsGoldenBytes) {
  using Schema = RecordSchema<TypeParam>;
  const fs::path path = fs::path(VISORS_SOURCE_DIR) / "tests/gnc/golden" /
                        ("channel_" + std::to_string(static_cast<int>(Schema::kChannel)) + ".txt");
  const std::string text = golden_text(test::record_fixture<TypeParam>());
  if (updating()) write_text(path, text);
  const std::string golden = read_text(path);
  ASSERT_FALSE(golden.empty()) << path << " is missing";
  const std::vector<std::string> expected = lines(golden), actual = lines(text);
  for (std::size_t i = 0; i < std::min(expected.size(), actual.size()); ++i) {
    ASSERT_EQ(actual[i], expected[i]) << path << ":" << i + 1;  // the first line that differs
  }
  EXPECT_EQ(actual.size(), expected.size()) << path;
}

// Any byte of the payload changed to 0x01, 0x80 or 0xFF and resealed: refused, or a message whose
// record is exactly the changed bytes (no padding, unused slot or out-of-range code slips through).
TYPED_TEST(RecordSchemaTest, AResealedChangeIsRefusedOrIsAValue) {
  const std::vector<std::uint8_t> bytes = record_of(test::record_fixture<TypeParam>());
  int refused = 0, values = 0;
  for (std::size_t offset = kHeaderBytes; offset < bytes.size() - kChecksumBytes; ++offset) {
    for (const std::uint8_t value : {std::uint8_t{0x01}, std::uint8_t{0x80}, std::uint8_t{0xFF}}) {
      if (bytes[offset] == value) continue;
      const std::vector<std::uint8_t> changed = resealed(bytes, offset, value);
      TypeParam out{};
      RecordHeader h;
      if (decode(std::span<const std::uint8_t>(changed), out, h) != RecordStatus::kAccepted) {
        ++refused;
        continue;
      }
      ++values;
      EXPECT_EQ(record_of(out), changed) << "offset " << offset << " = " << int{value};
    }
  }
  EXPECT_GT(values, 0);
}

// Every padding byte set to 1: kBadPadding; every flag set to 2: kBadEnumeration (the fixture's
// slots in use; the unused ones are AResealedChange's).
TYPED_TEST(RecordSchemaTest, PaddingAndFlagsAreChecked) {
  const std::vector<std::uint8_t> bytes = record_of(test::record_fixture<TypeParam>());
  for (const files::LayoutRow& row : leaves(files::record_layout<TypeParam>())) {
    if (row.offset < kHeaderBytes || row.offset >= bytes.size() - kChecksumBytes) continue;
    if (row.type == "0") {
      for (std::size_t i = row.offset; i < row.offset + row.bytes; ++i) {
        EXPECT_EQ(decode_bytes<TypeParam>(resealed(bytes, i, 1)), RecordStatus::kBadPadding) << row.instance;
      }
    }
    if (row.type == "u8 0/1" || row.type == "u8 enum") {
      EXPECT_EQ(decode_bytes<TypeParam>(resealed(bytes, row.offset, 0xFF)), RecordStatus::kBadEnumeration) << row.instance;
    }
  }
}

// docs/record-layout.md's tables, between its markers, are the field lists' (record_layout_tables).
TEST(RecordSchema, TheDocumentedTablesAreTheSchemas) {
  const fs::path path = fs::path(VISORS_SOURCE_DIR) / "docs/record-layout.md";
  const std::string begin = "<!-- generated: record_layout_tables() -->\n", end = "<!-- end of the generated tables -->";
  std::string doc = read_text(path);
  const std::size_t from = doc.find(begin), to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << path << " lacks " << begin;
  ASSERT_NE(to, std::string::npos) << path << " lacks " << end;
  const std::size_t start = from + begin.size();
  const std::string tables = files::record_layout_tables();
  if (updating()) {
    doc.replace(start, to - start, tables);
    write_text(path, doc);
  }
  doc = read_text(path);
  EXPECT_EQ(doc.substr(start, doc.find(end) - start), tables);
}

}  // namespace
}  // namespace visors::gnc
