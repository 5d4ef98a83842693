#pragma once
// The vocabulary a record's payload is described in (gnc/record_schema.hpp). A field type knows
// its size on the wire (kBytes, at compile time), how to write itself, how to read itself back
// with the structural checks (an enumeration within its range, a padding or unused byte 0), and
// how to describe itself for the layout table (docs/record-layout.md, gnc/files/record_layout).
// Payloads are therefore written once, as a list of these types, and the encoder, the decoder,
// the sizes and the table all come from that list.
//
// Every number little-endian; doubles as their IEEE 754 bits; times as GPS nanoseconds (i64).
// A field reaches its value through an accessor, a member path (At<&Message::part, &Part::x>)
// from the object its list describes. Counts and presence flags are read from the root message
// (RootAt): a list of repeated items is often described away from the count that bounds it.
//
// Each field's operations:
//   write(Writer&, const Root&, const T&)            the bytes of the field of object T
//   read(Reader&, Root&, T&) -> RecordStatus         the field into T; kAccepted or why not
//   describe(Layout&)                                its rows in the layout table (ground code)
// The root is written before it is read: a count or flag read earlier bounds the fields after it.
// No allocation, no exception: flight code (describe is instantiated by ground code only).

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/gnc/record_header.hpp"

namespace visors::gnc::record {

/// A string literal as a template argument (a field's name, unit, meaning).
template <std::size_t N>
struct Text {
  char chars[N]{};
  constexpr Text(const char (&text)[N]) { std::copy_n(text, N, chars); }  // NOLINT: implicit by design
  [[nodiscard]] constexpr std::string_view view() const { return {chars, N - 1}; }
};

/// Little-endian writes into a buffer the caller sized for the whole record.
class Writer {
 public:
  explicit Writer(std::span<std::uint8_t> out) : out_(out) {}
  void u8(std::uint8_t v) { out_[pos_++] = v; }
  void u16(std::uint16_t v) { unsigned_le(v, 2); }
  void u32(std::uint32_t v) { unsigned_le(v, 4); }
  void i32(std::int32_t v) { unsigned_le(static_cast<std::uint32_t>(v), 4); }
  void i64(std::int64_t v) { unsigned_le(static_cast<std::uint64_t>(v), 8); }
  void f64(double v) { unsigned_le(std::bit_cast<std::uint64_t>(v), 8); }
  void time(core::GpsTime t) { i64(t.nanoseconds()); }
  void zeros(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) u8(0);
  }
  [[nodiscard]] std::size_t position() const { return pos_; }

 private:
  void unsigned_le(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::span<std::uint8_t> out_;
  std::size_t pos_ = 0;
};

/// Little-endian reads from a record whose size was checked against its channel's.
class Reader {
 public:
  Reader(std::span<const std::uint8_t> in, std::size_t position) : in_(in), pos_(position) {}
  std::uint8_t u8() { return in_[pos_++]; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsigned_le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_le(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(unsigned_le(4))); }
  std::int64_t i64() { return static_cast<std::int64_t>(unsigned_le(8)); }
  double f64() { return std::bit_cast<double>(unsigned_le(8)); }
  core::GpsTime time() { return core::GpsTime::from_nanoseconds(i64()); }
  /// The next n bytes are all 0 (-0.0 is not: a record decodes to one message only).
  bool zeros(std::size_t n) {
    bool all = true;
    for (std::size_t i = 0; i < n; ++i) all = all && u8() == 0;
    return all;
  }
  [[nodiscard]] std::size_t position() const { return pos_; }

