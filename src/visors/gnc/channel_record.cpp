#include "visors/gnc/channel_record.hpp"

#include <algorithm>
#include <bit>
#include <cassert>

#include "visors/gnc/crc32c.hpp"

namespace visors::gnc {
namespace {

constexpr int kModes = 6;          // gnc_mode.hpp, kManual .. kEscape
constexpr int kCommandKinds = 7;   // messages.hpp, kToManual .. kMakePassive
static_assert(static_cast<int>(Mode::kEscape) == kModes - 1, "a new mode needs its code here");
static_assert(static_cast<int>(GroundCommand::Kind::kMakePassive) == kCommandKinds - 1, "a new command needs its code here");

// Little-endian writes into a buffer the caller sized (write_record checks it once).
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
  void vector3(const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) f64(v(i));
  }
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

// Little-endian reads from a record whose size was checked (read_frame).
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> in, std::size_t position) : in_(in), pos_(position) {}
  std::uint8_t u8() { return in_[pos_++]; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsigned_le(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_le(4)); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(unsigned_le(4))); }
  std::int64_t i64() { return static_cast<std::int64_t>(unsigned_le(8)); }
  double f64() { return std::bit_cast<double>(unsigned_le(8)); }
  core::GpsTime time() { return core::GpsTime::from_nanoseconds(i64()); }
  Eigen::Vector3d vector3() {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v(i) = f64();
    return v;
  }
  /// The next n bytes are all 0.
  bool zeros(std::size_t n) {
    bool all = true;
    for (std::size_t i = 0; i < n; ++i) all = all && u8() == 0;
    return all;
  }

 private:
  std::uint64_t unsigned_le(int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(in_[pos_++]) << (8 * i);
    return v;
  }
  std::span<const std::uint8_t> in_;
  std::size_t pos_ = 0;
};

// Header, payload (written by `payload`), checksum; 0 when `out` is too small.
template <class Payload>
std::size_t write_record(Channel channel, core::GpsTime t, std::uint32_t sequence, std::span<std::uint8_t> out,
                         Payload&& payload) {
  const std::size_t size = record_size(channel);
  if (out.size() < size) return 0;
  Writer w(out);
  w.u8(kRecordMagic[0]);
  w.u8(kRecordMagic[1]);
  w.u8(static_cast<std::uint8_t>(channel));
  w.u8(kRecordVersion);
  w.u16(static_cast<std::uint16_t>(size));
  w.u16(0);
  w.time(t);
  w.u32(sequence);
  payload(w);
  assert(w.position() == size - kChecksumBytes);  // the payload writer matches record_size()
  const std::uint32_t crc = crc32c(out.first(size - kChecksumBytes));
  w.u32(crc);
  return w.position();
}

// The structural checks of the file comment, up to the payload.
RecordStatus read_frame(std::span<const std::uint8_t> in, Channel expected, RecordHeader& header) {
  if (in.size() < kHeaderBytes) return RecordStatus::kTruncated;
  Reader r(in, 0);
  if (r.u8() != kRecordMagic[0] || r.u8() != kRecordMagic[1]) return RecordStatus::kBadMagic;
  const std::uint8_t channel = r.u8();
  const std::uint8_t version = r.u8();
  const std::uint16_t size = r.u16();
  if (size < kHeaderBytes + kChecksumBytes || size > kMaxRecordBytes) return RecordStatus::kBadSize;
  if (in.size() < size) return RecordStatus::kTruncated;
  if (crc32c(in.first(size - kChecksumBytes)) != Reader(in, size - kChecksumBytes).u32()) return RecordStatus::kBadChecksum;
  if (channel < 1 || channel > kChannels) return RecordStatus::kUnknownChannel;
  if (channel != static_cast<std::uint8_t>(expected)) return RecordStatus::kWrongChannel;
  if (version != kRecordVersion) return RecordStatus::kBadVersion;
  if (size != record_size(expected)) return RecordStatus::kBadSize;
  if (r.u16() != 0) return RecordStatus::kBadPadding;  // reserved
  header.channel = expected;
  header.version = version;
  header.size = size;
  header.t = r.time();
  header.sequence = r.u32();
  return RecordStatus::kAccepted;
}

