// visors-fsw: one spacecraft's flight software as its own process behind its byte interface
// (docs/flight-software-process.md): the seam at which the simulator, a hardware-in-the-loop bench
// or the spacecraft's host application drives it.
//
//   visors-fsw --config FLIGHT_CONFIG_JSON --craft dsc|osc
//
// Creates the component of `craft` from the flight configuration file (gnc/files/
// flight_config_json.hpp: the file `visors run` writes in its run directory), then speaks the
// record stream of gnc/record_stream.hpp on its standard input and output:
//  - once created, an empty batch ("ready");
//  - for each batch of input records, one step at the batch's tone (RecordInterface::tone: the
//    time tag of its time-at-tone record) and a batch of the step's output records (maneuver,
//    observation, crosslink, telemetry, navigation telemetry: those the step produced, in this
//    order). A batch without a tone is not stepped: an empty batch answers it, and it is counted.
// Records beyond kMaxStepRecords in a batch and frames too long for a record are dropped and
// counted. When the input stream closes between batches the process ends (exit 0) with its counts
// and its footprint (footprint.hpp: heap, peak resident memory, stack high-water) on standard
// error. Exit 2: bad arguments or configuration; 1: a broken stream.
// After creation nothing is allocated: the step and the stream use the buffers made here.

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <unistd.h>

#include "footprint.hpp"
#include "visors/gnc/files/flight_config_json.hpp"
#include "visors/gnc/record_interface.hpp"
#include "visors/gnc/record_stream.hpp"

namespace {

using visors::gnc::FrameStatus;
using visors::gnc::RecordView;

constexpr int kExitBrokenStream = 1;
constexpr int kExitBadInput = 2;
/// The records of one step the process keeps; a step of the simulator's garbage fault has ~25.
constexpr std::size_t kMaxStepRecords = 64;

struct Arguments {
  std::string config;
  std::string craft;
};

std::optional<Arguments> parse_arguments(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if ((arg == "--config" || arg == "--craft") && i + 1 < argc) {
      (arg == "--config" ? a.config : a.craft) = argv[++i];
    } else {
      std::fprintf(stderr, "visors-fsw: unexpected argument '%s'\n", argv[i]);
      return std::nullopt;
    }
  }
  if (a.config.empty() || (a.craft != "dsc" && a.craft != "osc")) {
    std::fprintf(stderr, "usage: visors-fsw --config FLIGHT_CONFIG_JSON --craft dsc|osc\n");
    return std::nullopt;
  }
  return a;
}

/// What the stream brought and what was dropped, for the report at the end.
struct Counts {
  std::int64_t steps = 0, records = 0, beyond_capacity = 0, too_long = 0, without_tone = 0;
};

/// The process's buffers, made once.
struct Link {
  visors::gnc::FrameReader in{STDIN_FILENO};
  visors::gnc::FrameWriter out{STDOUT_FILENO};
  std::array<visors::gnc::RecordBuffer, kMaxStepRecords> records{};
  std::array<RecordView, kMaxStepRecords> views{};
  visors::gnc::RecordBuffer spill{};  // where a record beyond the capacity is read, then dropped
  std::size_t count = 0;              // records of the current batch
};

/// Reads one batch into link.views[0, count). Returns kEndOfBatch, kEndOfStream (closed before
/// the batch's first frame) or kBroken.
FrameStatus read_batch(Link& link, Counts& counts) {
  link.count = 0;
  bool first = true;
  for (;;) {
    const bool room = link.count < kMaxStepRecords;
    visors::gnc::RecordBuffer& buffer = room ? link.records[link.count] : link.spill;
    std::size_t size = 0;
    const FrameStatus status = link.in.next(buffer, size);
    if (status == FrameStatus::kEndOfStream) return first ? status : FrameStatus::kBroken;
    if (status == FrameStatus::kEndOfBatch || status == FrameStatus::kBroken) return status;
    first = false;
    if (status == FrameStatus::kTooLong) {
      ++counts.too_long;
    } else if (!room) {
      ++counts.beyond_capacity;
    } else {
      link.views[link.count++] = RecordView(buffer.data(), size);
      ++counts.records;
    }
  }
}

/// The counts and the footprint on standard error, at the end.
void report(const char* craft, const Counts& c, const visors::fsw::Footprint& f, int status) {
  const auto n = [](std::int64_t v) { return static_cast<long long>(v); };
  const auto kib = [](std::size_t bytes) { return static_cast<unsigned long long>((bytes + 1023) / 1024); };
  std::fprintf(stderr,
               "visors-fsw %s: %lld steps, %lld records; dropped: %lld beyond %zu a batch, %lld frames too long; "
               "%lld batches without a tone%s\n",
               craft, n(c.steps), n(c.records), n(c.beyond_capacity), kMaxStepRecords, n(c.too_long),
               n(c.without_tone), status == 0 ? "" : "; the stream broke");
  std::fprintf(stderr,
               "visors-fsw %s: heap in use %llu KiB after creation, %llu KiB at the end; peak resident %llu KiB; "
               "stack high-water %llu KiB%s\n",
               craft, kib(f.heap_after_creation), kib(f.heap_at_end), kib(f.peak_resident), kib(f.stack_high_water),
               f.stack_high_water >= visors::fsw::kPaintedBytes ? " (at least: the painted region)" : "");
}

/// Steps at each batch's tone until the input ends. Returns the exit status.
int serve(visors::gnc::RecordInterface& component, Link& link, Counts& counts) {
  if (!link.out.end_batch()) return kExitBrokenStream;  // ready
  for (;;) {
    const FrameStatus batch = read_batch(link, counts);
    if (batch == FrameStatus::kEndOfStream) return 0;
    if (batch == FrameStatus::kBroken) return kExitBrokenStream;
    const std::span<const RecordView> inputs(link.views.data(), link.count);
    bool written = true;
    if (const auto tone = component.tone(inputs)) {
      const visors::gnc::OutputRecords& out = component.step(*tone, inputs);
      for (const auto* record : {&out.maneuver, &out.observation, &out.crosslink, &out.telemetry, &out.navigation}) {
        written = written && link.out.record(record->view());
      }
      ++counts.steps;
    } else {
      ++counts.without_tone;
    }
    if (!written || !link.out.end_batch()) return kExitBrokenStream;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = parse_arguments(argc, argv);
  if (!args) return kExitBadInput;
  const char* craft = args->craft.c_str();
  auto setup = visors::gnc::files::read_component_setup(args->config, args->craft);
  if (!setup.ok()) {
    std::fprintf(stderr, "visors-fsw %s: %s\n", craft, setup.error().describe().c_str());
    return kExitBadInput;
  }
  auto component = visors::gnc::files::make_component(setup.value());
  if (!component.ok()) {
    std::fprintf(stderr, "visors-fsw %s: %s\n", craft, component.error().describe().c_str());
    return kExitBadInput;
  }
  visors::gnc::RecordInterface flight_software = std::move(component).value();
  auto link = std::make_unique<Link>();
  Counts counts;
  visors::fsw::Footprint footprint;
  footprint.heap_after_creation = visors::fsw::heap_in_use();
  visors::fsw::StackGauge stack;
  stack.paint(&footprint);
  const int status = serve(flight_software, *link, counts);
  footprint.stack_high_water = stack.high_water();
  footprint.heap_at_end = visors::fsw::heap_in_use();
  footprint.peak_resident = visors::fsw::peak_resident();
  report(craft, counts, footprint, status);
  return status;
}