 private:
  std::uint64_t unsigned_le(int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(in_[pos_++]) << (8 * i);
    return v;
  }
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
};

// ---- Accessors.

/// A member path from an object: At<>::get(x) is x, At<&A::b, &B::c>::get(a) is a.b.c.
template <auto... Members>
struct At;
template <>
struct At<> {
  template <class T>
  static constexpr T& get(T& x) { return x; }
};
template <auto First, auto... Rest>
struct At<First, Rest...> {
  template <class T>
  static constexpr decltype(auto) get(T& x) { return At<Rest...>::get(x.*First); }
};

// ---- Wire encodings of one value.

struct WireF64 {
  static constexpr std::size_t kBytes = 8;
  static constexpr std::string_view kType = "f64";
  static void put(Writer& w, double v) { w.f64(v); }
  static RecordStatus take(Reader& r, double& v) {
    v = r.f64();
    return RecordStatus::kAccepted;
  }
};

struct WireI32 {
  static constexpr std::size_t kBytes = 4;
  static constexpr std::string_view kType = "i32";
  static void put(Writer& w, std::int32_t v) { w.i32(v); }
  template <class Int>
  static RecordStatus take(Reader& r, Int& v) {
    v = r.i32();
    return RecordStatus::kAccepted;
  }
};

struct WireI64 {
  static constexpr std::size_t kBytes = 8;
  static constexpr std::string_view kType = "i64";
  static void put(Writer& w, std::int64_t v) { w.i64(v); }
  static RecordStatus take(Reader& r, std::int64_t& v) {
    v = r.i64();
    return RecordStatus::kAccepted;
  }
};

struct WireTime {
  static constexpr std::size_t kBytes = 8;
  static constexpr std::string_view kType = "i64 GPS ns";
  static void put(Writer& w, core::GpsTime t) { w.time(t); }
  static RecordStatus take(Reader& r, core::GpsTime& t) {
    t = r.time();
    return RecordStatus::kAccepted;
  }
};

/// A boolean as one byte, 0 or 1 (anything else: kBadEnumeration).
struct WireFlag {
  static constexpr std::size_t kBytes = 1;
  static constexpr std::string_view kType = "u8 0/1";
  static void put(Writer& w, bool v) { w.u8(v ? 1 : 0); }
  static RecordStatus take(Reader& r, bool& v) {
    const std::uint8_t byte = r.u8();
    if (byte > 1) return RecordStatus::kBadEnumeration;
    v = byte == 1;
    return RecordStatus::kAccepted;
  }
};

/// A small non-negative integer (a PRN) as one byte, its low 8 bits.
struct WireU8 {
  static constexpr std::size_t kBytes = 1;
  static constexpr std::string_view kType = "u8";
  static void put(Writer& w, int v) { w.u8(static_cast<std::uint8_t>(v)); }
  static RecordStatus take(Reader& r, int& v) {
    v = r.u8();
    return RecordStatus::kAccepted;
  }
};

/// An enumeration of `Count` values 0 .. Count-1 as one byte (beyond: kBadEnumeration).
template <class Enum, int Count>
struct WireEnum {
  static constexpr std::size_t kBytes = 1;
  static constexpr std::string_view kType = "u8 enum";
  static void put(Writer& w, Enum v) { w.u8(static_cast<std::uint8_t>(v)); }
  static RecordStatus take(Reader& r, Enum& v) {
    const std::uint8_t byte = r.u8();
    if (byte >= Count) return RecordStatus::kBadEnumeration;
    v = static_cast<Enum>(byte);
    return RecordStatus::kAccepted;
  }
};

// ---- Fields.

/// One value of `Wire`'s encoding at Acc, with its unit and meaning.
template <class Wire, Text Name, class Acc, Text Unit, Text Doc>
struct Scalar {
  static constexpr std::size_t kBytes = Wire::kBytes;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) { Wire::put(w, Acc::get(x)); }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) { return Wire::take(r, Acc::get(x)); }
  template <class Layout>
  static void describe(Layout& out) { out.field(kBytes, Wire::kType, Name.view(), Unit.view(), Doc.view()); }
};

template <Text Name, class Acc, Text Unit, Text Doc>
using F64 = Scalar<WireF64, Name, Acc, Unit, Doc>;
template <Text Name, class Acc, Text Doc>
using I32 = Scalar<WireI32, Name, Acc, "", Doc>;
template <Text Name, class Acc, Text Doc>
using I64 = Scalar<WireI64, Name, Acc, "", Doc>;
template <Text Name, class Acc, Text Doc>
using Time = Scalar<WireTime, Name, Acc, "ns", Doc>;
template <Text Name, class Acc, Text Doc>
using Flag = Scalar<WireFlag, Name, Acc, "", Doc>;
template <Text Name, class Acc, Text Doc>
using U8 = Scalar<WireU8, Name, Acc, "", Doc>;
template <Text Name, class Acc, class Enum, int Count, Text Doc>
using Enumerated = Scalar<WireEnum<Enum, Count>, Name, Acc, "", Doc>;

/// N doubles of a vector (Eigen or std::array) at Acc, element by element.
template <int N, Text Name, class Acc, Text Unit, Text Doc>
struct Vector {
  static_assert(N == 3 || N == 6, "the table names 3- and 6-vectors");
  static constexpr std::size_t kBytes = 8 * N;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) {
    const auto& v = Acc::get(x);
    for (int i = 0; i < N; ++i) w.f64(v[i]);
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) {
    auto& v = Acc::get(x);
    for (int i = 0; i < N; ++i) v[i] = r.f64();
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) {
    out.field(kBytes, N == 3 ? "3 f64" : "6 f64", Name.view(), Unit.view(), Doc.view());
  }
};
template <Text Name, class Acc, Text Unit, Text Doc>
using Vector3 = Vector<3, Name, Acc, Unit, Doc>;
template <Text Name, class Acc, Text Unit, Text Doc>
using Vector6 = Vector<6, Name, Acc, Unit, Doc>;