bool flag(std::uint8_t byte, bool& out) {
  if (byte > 1) return false;
  out = byte == 1;
  return true;
}

constexpr int kSlots = gnss::kMaxGpsChannels;  // observations per epoch in a record
constexpr std::size_t kGpsChannelBytes = 48, kEphemerisBytes = 208, kCrosslinkObservationBytes = 24, kImpulseBytes = 32;

std::uint8_t lock_flags(bool loss_of_lock, bool half_cycle) {
  return static_cast<std::uint8_t>((loss_of_lock ? 1 : 0) | (half_cycle ? 2 : 0));
}

bool read_lock_flags(std::uint8_t byte, bool& loss_of_lock, bool& half_cycle) {
  if (byte > 3) return false;
  loss_of_lock = (byte & 1) != 0;
  half_cycle = (byte & 2) != 0;
  return true;
}

void write_navigation(Writer& w, const CrosslinkNavigation& n) {
  const int count = n.has_epoch ? std::clamp(n.epoch.count, 0, kSlots) : 0;
  const int impulses = std::clamp(n.impulse_count, 0, kCrosslinkImpulses);
  w.u8(n.has_epoch ? 1 : 0);
  w.u8(static_cast<std::uint8_t>(impulses));
  w.u8(n.has_range ? 1 : 0);
  w.u8(static_cast<std::uint8_t>(count));
  w.zeros(4);
  w.time(n.has_epoch ? n.epoch.t : core::GpsTime{});
  for (int k = 0; k < kSlots; ++k) {
    if (k >= count) {
      w.zeros(kCrosslinkObservationBytes);
      continue;
    }
    const nav::GpsObservation& o = n.epoch.observations[static_cast<std::size_t>(k)];
    w.u8(static_cast<std::uint8_t>(o.prn));
    w.u8(lock_flags(o.loss_of_lock, o.half_cycle));
    w.zeros(6);
    w.f64(o.code_m);
    w.f64(o.phase_cycles);
  }
  const Eigen::Quaterniond q = n.has_epoch ? n.q_body_to_gcrf : Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
  w.f64(q.w());
  w.f64(q.x());
  w.f64(q.y());
  w.f64(q.z());
  for (int k = 0; k < kCrosslinkImpulses; ++k) {
    if (k >= impulses) {
      w.zeros(kImpulseBytes);
      continue;
    }
    w.time(n.impulses[static_cast<std::size_t>(k)].t);
    w.vector3(n.impulses[static_cast<std::size_t>(k)].dv_gcrf_mps);
  }
  w.time(n.has_range ? n.range.t : core::GpsTime{});
  w.f64(n.has_range ? n.range.range_m : 0.0);
}

