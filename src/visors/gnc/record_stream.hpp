#pragma once
// Records over a byte stream (a pipe, a local socket, a serial line) between a host and a flight
// software process (apps/fsw/, docs/flight-software-process.md). Each record travels in a frame:
// its length (u32, little-endian) then its bytes, so a garbage record cannot desynchronise the
// stream whatever its own header says; a frame of length 0 closes a batch (the records of one
// step: its inputs one way, its outputs the other).
// Blocking I/O on a file descriptor through fixed buffers: nothing is allocated after
// construction, nothing throws. A read may be given a timeout (the host's watchdog on a process
// that stopped answering).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "visors/gnc/channel_record.hpp"

namespace visors::gnc {

inline constexpr std::size_t kFrameLengthBytes = 4;
/// The longest frame read into a record buffer: any longer is no record of this interface.
inline constexpr std::size_t kMaxFrameBytes = kMaxRecordBytes;

enum class FrameStatus : std::uint8_t {
  kRecord,       // a frame of 1..kMaxFrameBytes bytes, now in the record buffer
  kEndOfBatch,   // a frame of length 0
  kTooLong,      // a frame longer than kMaxFrameBytes: its bytes read and dropped
  kEndOfStream,  // the writer closed the stream between two frames
  kBroken,       // closed within a frame, a read error, or the timeout ran out
};

class FrameReader {
 public:
  explicit FrameReader(int fd) : fd_(fd) {}
  /// The next frame; a record's bytes go to `record`, their number to `size` (0 otherwise).
  /// `timeout_ms`: the longest wait for the stream's next bytes (< 0: forever).
  FrameStatus next(RecordBuffer& record, std::size_t& size, int timeout_ms = -1);

 private:
  enum class Fill : std::uint8_t { kData, kClosed, kFailed };
  Fill fill(int timeout_ms);  // reads what the stream has (at least a byte) into buffer_
  /// Takes n bytes of the stream (to `out`, or dropped when null); kClosed only before the first.
  Fill take(std::uint8_t* out, std::size_t n, int timeout_ms);

  int fd_;
  std::array<std::uint8_t, 1 << 16> buffer_{};
  std::size_t begin_ = 0, end_ = 0;  // the unread bytes: [begin_, end_)
};

class FrameWriter {
 public:
  explicit FrameWriter(int fd) : fd_(fd) {}
  /// Queues a record's frame (any length up to 2^32 - 1: the reader drops what is too long; an
  /// empty span is no record and queues nothing). False when a write failed (the reader is gone)
  /// or the record is longer than a frame can say.
  bool record(std::span<const std::uint8_t> bytes);
  /// Queues the end of the batch and writes out everything queued. False when a write failed.
  bool end_batch();

 private:
  bool queue(std::span<const std::uint8_t> bytes);
  bool flush();

  int fd_;
  std::array<std::uint8_t, 1 << 16> buffer_{};
  std::size_t size_ = 0;
};

}  // namespace visors::gnc
