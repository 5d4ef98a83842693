#include "visors/gnc/record_stream.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <poll.h>
#include <unistd.h>

namespace visors::gnc {

FrameReader::Fill FrameReader::fill(int timeout_ms) {
  if (begin_ == end_) begin_ = end_ = 0;
  if (begin_ > 0 && end_ == buffer_.size()) {  // room at the end: move the unread bytes to the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  for (;;) {
    if (timeout_ms >= 0) {
      pollfd p{.fd = fd_, .events = POLLIN, .revents = 0};
      const int ready = ::poll(&p, 1, timeout_ms);
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) return Fill::kFailed;  // the timeout ran out, or poll failed
    }
    const ssize_t n = ::read(fd_, buffer_.data() + end_, buffer_.size() - end_);
    if (n > 0) {
      end_ += static_cast<std::size_t>(n);
      return Fill::kData;
    }
    if (n == 0) return Fill::kClosed;
    if (errno != EINTR) return Fill::kFailed;
  }
}

FrameReader::Fill FrameReader::take(std::uint8_t* out, std::size_t n, int timeout_ms) {
  std::size_t taken = 0;
  while (taken < n) {
    if (begin_ == end_) {
      const Fill f = fill(timeout_ms);
      if (f == Fill::kClosed && taken > 0) return Fill::kFailed;  // closed within the piece
      if (f != Fill::kData) return f;
    }
    const std::size_t k = std::min(n - taken, end_ - begin_);
    if (out != nullptr) std::memcpy(out + taken, buffer_.data() + begin_, k);
    begin_ += k;
    taken += k;
  }
  return Fill::kData;
}

FrameStatus FrameReader::next(RecordBuffer& record, std::size_t& size, int timeout_ms) {
  size = 0;
  std::array<std::uint8_t, kFrameLengthBytes> length_bytes{};
  const Fill head = take(length_bytes.data(), length_bytes.size(), timeout_ms);
  if (head == Fill::kClosed) return FrameStatus::kEndOfStream;
  if (head == Fill::kFailed) return FrameStatus::kBroken;
  std::size_t length = 0;
  for (std::size_t i = 0; i < kFrameLengthBytes; ++i) length |= static_cast<std::size_t>(length_bytes[i]) << (8 * i);
  if (length == 0) return FrameStatus::kEndOfBatch;
  const bool fits = length <= kMaxFrameBytes;
  if (take(fits ? record.data() : nullptr, length, timeout_ms) != Fill::kData) return FrameStatus::kBroken;
  if (!fits) return FrameStatus::kTooLong;
  size = length;
  return FrameStatus::kRecord;
}

bool FrameWriter::flush() {
  std::size_t written = 0;
  while (written < size_) {
    const ssize_t n = ::write(fd_, buffer_.data() + written, size_ - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  size_ = 0;
  return true;
}

bool FrameWriter::queue(std::span<const std::uint8_t> bytes) {
  while (!bytes.empty()) {
    if (size_ == buffer_.size() && !flush()) return false;
    const std::size_t k = std::min(bytes.size(), buffer_.size() - size_);
    std::memcpy(buffer_.data() + size_, bytes.data(), k);
    size_ += k;
    bytes = bytes.subspan(k);
  }
  return true;
}

bool FrameWriter::record(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return true;  // no record (a frame of length 0 would end the batch)
  if constexpr (sizeof(std::size_t) > 4) {
    if (bytes.size() > 0xFFFFFFFFu) return false;
  }
  const auto length = static_cast<std::uint32_t>(bytes.size());
  const std::array<std::uint8_t, kFrameLengthBytes> length_bytes{
      static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8), static_cast<std::uint8_t>(length >> 16),
      static_cast<std::uint8_t>(length >> 24)};
  return queue(length_bytes) && queue(bytes);
}

bool FrameWriter::end_batch() {
  constexpr std::array<std::uint8_t, kFrameLengthBytes> kEnd{};
  return queue(kEnd) && flush();
}

}  // namespace visors::gnc