// The navigation part; anything not in use must be all 0 bytes (a record decodes to one message
// only: -0.0 is not 0 here, as the fuzzer found).
RecordStatus read_navigation(Reader& r, CrosslinkNavigation& n) {
  const std::uint8_t has_epoch = r.u8(), impulses = r.u8(), has_range = r.u8(), count = r.u8();
  if (!flag(has_epoch, n.has_epoch) || !flag(has_range, n.has_range)) return RecordStatus::kBadEnumeration;
  if (impulses > kCrosslinkImpulses || count > kSlots || (!n.has_epoch && count > 0)) return RecordStatus::kBadEnumeration;
  if (!r.zeros(4)) return RecordStatus::kBadPadding;
  n.epoch.count = count;
  n.q_body_to_gcrf = Eigen::Quaterniond::Identity();
  if (n.has_epoch) {
    n.epoch.t = r.time();
    for (int k = 0; k < kSlots; ++k) {
      if (k >= count) {
        if (!r.zeros(kCrosslinkObservationBytes)) return RecordStatus::kBadPadding;
        continue;
      }
      nav::GpsObservation& o = n.epoch.observations[static_cast<std::size_t>(k)];
      o.prn = r.u8();
      if (!read_lock_flags(r.u8(), o.loss_of_lock, o.half_cycle)) return RecordStatus::kBadEnumeration;
      if (!r.zeros(6)) return RecordStatus::kBadPadding;
      o.code_m = r.f64();
      o.phase_cycles = r.f64();
    }
    const double w = r.f64(), x = r.f64(), y = r.f64(), z = r.f64();
    n.q_body_to_gcrf = Eigen::Quaterniond(w, x, y, z);
  } else if (!r.zeros(8 + kSlots * kCrosslinkObservationBytes + 32)) {  // time tag, observations, attitude
    return RecordStatus::kBadPadding;
  }
  n.impulse_count = impulses;
  for (int k = 0; k < kCrosslinkImpulses; ++k) {
    if (k >= impulses) {
      if (!r.zeros(kImpulseBytes)) return RecordStatus::kBadPadding;
      continue;
    }
    n.impulses[static_cast<std::size_t>(k)].t = r.time();
    n.impulses[static_cast<std::size_t>(k)].dv_gcrf_mps = r.vector3();
  }
  if (!n.has_range) return r.zeros(16) ? RecordStatus::kAccepted : RecordStatus::kBadPadding;
  n.range.t = r.time();
  n.range.range_m = r.f64();
  return RecordStatus::kAccepted;
}

void write_ephemeris(Writer& w, const gnss::BroadcastEphemeris& e) {
  w.i32(e.prn);
  w.i32(e.iode);
  w.i32(e.iodc);
  w.i32(e.health);
  w.time(e.toc);
  w.time(e.toe);
  w.time(e.transmission);
  for (double v : {e.af0_s, e.af1_sps, e.af2_sps2, e.sqrt_a, e.eccentricity, e.i0_rad, e.omega0_rad, e.omega_rad, e.m0_rad,
                   e.delta_n_radps, e.idot_radps, e.omega_dot_radps, e.cuc_rad, e.cus_rad, e.crc_m, e.crs_m, e.cic_rad,
                   e.cis_rad, e.tgd_s, e.ura_m, e.fit_interval_h}) {
    w.f64(v);
  }
}

gnss::BroadcastEphemeris read_ephemeris(Reader& r) {
  gnss::BroadcastEphemeris e;
  e.prn = r.i32();
  e.iode = r.i32();
  e.iodc = r.i32();
  e.health = r.i32();
  e.toc = r.time();
  e.toe = r.time();
  e.transmission = r.time();
  for (double* v : {&e.af0_s, &e.af1_sps, &e.af2_sps2, &e.sqrt_a, &e.eccentricity, &e.i0_rad, &e.omega0_rad, &e.omega_rad,
                    &e.m0_rad, &e.delta_n_radps, &e.idot_radps, &e.omega_dot_radps, &e.cuc_rad, &e.cus_rad, &e.crc_m, &e.crs_m,
                    &e.cic_rad, &e.cis_rad, &e.tgd_s, &e.ura_m, &e.fit_interval_h}) {
    *v = r.f64();
  }
  return e;
}

}  // namespace

std::string_view to_string(RecordStatus status) {
  switch (status) {
    case RecordStatus::kAccepted: return "accepted";
    case RecordStatus::kTruncated: return "truncated";
    case RecordStatus::kBadMagic: return "bad_magic";
    case RecordStatus::kUnknownChannel: return "unknown_channel";
    case RecordStatus::kWrongChannel: return "wrong_channel";
    case RecordStatus::kBadVersion: return "bad_version";
    case RecordStatus::kBadSize: return "bad_size";
    case RecordStatus::kBadChecksum: return "bad_checksum";
    case RecordStatus::kBadEnumeration: return "bad_enumeration";
    case RecordStatus::kBadPadding: return "bad_padding";
    case RecordStatus::kOutOfOrder: return "out_of_order";
  }
  return "unknown";
}

