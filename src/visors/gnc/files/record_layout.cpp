#include "visors/gnc/files/record_layout.hpp"

#include <sstream>
#include <tuple>
#include <utility>

namespace visors::gnc::files {

void LayoutBuilder::add(std::size_t bytes, std::string name, std::string_view type, std::string_view unit, std::string meaning,
                        bool leaf) {
  LayoutRow row;
  row.offset = offset_;
  row.bytes = bytes;
  row.field = path(name, false);
  row.instance = path(name, true);
  row.type = std::string(type);
  row.unit = std::string(unit);
  row.meaning = std::move(meaning);
  row.leaf = leaf;
  row.first_item = first_item();
  rows_.push_back(std::move(row));
}

void LayoutBuilder::field(std::size_t bytes, std::string_view type, std::string_view name, std::string_view unit,
                          std::string_view meaning) {
  add(bytes, std::string(name), type, unit, std::string(meaning), true);
  offset_ += bytes;
}

void LayoutBuilder::padding(std::size_t bytes) {
  add(bytes, "(padding)", "0", "", "", true);
  offset_ += bytes;
}

void LayoutBuilder::limit(int n, std::string_view how, std::string_view other) {
  std::string& meaning = rows_.back().meaning;
  std::ostringstream text;
  if (how == "at most") text << "0 .. " << other;
  else if (how == "if") text << "0 .. " << n << " if " << other << ", else 0";
  else text << "0 .. " << n;
  meaning += (meaning.empty() ? "" : ", ") + text.str();
}

void LayoutBuilder::enter(std::string_view name) { parts_.emplace_back(name); }

void LayoutBuilder::leave() { parts_.pop_back(); }

void LayoutBuilder::begin_condition(std::string_view flag, std::size_t bytes) {
  add(bytes, "", "", "", "present if " + std::string(flag) + ", else all 0", false);
  rows_.back().field = rows_.back().instance = "(if " + std::string(flag) + ")";
  conditions_.emplace_back(flag);
}

void LayoutBuilder::end_condition() { conditions_.pop_back(); }

void LayoutBuilder::begin_slots(std::string_view name, int n, std::size_t item_bytes, bool all_in_use) {
  std::ostringstream type;
  type << n << " x " << item_bytes << " bytes";
  add(static_cast<std::size_t>(n) * item_bytes, std::string(name), type.str(), "",
      all_in_use ? "" : "slots after the count all 0", false);
  lists_.push_back({offset_, item_bytes, n, 0});
  parts_.emplace_back(std::string(name) + "[]");
}

void LayoutBuilder::begin_item(int k) {
  lists_.back().k = k;
  offset_ = lists_.back().start + static_cast<std::size_t>(k) * lists_.back().item_bytes;
}

void LayoutBuilder::end_slots() {
  offset_ = lists_.back().start + static_cast<std::size_t>(lists_.back().n) * lists_.back().item_bytes;
  lists_.pop_back();
  parts_.pop_back();
}

bool LayoutBuilder::first_item() const {
  for (const List& list : lists_) {
    if (list.k != 0) return false;
  }
  return true;
}

// The parts joined by '.', each list's "[]" as its letter (k, j, ... by depth) or its slot number.
std::string LayoutBuilder::path(std::string_view name, bool numbered) const {
  static constexpr std::string_view kLetters = "kjil";
  std::string out;
  std::size_t depth = 0;
  for (const std::string& part : parts_) {
    if (!out.empty()) out += '.';
    if (part.ends_with("[]")) {
      out += part.substr(0, part.size() - 2);
      out += '[';
      out += numbered ? std::to_string(lists_[depth].k) : std::string(1, kLetters[depth % kLetters.size()]);
      out += ']';
      ++depth;
    } else {
      out += part;
    }
  }
  if (!name.empty()) {
    if (!out.empty()) out += '.';
    out += name;
  }
  return out;
}

std::vector<LayoutRow> header_layout() {
  LayoutBuilder b(0);
  b.field(2, "2 u8", "magic", "", "'V' 'G'");
  b.field(1, "u8", "channel", "", "the channel's number (below)");
  b.field(1, "u8", "version", "", "the format's version, " + std::to_string(kRecordVersion));
  b.field(2, "u16", "size", "bytes", "the whole record's size");
  b.field(2, "u16", "reserved", "", "0");
  b.field(8, "i64 GPS ns", "t", "ns", "the message's own time");
  b.field(4, "u32", "sequence", "", "per channel and sender, +1 per record, wraps");
  return std::move(b).rows();
}

namespace {

void write_table(std::ostream& out, const std::vector<LayoutRow>& rows) {
  out << "| offset | bytes | field | encoding | unit | meaning |\n|---:|---:|---|---|---|---|\n";
  for (const LayoutRow& row : rows) {
    if (!row.first_item) continue;
    out << "| " << row.offset << " | " << row.bytes << " | `" << row.field << "` | " << row.type << " | " << row.unit << " | "
        << row.meaning << " |\n";
  }
}

template <class Message>
void write_channel(std::ostream& out) {
  using Schema = RecordSchema<Message>;
  std::vector<LayoutRow> rows = record_layout<Message>();
  rows.erase(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(header_layout().size()));  // the header's table is above
  out << "\n### " << static_cast<int>(Schema::kChannel) << " " << Schema::kTitle << ": " << kHeaderBytes + kPayloadBytes<Message> + kChecksumBytes
      << " bytes\n\n";
  write_table(out, rows);
}

// The index of each telemetry counter rejected.by_reason[k] and rejected.by_channel[k].
void write_rejection_reasons(std::ostringstream& out) {
  out << "### Telemetry's rejection counters\n\n";
  out << "| k | `rejected.by_reason[k]` |\n|---:|---|\n";
  for (int k = 1; k < kRejectionReasons; ++k) out << "| " << k << " | " << to_string(static_cast<RejectionReason>(k)) << " |\n";
  out << "\n| k | `rejected.by_channel[k]` |\n|---:|---|\n| 0 | unknown |\n";
  for (int k = 1; k <= kChannels; ++k) out << "| " << k << " | " << to_string(static_cast<Channel>(k)) << " |\n";
  out << "\n";
}

}  // namespace

std::string record_layout_tables() {
  std::ostringstream out;
  out << "### Header: " << kHeaderBytes << " bytes\n\n";
  write_table(out, header_layout());
  std::apply([&out](auto... messages) { (write_channel<decltype(messages)>(out), ...); }, RecordMessages{});
  write_rejection_reasons(out);
  return out.str();
}

}  // namespace visors::gnc::files