/// A quaternion (Eigen::Quaterniond) as w, x, y, z.
template <Text Name, class Acc, Text Doc>
struct Quaternion {
  static constexpr std::size_t kBytes = 32;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) {
    const Eigen::Quaterniond& q = Acc::get(x);
    for (double v : {q.w(), q.x(), q.y(), q.z()}) w.f64(v);
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) {
    const double qw = r.f64(), qx = r.f64(), qy = r.f64(), qz = r.f64();
    Acc::get(x) = Eigen::Quaterniond(qw, qx, qy, qz);
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) { out.field(kBytes, "4 f64 w x y z", Name.view(), "", Doc.view()); }
};

/// A position and velocity (core::StateVector) as r then v.
template <Text Name, class Acc, Text Doc>
struct State {
  static constexpr std::size_t kBytes = 48;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) {
    const core::StateVector& s = Acc::get(x);
    for (int i = 0; i < 3; ++i) w.f64(s.r(i));
    for (int i = 0; i < 3; ++i) w.f64(s.v(i));
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) {
    core::StateVector& s = Acc::get(x);
    for (int i = 0; i < 3; ++i) s.r(i) = r.f64();
    for (int i = 0; i < 3; ++i) s.v(i) = r.f64();
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) { out.field(kBytes, "6 f64 r v", Name.view(), "m, m/s", Doc.view()); }
};

/// A symmetric N x N matrix as its upper triangle row by row; read back into both triangles.
template <int N, Text Name, class Acc, Text Unit, Text Doc>
struct SymmetricUpper {
  static_assert(N == 6, "the table names a 6 x 6 matrix's 21 values");
  static constexpr std::size_t kBytes = 8 * N * (N + 1) / 2;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) {
    const auto& m = Acc::get(x);
    for (int i = 0; i < N; ++i) {
      for (int j = i; j < N; ++j) w.f64(m(i, j));
    }
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) {
    auto& m = Acc::get(x);
    for (int i = 0; i < N; ++i) {
      for (int j = i; j < N; ++j) m(i, j) = m(j, i) = r.f64();
    }
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) {
    out.field(kBytes, "21 f64 upper triangle, row by row", Name.view(), Unit.view(), Doc.view());
  }
};

/// Two booleans as bits 0 and 1 of one byte (higher bits set: kBadEnumeration).
template <Text Name, class Bit0, class Bit1, Text Doc>
struct TwoBits {
  static constexpr std::size_t kBytes = 1;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T& x) {
    w.u8(static_cast<std::uint8_t>((Bit0::get(x) ? 1 : 0) | (Bit1::get(x) ? 2 : 0)));
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T& x) {
    const std::uint8_t byte = r.u8();
    if (byte > 3) return RecordStatus::kBadEnumeration;
    Bit0::get(x) = (byte & 1) != 0;
    Bit1::get(x) = (byte & 2) != 0;
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) { out.field(kBytes, "u8 bits", Name.view(), "", Doc.view()); }
};

/// N reserved bytes, 0 (anything else: kBadPadding).
template <std::size_t N>
struct Padding {
  static constexpr std::size_t kBytes = N;
  template <class Root, class T>
  static void write(Writer& w, const Root&, const T&) { w.zeros(N); }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root&, T&) { return r.zeros(N) ? RecordStatus::kAccepted : RecordStatus::kBadPadding; }
  template <class Layout>
  static void describe(Layout& out) { out.padding(N); }
};

// ---- Counts: how many items of a list are in use.

/// At most N.
template <int N>
struct AtMost {
  template <class Root>
  static constexpr int value(const Root&) { return N; }
  template <class Layout>
  static void describe(Layout& out) { out.limit(N, "", ""); }
};

/// At most N when the root's flag at FlagAt is set, else 0.
template <int N, Text FlagName, class FlagAt>
struct AtMostIf {
  template <class Root>
  static constexpr int value(const Root& root) { return FlagAt::get(root) ? N : 0; }
  template <class Layout>
  static void describe(Layout& out) { out.limit(N, "if", FlagName.view()); }
};

/// At most the value of another count (a Count field).
template <class Bound>
struct AtMostCountOf {
  template <class Root>
  static constexpr int value(const Root& root) { return Bound::value(root); }
  template <class Layout>
  static void describe(Layout& out) { out.limit(-1, "at most", Bound::kName.view()); }
};