std::size_t encode(const TimeAtTone& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kTimeAtTone, m.t, sequence, out, [&m](Writer& w) {
    w.f64(m.q_body_to_gcrf.w());
    w.f64(m.q_body_to_gcrf.x());
    w.f64(m.q_body_to_gcrf.y());
    w.f64(m.q_body_to_gcrf.z());
  });
}

std::size_t encode(const NavigationSolution& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kNavigation, m.t, sequence, out, [&m](Writer& w) {
    for (const core::StateVector* x : {&m.chief_gcrf, &m.deputy_gcrf}) {
      w.vector3(x->r);
      w.vector3(x->v);
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = i; j < 6; ++j) w.f64(m.relative_covariance_rtn(i, j));
    }
  });
}

std::size_t encode(const CrosslinkMessage& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kCrosslink, m.t, sequence, out, [&m](Writer& w) {
    w.u8(static_cast<std::uint8_t>(m.sender));
    w.u8(static_cast<std::uint8_t>(m.mode));
    w.u8(m.sender_active ? 1 : 0);
    w.u8(m.has_observation ? 1 : 0);
    w.i32(m.observations_done);
    w.i32(m.observations_planned);
    w.i32(m.observation_index);
    w.time(m.slew_start);
    w.time(m.observation_start);
    w.time(m.observation_end);
    write_navigation(w, m.navigation);
  });
}

std::size_t encode(const GroundCommand& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kGroundCommand, m.t, sequence, out, [&m](Writer& w) {
    w.u8(static_cast<std::uint8_t>(m.kind));
    w.zeros(3);
    w.i32(m.observations);
  });
}

std::size_t encode(const PropulsionTelemetry& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kPropulsion, m.t, sequence, out, [&m](Writer& w) {
    w.vector3(m.dv_body_mps);
    w.f64(m.mass_kg);
    w.u8(m.executed ? 1 : 0);
    w.zeros(7);
  });
}

std::size_t encode(const GpsMessage& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kGps, m.t, sequence, out, [&m](Writer& w) {
    const int count = std::clamp(m.epoch.channel_count, 0, kSlots);
    w.u8(static_cast<std::uint8_t>(count));
    w.u8(m.has_ephemeris ? 1 : 0);
    w.zeros(6);
    for (int k = 0; k < kSlots; ++k) {
      if (k >= count) {
        w.zeros(kGpsChannelBytes);
        continue;
      }
      const gnss::GpsChannelMeasurement& c = m.epoch.channels[static_cast<std::size_t>(k)];
      w.u8(static_cast<std::uint8_t>(c.prn));
      w.u8(lock_flags(c.loss_of_lock, c.half_cycle_ambiguity));
      w.zeros(6);
      for (double v : {c.pseudorange_m, c.carrier_phase_cycles, c.doppler_hz, c.cn0_dbhz, c.lock_time_s}) w.f64(v);
    }
    if (m.has_ephemeris) write_ephemeris(w, m.ephemeris);
    else w.zeros(kEphemerisBytes);
  });
}

std::size_t encode(const LaserRange& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kLaserRange, m.t, sequence, out, [&m](Writer& w) { w.f64(m.range_m); });
}

std::size_t encode(const ManeuverCommand& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kManeuver, m.t, sequence, out, [&m](Writer& w) {
    w.vector3(m.dv_body_mps);
    w.vector3(m.dv_rtn_mps);
  });
}

std::size_t encode(const ObservationCommand& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kObservation, m.t, sequence, out, [&m](Writer& w) {
    w.i32(m.index);
    w.zeros(4);
    w.time(m.slew_start);
    w.time(m.start);
    w.time(m.end);
  });
}

