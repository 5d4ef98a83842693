// Records over a byte stream (gnc/record_stream.hpp), through a real pipe: frames and batches
// read back as written, a frame too long for a record dropped without losing the stream, the
// stream's end told apart from a frame cut short, a silent writer caught by the timeout.
#include <gtest/gtest.h>

#include <array>
#include <csignal>
#include <cstdint>
#include <thread>
#include <vector>

#include <unistd.h>

#include "visors/gnc/record_stream.hpp"

namespace visors::gnc {
namespace {

// A pipe whose ends close with the test.
struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int fd[2];
    EXPECT_EQ(::pipe(fd), 0);
    read = fd[0];
    write = fd[1];
  }
  void close_write() {
    if (write >= 0) ::close(write);
    write = -1;
  }
  ~Pipe() {
    close_write();
    ::close(read);
  }
};

std::vector<std::uint8_t> bytes(std::size_t n, std::uint8_t first) {
  std::vector<std::uint8_t> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(first + i);
  return b;
}

struct Read {
  FrameStatus status;
  std::vector<std::uint8_t> bytes;
};

Read next(FrameReader& reader, int timeout_ms = 2000) {
  RecordBuffer buffer{};
  std::size_t size = 99;
  const FrameStatus status = reader.next(buffer, size, timeout_ms);
  return {status, std::vector<std::uint8_t>(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(size))};
}

TEST(RecordStream, ARecordReadsBackAsWritten) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  const auto record = bytes(kMaxRecordBytes, 3);
  ASSERT_TRUE(writer.record(record));
  ASSERT_TRUE(writer.end_batch());
  const Read r = next(reader);
  EXPECT_EQ(r.status, FrameStatus::kRecord);
  EXPECT_EQ(r.bytes, record);
}

TEST(RecordStream, TheEmptyFrameEndsTheBatch) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  ASSERT_TRUE(writer.record(bytes(30, 1)));
  ASSERT_TRUE(writer.end_batch());
  next(reader);
  EXPECT_EQ(next(reader).status, FrameStatus::kEndOfBatch);
}

// An empty record would be read as the batch's end: the writer sends nothing for it.
TEST(RecordStream, AnEmptyRecordIsNotWritten) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  ASSERT_TRUE(writer.record({}));
  ASSERT_TRUE(writer.record(bytes(5, 1)));
  ASSERT_TRUE(writer.end_batch());
  EXPECT_EQ(next(reader).bytes, bytes(5, 1));
}

// Batches larger than the writer's and the reader's buffers (64 KiB) arrive whole and in order;
// a thread reads while the writer writes (a pipe holds 64 KiB).
TEST(RecordStream, BatchesLargerThanTheBuffersArriveInOrder) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  constexpr int kRecords = 200;  // 200 x 1,268 bytes: four buffers' worth
  std::vector<Read> got;
  std::thread consumer([&] {
    for (int i = 0; i <= kRecords; ++i) got.push_back(next(reader, 10000));
  });
  for (int i = 0; i < kRecords; ++i) ASSERT_TRUE(writer.record(bytes(kMaxRecordBytes, static_cast<std::uint8_t>(i))));
  ASSERT_TRUE(writer.end_batch());
  consumer.join();
  ASSERT_EQ(got.size(), static_cast<std::size_t>(kRecords + 1));
  bool in_order = true;
  for (int i = 0; i < kRecords; ++i) {
    in_order = in_order && got[static_cast<std::size_t>(i)].bytes == bytes(kMaxRecordBytes, static_cast<std::uint8_t>(i));
  }
  EXPECT_TRUE(in_order);
  EXPECT_EQ(got.back().status, FrameStatus::kEndOfBatch);
}

// A frame longer than any record is dropped whole: the frame after it reads intact.
TEST(RecordStream, AFrameTooLongIsDroppedAndTheNextReadsIntact) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  std::thread producer([&] {
    writer.record(bytes(kMaxFrameBytes + 1, 0));
    writer.record(bytes(12, 7));
    writer.end_batch();
  });
  const Read dropped = next(reader);
  const Read after = next(reader);
  producer.join();
  EXPECT_EQ(dropped.status, FrameStatus::kTooLong);
  EXPECT_TRUE(dropped.bytes.empty());
  EXPECT_EQ(after.bytes, bytes(12, 7));
}

TEST(RecordStream, AStreamClosedBetweenFramesIsItsEnd) {
  Pipe pipe;
  FrameWriter writer(pipe.write);
  FrameReader reader(pipe.read);
  ASSERT_TRUE(writer.end_batch());
  pipe.close_write();
  next(reader);
  EXPECT_EQ(next(reader).status, FrameStatus::kEndOfStream);
}

// A writer gone within a frame (its length said 100 bytes, 10 came) breaks the stream.
TEST(RecordStream, AStreamClosedWithinAFrameIsBroken) {
  Pipe pipe;
  FrameReader reader(pipe.read);
  const std::array<std::uint8_t, 14> cut{100, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  ASSERT_EQ(::write(pipe.write, cut.data(), cut.size()), static_cast<ssize_t>(cut.size()));
  pipe.close_write();
  EXPECT_EQ(next(reader).status, FrameStatus::kBroken);
}

TEST(RecordStream, AStreamClosedWithinALengthIsBroken) {
  Pipe pipe;
  FrameReader reader(pipe.read);
  const std::array<std::uint8_t, 2> cut{100, 0};
  ASSERT_EQ(::write(pipe.write, cut.data(), cut.size()), static_cast<ssize_t>(cut.size()));
  pipe.close_write();
  EXPECT_EQ(next(reader).status, FrameStatus::kBroken);
}

TEST(RecordStream, ASilentWriterRunsOutTheTimeout) {
  Pipe pipe;
  FrameReader reader(pipe.read);
  EXPECT_EQ(next(reader, 50).status, FrameStatus::kBroken);
}

// Writing to a reader that is gone fails (EPIPE; SIGPIPE ignored here, as the host does).
TEST(RecordStream, WritingToAClosedReaderFails) {
  int fd[2];
  ASSERT_EQ(::pipe(fd), 0);
  ::close(fd[0]);
  std::signal(SIGPIPE, SIG_IGN);
  FrameWriter writer(fd[1]);
  writer.record(bytes(10, 0));
  EXPECT_FALSE(writer.end_batch());
  ::close(fd[1]);
}

}  // namespace
}  // namespace visors::gnc
