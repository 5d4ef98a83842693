#pragma once
// The channel records' layout as rows (offset, size, field, encoding, unit, meaning), built from
// the records' field lists (gnc/record_schema.hpp): the table of docs/record-layout.md and the
// annotations of the golden records (tests/gnc/golden/). Ground side.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "visors/gnc/record_header.hpp"
#include "visors/gnc/record_schema.hpp"

namespace visors::gnc::files {

struct LayoutRow {
  std::size_t offset = 0;  // from the record's first byte [bytes]
  std::size_t bytes = 0;
  std::string field;       // its path, slots by letter: "epoch.channels[k].prn"
  std::string instance;    // the same with the slot's number: "epoch.channels[3].prn"
  std::string type;        // the wire encoding
  std::string unit;
  std::string meaning;
  bool leaf = true;        // a field's bytes (false: a list or a condition over the rows after it)
  bool first_item = true;  // of the first slot of every list it is in (the table shows these)
};

/// Collects the rows of a field list's describe() (gnc/record_fields.hpp's Layout operations).
class LayoutBuilder {
 public:
  explicit LayoutBuilder(std::size_t offset) : offset_(offset) {}
  void field(std::size_t bytes, std::string_view type, std::string_view name, std::string_view unit, std::string_view meaning);
  void padding(std::size_t bytes);
  /// The bound of the count just described: at most n, or another count's value, or n if a flag.
  void limit(int n, std::string_view how, std::string_view other);
  void enter(std::string_view name);
  void leave();
  void begin_condition(std::string_view flag, std::size_t bytes);
  void end_condition();
  void begin_slots(std::string_view name, int n, std::size_t item_bytes, bool all_in_use);
  void begin_item(int k);
  void end_slots();
  [[nodiscard]] std::size_t offset() const { return offset_; }
  [[nodiscard]] std::vector<LayoutRow> rows() && { return std::move(rows_); }

 private:
  struct List {
    std::size_t start = 0, item_bytes = 0;
    int n = 0, k = 0;
  };
  [[nodiscard]] std::string path(std::string_view name, bool numbered) const;
  [[nodiscard]] bool first_item() const;
  void add(std::size_t bytes, std::string name, std::string_view type, std::string_view unit, std::string meaning, bool leaf);

  std::size_t offset_;
  std::vector<std::string> parts_;  // "epoch", "channels[]"
  std::vector<List> lists_;
  std::vector<std::string> conditions_;
  std::vector<LayoutRow> rows_;
};

/// The header's rows (offsets 0 .. kHeaderBytes).
std::vector<LayoutRow> header_layout();

/// Every row of a message's record: the header, the payload's fields (each slot's), the checksum.
template <class Message>
std::vector<LayoutRow> record_layout() {
  std::vector<LayoutRow> rows = header_layout();
  LayoutBuilder builder(kHeaderBytes);
  RecordSchema<Message>::Payload::describe(builder);
  std::vector<LayoutRow> payload = std::move(builder).rows();
  rows.insert(rows.end(), payload.begin(), payload.end());
  rows.push_back({kHeaderBytes + kPayloadBytes<Message>, kChecksumBytes, "crc32c", "crc32c", "u32", "",
                  "CRC-32C (Castagnoli) of the header and payload", true, true});
  return rows;
}

/// The layout tables of docs/record-layout.md (between its "generated" markers): the header's,
/// then one per channel in channel order.
std::string record_layout_tables();

}  // namespace visors::gnc::files