std::size_t encode(const Telemetry& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kTelemetry, m.t, sequence, out, [&m](Writer& w) {
    w.u8(static_cast<std::uint8_t>(m.mode));
    for (bool b : {m.active, m.estimate_valid, m.safety_checked, m.star_tracker_power, m.lrf_power, m.gnc_incapable,
                   m.passive_safety_violated}) {
      w.u8(b ? 1 : 0);
    }
    for (int i = 0; i < 6; ++i) w.f64(m.roe_mean_m(i));
    w.f64(m.safety_margin_m);
    for (int i = 0; i < 6; ++i) w.f64(m.roe_target_m(i));
    w.i32(m.observations_done);
    w.i32(m.pending_pieces);
    w.i64(m.plans);
    w.i64(m.planning_failures);
    const RejectionCounters& r = m.rejected;
    for (std::int64_t v : {r.time_at_tone, r.navigation, r.crosslink, r.command, r.propulsion, r.gps, r.laser_range}) w.i64(v);
    for (std::int64_t v : m.records.by_status) w.i64(v);
    w.u8(m.navigation_valid ? 1 : 0);
    w.u8(m.navigation_fixed ? 1 : 0);
    w.u8(m.drag_valid ? 1 : 0);
    w.zeros(5);
    w.time(m.navigation_update);
    w.f64(m.differential_drag_mps2);
  });
}

namespace {

constexpr std::size_t kDoubleDifferenceBytes = 24;

void write_counters(Writer& w, const NavigationCounters& c) {
  for (std::int64_t v : {c.epochs_joint, c.epochs_alone, c.epochs_refused, c.epochs_fixed, c.wrong_fixes_refused,
                         c.impulses_applied, c.impulses_late, c.laser_used, c.laser_rejected, c.clock_jumps}) {
    w.i64(v);
  }
  for (std::int64_t v : c.ephemerides) w.i64(v);
}

void write_double_differences(Writer& w, const NavigationTelemetry& m, int count) {
  for (int k = 0; k < kTelemetryDoubleDifferences; ++k) {
    if (k >= count) {
      w.zeros(kDoubleDifferenceBytes);
      continue;
    }
    const FixedDoubleDifference& d = m.dd[static_cast<std::size_t>(k)];
    w.u8(static_cast<std::uint8_t>(d.prn));
    w.zeros(7);
    w.i64(d.integer_cycles);
    w.f64(d.fixed_cycles);
  }
}

constexpr std::size_t kCombinationBytes = 4 * kTelemetryDoubleDifferences + 4 + 8;

void write_combinations(Writer& w, const NavigationTelemetry& m, int dd_count, int count) {
  for (int i = 0; i < kTelemetryDoubleDifferences; ++i) {
    if (i >= count) {
      w.zeros(kCombinationBytes);
      continue;
    }
    const FixedCombination& c = m.combinations[static_cast<std::size_t>(i)];
    for (int j = 0; j < kTelemetryDoubleDifferences; ++j) w.i32(j < dd_count ? c.dd_coefficients[static_cast<std::size_t>(j)] : 0);
    w.zeros(4);
    w.i64(c.integer_cycles);
  }
}

}  // namespace

std::size_t encode(const NavigationTelemetry& m, std::uint32_t sequence, std::span<std::uint8_t> out) {
  return write_record(Channel::kNavigationTelemetry, m.t, sequence, out, [&m](Writer& w) {
    const int count = std::clamp(m.dd_count, 0, kTelemetryDoubleDifferences);
    for (bool b : {m.has_solution, m.valid, m.fixed, m.fix_applied, m.full_fix}) w.u8(b ? 1 : 0);
    w.u8(static_cast<std::uint8_t>(count));
    w.u8(static_cast<std::uint8_t>(m.dd_reference_prn));
    const int combinations = std::clamp(m.combination_count, 0, count);
    w.u8(static_cast<std::uint8_t>(combinations));
    w.time(m.update_t);
    for (const core::StateVector* x : {&m.dsc_gcrf, &m.osc_gcrf}) {
      w.vector3(x->r);
      w.vector3(x->v);
    }
    for (const Eigen::Vector3d* v : {&m.p_dsc_body_m, &m.p_osc_body_m, &m.empirical_dsc_rtn_mps2, &m.empirical_osc_rtn_mps2,
                                     &m.relative_sigma_rtn_m}) {
      w.vector3(*v);
    }
    write_double_differences(w, m, count);
    write_combinations(w, m, count, combinations);
    write_counters(w, m.counters);
  });
}