/// A count as one byte, bounded by Limit: written clamped to 0 .. limit, refused beyond it
/// (kBadEnumeration) when read. Its value is reached from the root message (CountAt), so that the
/// list it counts can sit elsewhere in the record (value() is what both sides use).
template <Text Name, class CountAt, class Limit, Text Doc>
struct Count {
  static constexpr std::size_t kBytes = 1;
  static constexpr Text kName = Name;
  template <class Root>
  static int value(const Root& root) {
    return std::clamp(static_cast<int>(CountAt::get(root)), 0, Limit::value(root));
  }
  template <class Root, class T>
  static void write(Writer& w, const Root& root, const T&) { w.u8(static_cast<std::uint8_t>(value(root))); }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root& root, T&) {
    const int count = r.u8();
    if (count > Limit::value(root)) return RecordStatus::kBadEnumeration;
    CountAt::get(root) = count;
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) {
    out.field(kBytes, "u8 count", Name.view(), "", Doc.view());
    Limit::describe(out);
  }
};

/// Every item of a list (a fixed-size array in use as a whole).
template <int N>
struct All {
  template <class Root>
  static constexpr int value(const Root&) { return N; }
};

// ---- Structure.

/// Fields one after the other.
template <class... Fields>
struct Sequence {
  static constexpr std::size_t kBytes = (Fields::kBytes + ... + 0);
  template <class Root, class T>
  static void write(Writer& w, const Root& root, const T& x) {
    (Fields::write(w, root, x), ...);
  }
  /// Field by field until the first refusal.
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root& root, T& x) {
    RecordStatus status = RecordStatus::kAccepted;
    (void)(((status = Fields::read(r, root, x)) == RecordStatus::kAccepted) && ...);
    return status;
  }
  template <class Layout>
  static void describe(Layout& out) { (Fields::template describe<Layout>(out), ...); }
};

/// The fields of a part of the object (at Acc), named Name in the table.
template <Text Name, class Acc, class... Fields>
struct Part {
  static constexpr std::size_t kBytes = Sequence<Fields...>::kBytes;
  template <class Root, class T>
  static void write(Writer& w, const Root& root, const T& x) { Sequence<Fields...>::write(w, root, Acc::get(x)); }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root& root, T& x) { return Sequence<Fields...>::read(r, root, Acc::get(x)); }
  template <class Layout>
  static void describe(Layout& out) {
    out.enter(Name.view());
    Sequence<Fields...>::describe(out);
    out.leave();
  }
};

/// Fields present when the root's flag at FlagAt is set; otherwise as many bytes, all 0 (read:
/// anything else is kBadPadding, and the fields keep their defaults).
template <Text FlagName, class FlagAt, class... Fields>
struct IfFlag {
  static constexpr std::size_t kBytes = Sequence<Fields...>::kBytes;
  template <class Root, class T>
  static void write(Writer& w, const Root& root, const T& x) {
    if (FlagAt::get(root)) Sequence<Fields...>::write(w, root, x);
    else w.zeros(kBytes);
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root& root, T& x) {
    if (FlagAt::get(root)) return Sequence<Fields...>::read(r, root, x);
    return r.zeros(kBytes) ? RecordStatus::kAccepted : RecordStatus::kBadPadding;
  }
  template <class Layout>
  static void describe(Layout& out) {
    out.begin_condition(FlagName.view(), kBytes);
    Sequence<Fields...>::describe(out);
    out.end_condition();
  }
};

/// N items of an array at Acc, each of Fields; the first InUse::value(root) hold their item, the
/// others all 0 bytes (read: anything else is kBadPadding).
template <Text Name, int N, class Acc, class InUse, class... Fields>
struct Slots {
  static constexpr std::size_t kItemBytes = Sequence<Fields...>::kBytes;
  static constexpr std::size_t kBytes = N * kItemBytes;
  template <class Root, class T>
  static void write(Writer& w, const Root& root, const T& x) {
    const auto& items = Acc::get(x);
    static_assert(std::tuple_size_v<std::remove_cvref_t<decltype(items)>> >= N, "the array holds the slots");
    const int used = std::min(N, InUse::value(root));
    for (int k = 0; k < N; ++k) {
      if (k < used) Sequence<Fields...>::write(w, root, items[static_cast<std::size_t>(k)]);
      else w.zeros(kItemBytes);
    }
  }
  template <class Root, class T>
  static RecordStatus read(Reader& r, Root& root, T& x) {
    auto& items = Acc::get(x);
    const int used = std::min(N, InUse::value(root));
    for (int k = 0; k < N; ++k) {
      const RecordStatus status = k < used ? Sequence<Fields...>::read(r, root, items[static_cast<std::size_t>(k)])
                                           : (r.zeros(kItemBytes) ? RecordStatus::kAccepted : RecordStatus::kBadPadding);
      if (status != RecordStatus::kAccepted) return status;
    }
    return RecordStatus::kAccepted;
  }
  template <class Layout>
  static void describe(Layout& out) {
    out.begin_slots(Name.view(), N, kItemBytes, std::is_same_v<InUse, All<N>>);
    for (int k = 0; k < N; ++k) {
      out.begin_item(k);
      Sequence<Fields...>::describe(out);
    }
    out.end_slots();
  }
};

}  // namespace visors::gnc::record
