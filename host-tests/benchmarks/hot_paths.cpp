#include "hot_paths.hpp"

#include <string.h>

namespace costa::hotpaths {
namespace {

constexpr uint32_t kSdoRequest = 0x600U + Bench::kNodeId;
constexpr uint32_t kSdoResponse = 0x580U + Bench::kNodeId;

constexpr CanFrame frame(uint32_t id, uint8_t dlc, uint8_t b0 = 0, uint8_t b1 = 0, uint8_t b2 = 0,
                         uint8_t b3 = 0, uint8_t b4 = 0, uint8_t b5 = 0, uint8_t b6 = 0,
                         uint8_t b7 = 0) noexcept {
  return CanFrame{id, {b0, b1, b2, b3, b4, b5, b6, b7}, dlc, false, false};
}

/// Null when the frames sent since `firstFrame` are exactly `expected[0..count)`.
const char* expectFrames(const Bench& bench, uint32_t firstFrame, const CanFrame* expected,
                         uint32_t count) noexcept {
  if (bench.can().sent() - firstFrame != count) {
    return "a different number of frames than expected was sent";
  }
  for (uint32_t i = 0; i < count; ++i) {
    if (!sameOnWire(bench.can().frame(firstFrame + i), expected[i])) {
      return "a frame differs from the expected one";
    }
  }
  return nullptr;
}

// --- The empty operation and the idle processing cycle. -------------------------------------
void runEmpty(Bench&) noexcept {}

void runIdle(Bench& bench) noexcept {
  bench.cycle();
}

const char* verifyNothingSent(Bench& bench, uint32_t firstFrame) noexcept {
  return expectFrames(bench, firstFrame, nullptr, 0);
}

// --- SDO expedited upload of 0x1017 (UNSIGNED16, 0). ------------------------------------------
constexpr CanFrame kUpload1017 = frame(kSdoRequest, 8, 0x40, 0x17, 0x10, 0x00);

void runUpload1017(Bench& bench) noexcept {
  bench.receive(kUpload1017);
}

const char* verifyUpload1017(Bench& bench, uint32_t firstFrame) noexcept {
  static constexpr CanFrame kExpected[] = {frame(kSdoResponse, 8, 0x4B, 0x17, 0x10, 0x00)};
  return expectFrames(bench, firstFrame, kExpected, 1);
}

// --- SDO expedited download 0x1017 = 0. -------------------------------------------------------
constexpr CanFrame kDownload1017 = frame(kSdoRequest, 8, 0x2B, 0x17, 0x10, 0x00);

void runDownload1017(Bench& bench) noexcept {
  bench.receive(kDownload1017);
}

void clearDownload1017(Bench& bench) noexcept {
  bench.node().values().x1017_producer_heartbeat_time = 0xFFFF;
}

const char* verifyDownload1017(Bench& bench, uint32_t firstFrame) noexcept {
  static constexpr CanFrame kExpected[] = {frame(kSdoResponse, 8, 0x60, 0x17, 0x10, 0x00)};
  if (bench.node().values().x1017_producer_heartbeat_time != 0U) {
    return "0x1017 was not written";
  }
  return expectFrames(bench, firstFrame, kExpected, 1);
}

// --- SDO segmented upload of 0x2002 (VISIBLE_STRING, 20 characters): the whole transfer,
// initiate and three segment requests. -------------------------------------------------------
constexpr CanFrame kUploadLabel = frame(kSdoRequest, 8, 0x40, 0x02, 0x20, 0x00);
constexpr CanFrame kSegmentToggle0 = frame(kSdoRequest, 8, 0x60);
constexpr CanFrame kSegmentToggle1 = frame(kSdoRequest, 8, 0x70);

void runSegmentedUpload(Bench& bench) noexcept {
  bench.receive(kUploadLabel);
  bench.receive(kSegmentToggle0);
  bench.receive(kSegmentToggle1);
  bench.receive(kSegmentToggle0);
}

const char* verifySegmentedUpload(Bench& bench, uint32_t firstFrame) noexcept {
  static constexpr CanFrame kExpected[] = {
      frame(kSdoResponse, 8, 0x41, 0x02, 0x20, 0x00, 20),                // size indicated, 20
      frame(kSdoResponse, 8, 0x00, 'A', 'B', 'C', 'D', 'E', 'F', 'G'),   // toggle 0
      frame(kSdoResponse, 8, 0x10, 'H', 'I', 'J', 'K', 'L', 'M', 'N'),   // toggle 1
      frame(kSdoResponse, 8, 0x03, 'O', 'P', 'Q', 'R', 'S', 'T', 0x00),  // 6 bytes, last
  };
  return expectFrames(bench, firstFrame, kExpected, 4);
}

// --- RPDO1: 2 x UNSIGNED32 into 0x2000:01..02. ------------------------------------------------
constexpr CanFrame kRpdo2x32 =
    frame(0x200U + Bench::kNodeId, 8, 0x44, 0x33, 0x22, 0x11, 0x88, 0x77, 0x66, 0x55);

void runRpdo2x32(Bench& bench) noexcept {
  bench.receive(kRpdo2x32);
}

void clearRpdo2x32(Bench& bench) noexcept {
  memset(bench.node().values().x2000_received_2_x_u32.item, 0,
         sizeof bench.node().values().x2000_received_2_x_u32.item);
}

const char* verifyRpdo2x32(Bench& bench, uint32_t firstFrame) noexcept {
  const uint32_t* words = bench.node().values().x2000_received_2_x_u32.item;
  if (words[0] != 0x11223344U || words[1] != 0x55667788U) {
    return "0x2000:01..02 do not hold the RPDO's values";
  }
  return verifyNothingSent(bench, firstFrame);
}

// --- RPDO2: 8 x UNSIGNED8 into 0x2001:01..08. -------------------------------------------------
constexpr CanFrame kRpdo8x8 = frame(0x300U + Bench::kNodeId, 8, 1, 2, 3, 4, 5, 6, 7, 8);

void runRpdo8x8(Bench& bench) noexcept {
  bench.receive(kRpdo8x8);
}

void clearRpdo8x8(Bench& bench) noexcept {
  memset(bench.node().values().x2001_received_8_x_u8.item, 0,
         sizeof bench.node().values().x2001_received_8_x_u8.item);
}

const char* verifyRpdo8x8(Bench& bench, uint32_t firstFrame) noexcept {
  const uint8_t* bytes = bench.node().values().x2001_received_8_x_u8.item;
  for (uint8_t i = 0; i < 8U; ++i) {
    if (bytes[i] != i + 1U) {
      return "0x2001:01..08 do not hold the RPDO's values";
    }
  }
  return verifyNothingSent(bench, firstFrame);
}

// --- SYNC: TPDO1..4 (type 1), 0x2003:01..08 = 0x11111111 x sub-index. -------------------------
constexpr CanFrame kSync = frame(0x080, 0);

void runSync(Bench& bench) noexcept {
  bench.receive(kSync);
}

const char* verifySync(Bench& bench, uint32_t firstFrame) noexcept {
  static constexpr CanFrame kExpected[] = {
      frame(0x181, 8, 0x11, 0x11, 0x11, 0x11, 0x22, 0x22, 0x22, 0x22),
      frame(0x281, 8, 0x33, 0x33, 0x33, 0x33, 0x44, 0x44, 0x44, 0x44),
      frame(0x381, 8, 0x55, 0x55, 0x55, 0x55, 0x66, 0x66, 0x66, 0x66),
      frame(0x481, 8, 0x77, 0x77, 0x77, 0x77, 0x88, 0x88, 0x88, 0x88),
  };
  return expectFrames(bench, firstFrame, kExpected, 4);
}

const Operation kOperations[] = {
    {kEmptyKey, "empty measuring loop", 0, runEmpty, nullptr, verifyNothingSent},
    {kIdleKey, "idle processing cycle (process(), nothing due)", 0, runIdle, nullptr,
     verifyNothingSent},
    {"sdo_upload_1017", "SDO expedited upload 0x1017", 1, runUpload1017, nullptr, verifyUpload1017},
    {"sdo_download_1017", "SDO expedited download 0x1017", 1, runDownload1017, clearDownload1017,
     verifyDownload1017},
    {"sdo_segmented_upload_20", "SDO segmented upload, 20 bytes (initiate + 3 segments)", 4,
     runSegmentedUpload, nullptr, verifySegmentedUpload},
    {"rpdo_2x32", "RPDO 2 x u32", 1, runRpdo2x32, clearRpdo2x32, verifyRpdo2x32},
    {"rpdo_8x8", "RPDO 8 x u8", 1, runRpdo8x8, clearRpdo8x8, verifyRpdo8x8},
    {"sync_4_tpdos", "SYNC -> 4 synchronous TPDOs", 1, runSync, nullptr, verifySync},
};

NodeSettings settings() noexcept {
  NodeSettings settings;
  settings.nodeId = Bench::kNodeId;
  return settings;
}

const char* checkedRun(Bench& bench, const Operation& operation) noexcept {
  if (operation.clear != nullptr) {
    operation.clear(bench);
  }
  const uint32_t first = bench.can().sent();
  operation.run(bench);
  return operation.verify(bench, first);
}

}  // namespace

Bench::Bench() noexcept : node_(gen::hot_paths::kDefinition, can_, settings()) {}

const char* Bench::start() noexcept {
  node_.start(now_);
  static_cast<void>(node_.process(now_));
  node_.enterState(NmtState::kOperational);
  for (int i = 0; i < 10; ++i) {
    cycle();
  }
  return node_.state() == NmtState::kOperational ? nullptr : "the node is not operational";
}

const Operation* operations(size_t* count) noexcept {
  *count = sizeof kOperations / sizeof kOperations[0];
  return kOperations;
}

const char* prepare(Bench& bench, const Operation& operation, uint32_t warmUpRuns) noexcept {
  const char* error = checkedRun(bench, operation);
  for (uint32_t i = 0; error == nullptr && i < warmUpRuns; ++i) {
    operation.run(bench);
  }
  return error != nullptr ? error : checkedRun(bench, operation);
}

}  // namespace costa::hotpaths