std::optional<Channel> channel_of(std::span<const std::uint8_t> in) {
  if (in.size() < kHeaderBytes || in[2] < 1 || in[2] > kChannels) return std::nullopt;
  return static_cast<Channel>(in[2]);
}

namespace {

// The frame's checks, then `parse(reader, message)` on the payload (kAccepted, or the reason);
// the outputs are written only when the whole record is accepted.
template <class Message, class Parse>
RecordStatus decode_record(std::span<const std::uint8_t> in, Channel channel, Message& message, RecordHeader& header,
                           Parse&& parse) {
  RecordHeader h;
  if (const RecordStatus s = read_frame(in, channel, h); s != RecordStatus::kAccepted) return s;
  Reader r(in, kHeaderBytes);
  Message m{};
  m.t = h.t;
  if (const RecordStatus s = parse(r, m); s != RecordStatus::kAccepted) return s;
  message = m;
  header = h;
  return RecordStatus::kAccepted;
}

}  // namespace

RecordStatus decode(std::span<const std::uint8_t> in, TimeAtTone& message, RecordHeader& header) {
  return decode_record(in, Channel::kTimeAtTone, message, header, [](Reader& r, TimeAtTone& m) {
    const double w = r.f64(), x = r.f64(), y = r.f64(), z = r.f64();
    m.q_body_to_gcrf = Eigen::Quaterniond(w, x, y, z);
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, NavigationSolution& message, RecordHeader& header) {
  return decode_record(in, Channel::kNavigation, message, header, [](Reader& r, NavigationSolution& m) {
    for (core::StateVector* x : {&m.chief_gcrf, &m.deputy_gcrf}) {
      x->r = r.vector3();
      x->v = r.vector3();
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = i; j < 6; ++j) m.relative_covariance_rtn(i, j) = m.relative_covariance_rtn(j, i) = r.f64();
    }
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, CrosslinkMessage& message, RecordHeader& header) {
  return decode_record(in, Channel::kCrosslink, message, header, [](Reader& r, CrosslinkMessage& m) {
    const std::uint8_t sender = r.u8(), mode = r.u8();
    if (sender > 1 || mode >= kModes) return RecordStatus::kBadEnumeration;
    m.sender = static_cast<Spacecraft>(sender);
    m.mode = static_cast<Mode>(mode);
    if (!flag(r.u8(), m.sender_active) || !flag(r.u8(), m.has_observation)) return RecordStatus::kBadEnumeration;
    m.observations_done = r.i32();
    m.observations_planned = r.i32();
    m.observation_index = r.i32();
    m.slew_start = r.time();
    m.observation_start = r.time();
    m.observation_end = r.time();
    return read_navigation(r, m.navigation);
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, GroundCommand& message, RecordHeader& header) {
  return decode_record(in, Channel::kGroundCommand, message, header, [](Reader& r, GroundCommand& m) {
    const std::uint8_t kind = r.u8();
    if (kind >= kCommandKinds) return RecordStatus::kBadEnumeration;
    m.kind = static_cast<GroundCommand::Kind>(kind);
    if (!r.zeros(3)) return RecordStatus::kBadPadding;
    m.observations = r.i32();
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, PropulsionTelemetry& message, RecordHeader& header) {
  return decode_record(in, Channel::kPropulsion, message, header, [](Reader& r, PropulsionTelemetry& m) {
    m.dv_body_mps = r.vector3();
    m.mass_kg = r.f64();
    if (!flag(r.u8(), m.executed)) return RecordStatus::kBadEnumeration;
    return r.zeros(7) ? RecordStatus::kAccepted : RecordStatus::kBadPadding;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, GpsMessage& message, RecordHeader& header) {
  return decode_record(in, Channel::kGps, message, header, [](Reader& r, GpsMessage& m) {
    const std::uint8_t count = r.u8();
    if (count > kSlots || !flag(r.u8(), m.has_ephemeris)) return RecordStatus::kBadEnumeration;
    if (!r.zeros(6)) return RecordStatus::kBadPadding;
    m.epoch.t = m.t;
    m.epoch.channel_count = count;
    for (int k = 0; k < kSlots; ++k) {
      if (k >= count) {
        if (!r.zeros(kGpsChannelBytes)) return RecordStatus::kBadPadding;
        continue;
      }
      gnss::GpsChannelMeasurement& c = m.epoch.channels[static_cast<std::size_t>(k)];
      c.prn = r.u8();
      if (!read_lock_flags(r.u8(), c.loss_of_lock, c.half_cycle_ambiguity)) return RecordStatus::kBadEnumeration;
      if (!r.zeros(6)) return RecordStatus::kBadPadding;
      for (double* v : {&c.pseudorange_m, &c.carrier_phase_cycles, &c.doppler_hz, &c.cn0_dbhz, &c.lock_time_s}) *v = r.f64();
    }
    if (!m.has_ephemeris) return r.zeros(kEphemerisBytes) ? RecordStatus::kAccepted : RecordStatus::kBadPadding;
    m.ephemeris = read_ephemeris(r);
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, LaserRange& message, RecordHeader& header) {
  return decode_record(in, Channel::kLaserRange, message, header, [](Reader& r, LaserRange& m) {
    m.range_m = r.f64();
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, ManeuverCommand& message, RecordHeader& header) {
  return decode_record(in, Channel::kManeuver, message, header, [](Reader& r, ManeuverCommand& m) {
    m.dv_body_mps = r.vector3();
    m.dv_rtn_mps = r.vector3();
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, ObservationCommand& message, RecordHeader& header) {
  return decode_record(in, Channel::kObservation, message, header, [](Reader& r, ObservationCommand& m) {
    m.index = r.i32();
    if (!r.zeros(4)) return RecordStatus::kBadPadding;
    m.slew_start = r.time();
    m.start = r.time();
    m.end = r.time();
    return RecordStatus::kAccepted;
  });
}

RecordStatus decode(std::span<const std::uint8_t> in, Telemetry& message, RecordHeader& header) {
  return decode_record(in, Channel::kTelemetry, message, header, [](Reader& r, Telemetry& m) {
    const std::uint8_t mode = r.u8();
    if (mode >= kModes) return RecordStatus::kBadEnumeration;
    m.mode = static_cast<Mode>(mode);
    for (bool* b : {&m.active, &m.estimate_valid, &m.safety_checked, &m.star_tracker_power, &m.lrf_power, &m.gnc_incapable,
                    &m.passive_safety_violated}) {
      if (!flag(r.u8(), *b)) return RecordStatus::kBadEnumeration;
    }
    for (int i = 0; i < 6; ++i) m.roe_mean_m(i) = r.f64();
    m.safety_margin_m = r.f64();
    for (int i = 0; i < 6; ++i) m.roe_target_m(i) = r.f64();
    m.observations_done = r.i32();
    m.pending_pieces = r.i32();
    m.plans = r.i64();
    m.planning_failures = r.i64();
    RejectionCounters& c = m.rejected;
    for (std::int64_t* v : {&c.time_at_tone, &c.navigation, &c.crosslink, &c.command, &c.propulsion, &c.gps, &c.laser_range}) {
      *v = r.i64();
    }
    for (std::int64_t& v : m.records.by_status) v = r.i64();
    if (!flag(r.u8(), m.navigation_valid) || !flag(r.u8(), m.navigation_fixed) || !flag(r.u8(), m.drag_valid)) {
      return RecordStatus::kBadEnumeration;
    }
    if (!r.zeros(5)) return RecordStatus::kBadPadding;
    m.navigation_update = r.time();
    m.differential_drag_mps2 = r.f64();
    return RecordStatus::kAccepted;
  });
}

namespace {

void read_counters(Reader& r, NavigationCounters& c) {
  for (std::int64_t* v : {&c.epochs_joint, &c.epochs_alone, &c.epochs_refused, &c.epochs_fixed, &c.wrong_fixes_refused,
                          &c.impulses_applied, &c.impulses_late, &c.laser_used, &c.laser_rejected, &c.clock_jumps}) {
    *v = r.i64();
  }
  for (std::int64_t& v : c.ephemerides) v = r.i64();
}

// The double differences after the first `count` must be all 0 (a record decodes to one message).
RecordStatus read_double_differences(Reader& r, NavigationTelemetry& m) {
  for (int k = 0; k < kTelemetryDoubleDifferences; ++k) {
    if (k >= m.dd_count) {
      if (!r.zeros(kDoubleDifferenceBytes)) return RecordStatus::kBadPadding;
      continue;
    }
    FixedDoubleDifference& d = m.dd[static_cast<std::size_t>(k)];
    d.prn = r.u8();
    if (!r.zeros(7)) return RecordStatus::kBadPadding;
    d.integer_cycles = r.i64();
    d.fixed_cycles = r.f64();
  }
  return RecordStatus::kAccepted;
}

// The combinations after the first `combination_count`, and each one's coefficients after the
// first dd_count, must be all 0.
RecordStatus read_combinations(Reader& r, NavigationTelemetry& m) {
  for (int i = 0; i < kTelemetryDoubleDifferences; ++i) {
    if (i >= m.combination_count) {
      if (!r.zeros(kCombinationBytes)) return RecordStatus::kBadPadding;
      continue;
    }
    FixedCombination& c = m.combinations[static_cast<std::size_t>(i)];
    for (int j = 0; j < kTelemetryDoubleDifferences; ++j) {
      c.dd_coefficients[static_cast<std::size_t>(j)] = r.i32();
      if (j >= m.dd_count && c.dd_coefficients[static_cast<std::size_t>(j)] != 0) return RecordStatus::kBadPadding;
    }
    if (!r.zeros(4)) return RecordStatus::kBadPadding;
    c.integer_cycles = r.i64();
  }
  return RecordStatus::kAccepted;
}

}  // namespace

RecordStatus decode(std::span<const std::uint8_t> in, NavigationTelemetry& message, RecordHeader& header) {
  return decode_record(in, Channel::kNavigationTelemetry, message, header, [](Reader& r, NavigationTelemetry& m) {
    for (bool* b : {&m.has_solution, &m.valid, &m.fixed, &m.fix_applied, &m.full_fix}) {
      if (!flag(r.u8(), *b)) return RecordStatus::kBadEnumeration;
    }
    m.dd_count = r.u8();
    if (m.dd_count > kTelemetryDoubleDifferences) return RecordStatus::kBadEnumeration;
    m.dd_reference_prn = r.u8();
    m.combination_count = r.u8();
    if (m.combination_count > m.dd_count) return RecordStatus::kBadEnumeration;
    m.update_t = r.time();
    for (core::StateVector* x : {&m.dsc_gcrf, &m.osc_gcrf}) {
      x->r = r.vector3();
      x->v = r.vector3();
    }
    for (Eigen::Vector3d* v : {&m.p_dsc_body_m, &m.p_osc_body_m, &m.empirical_dsc_rtn_mps2, &m.empirical_osc_rtn_mps2,
                               &m.relative_sigma_rtn_m}) {
      *v = r.vector3();
    }
    if (const RecordStatus s = read_double_differences(r, m); s != RecordStatus::kAccepted) return s;
    if (const RecordStatus s = read_combinations(r, m); s != RecordStatus::kAccepted) return s;
    read_counters(r, m.counters);
    return RecordStatus::kAccepted;
  });
}

bool SequenceGate::would_admit(const RecordHeader& header) const {
  const auto c = static_cast<std::size_t>(header.channel);
  // Serial-number comparison (RFC 1982): ahead when the u32 difference, read signed, is > 0.
  return !seen_[c] || static_cast<std::int32_t>(header.sequence - last_[c]) > 0;
}

RecordStatus SequenceGate::admit(const RecordHeader& header) {
  if (!would_admit(header)) return RecordStatus::kOutOfOrder;
  const auto c = static_cast<std::size_t>(header.channel);
  seen_[c] = true;
  last_[c] = header.sequence;
  return RecordStatus::kAccepted;
}

}  // namespace visors::gnc
