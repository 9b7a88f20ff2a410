#include "operations.hpp"

#include <vector>

namespace costa::bench {
namespace {

constexpr uint8_t kId = BenchNode::kNodeId;

// Pre-operational, as the node is after power-on.
std::string asBooted(BenchNode&) {
  return "";
}

std::string operational(BenchNode& node) {
  return node.nmt(NmtCommand::kStart, NmtState::kOperational);
}

// --- SDO expedited upload: read 0x2000 (UNSIGNED32 setpoint, 1000), pre-operational. --------
const CanFrame kUploadSetpoint = makeFrame(0x600 + kId, {0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0});

void uploadExpedited(BenchNode& node) {
  node.node().onFrame(kUploadSetpoint, node.now());
}

std::string verifyUploadExpedited(BenchNode& node) {
  return node.expectFrames(
      {makeFrame(0x580 + kId, {0x43, 0x00, 0x20, 0x00, 0xE8, 0x03, 0x00, 0x00})});
}

// --- SDO expedited download: write 0x2000 = 1000, pre-operational. --------------------------
const CanFrame kDownloadSetpoint =
    makeFrame(0x600 + kId, {0x23, 0x00, 0x20, 0x00, 0xE8, 0x03, 0x00, 0x00});

void downloadExpedited(BenchNode& node) {
  node.node().onFrame(kDownloadSetpoint, node.now());
}

std::string verifyDownloadExpedited(BenchNode& node) {
  return node.expectFrames({makeFrame(0x580 + kId, {0x60, 0x00, 0x20, 0x00, 0, 0, 0, 0})});
}

// --- SDO segmented upload: 0x2006 (device label) holding 32 characters, so one run is the
// initiate exchange and 5 segment exchanges. Counted per segment: (initiate + 5 segments) / 5.
const char kLabel[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZ012345";
const CanFrame kUploadLabel = makeFrame(0x600 + kId, {0x40, 0x06, 0x20, 0x00, 0, 0, 0, 0});
const CanFrame kSegmentToggle0 = makeFrame(0x600 + kId, {0x60, 0, 0, 0, 0, 0, 0, 0});
const CanFrame kSegmentToggle1 = makeFrame(0x600 + kId, {0x70, 0, 0, 0, 0, 0, 0, 0});

std::string prepareLabel(BenchNode& node) {
  return node.sdoDownload(0x2006, 0, std::vector<uint8_t>(kLabel, kLabel + sizeof kLabel - 1));
}

void uploadSegmented(BenchNode& node) {
  Node& n = node.node();
  const Microseconds now = node.now();
  n.onFrame(kUploadLabel, now);
  n.onFrame(kSegmentToggle0, now);
  n.onFrame(kSegmentToggle1, now);
  n.onFrame(kSegmentToggle0, now);
  n.onFrame(kSegmentToggle1, now);
  n.onFrame(kSegmentToggle0, now);
}

std::string verifyUploadSegmented(BenchNode& node) {
  constexpr uint32_t kResponse = 0x580 + kId;
  return node.expectFrames({
      makeFrame(kResponse, {0x41, 0x06, 0x20, 0x00, 0x20, 0x00, 0x00, 0x00}),  // 32 bytes
      makeFrame(kResponse, {0x00, 0x41, 0x42, 0x43, 0x44, 0x45, 0x46, 0x47}),  // "ABCDEFG"
      makeFrame(kResponse, {0x10, 0x48, 0x49, 0x4A, 0x4B, 0x4C, 0x4D, 0x4E}),  // "HIJKLMN"
      makeFrame(kResponse, {0x00, 0x4F, 0x50, 0x51, 0x52, 0x53, 0x54, 0x55}),  // "OPQRSTU"
      makeFrame(kResponse, {0x10, 0x56, 0x57, 0x58, 0x59, 0x5A, 0x30, 0x31}),  // "VWXYZ01"
      makeFrame(kResponse, {0x07, 0x32, 0x33, 0x34, 0x35, 0x00, 0x00, 0x00}),  // "2345", last
  });
}

// --- SDO block upload of the same 32 characters with CRC, block size 127: initiate, start, one
// sub-block of 5 segments, acknowledgement, end, end response. Counted per segment. ----------
const CanFrame kBlockUploadLabel =
    makeFrame(0x600 + kId, {0xA4, 0x06, 0x20, 0x00, 0x7F, 0x00, 0x00, 0x00});
const CanFrame kBlockStart = makeFrame(0x600 + kId, {0xA3, 0, 0, 0, 0, 0, 0, 0});
const CanFrame kBlockAcknowledge = makeFrame(0x600 + kId, {0xA2, 0x05, 0x7F, 0, 0, 0, 0, 0});
const CanFrame kBlockEndResponse = makeFrame(0x600 + kId, {0xA1, 0, 0, 0, 0, 0, 0, 0});

void uploadBlock(BenchNode& node) {
  Node& n = node.node();
  const Microseconds now = node.now();
  n.onFrame(kBlockUploadLabel, now);
  n.onFrame(kBlockStart, now);
  n.process(now);  // segments the transmit queue could not take at once
  n.onFrame(kBlockAcknowledge, now);
  n.onFrame(kBlockEndResponse, now);
}

std::string verifyUploadBlock(BenchNode& node) {
  constexpr uint32_t kResponse = 0x580 + kId;
  return node.expectFrames({
      makeFrame(kResponse, {0xC6, 0x06, 0x20, 0x00, 0x20, 0x00, 0x00, 0x00}),  // CRC, 32 bytes
      makeFrame(kResponse, {0x01, 0x41, 0x42, 0x43, 0x44, 0x45, 0x46, 0x47}),  // "ABCDEFG"
      makeFrame(kResponse, {0x02, 0x48, 0x49, 0x4A, 0x4B, 0x4C, 0x4D, 0x4E}),  // "HIJKLMN"
      makeFrame(kResponse, {0x03, 0x4F, 0x50, 0x51, 0x52, 0x53, 0x54, 0x55}),  // "OPQRSTU"
      makeFrame(kResponse, {0x04, 0x56, 0x57, 0x58, 0x59, 0x5A, 0x30, 0x31}),  // "VWXYZ01"
      makeFrame(kResponse, {0x85, 0x32, 0x33, 0x34, 0x35, 0x00, 0x00, 0x00}),  // "2345", last
      makeFrame(kResponse, {0xCD, 0x07, 0xB2, 0x00, 0x00, 0x00, 0x00, 0x00}),  // 3 unused, CRC
  });
}

// --- RPDO1 (COB-ID 0x201, type 255): 0x2000 = 10000, 0x2004:02 = -10; operational. ----------
const CanFrame kRpdo1 = makeFrame(0x200 + kId, {0x10, 0x27, 0x00, 0x00, 0xF6});

void receiveRpdo(BenchNode& node) {
  node.node().onFrame(kRpdo1, node.now());
}

std::string verifyRpdo(BenchNode& node) {
  const od::ObjectDictionary& dictionary = node.node().dictionary();
  const od::EntryRef offset = dictionary.find(0x2004, 2);
  if (dictionary.readUnsigned(0x2000, 0, 0) != 10000U || !offset.valid() ||
      dictionary.readSigned(offset) != -10) {
    return "RPDO1 did not store 0x2000 = 10000 and 0x2004:02 = -10";
  }
  return node.expectFrames({});
}

// --- SYNC with TPDO1..4 valid, transmission type 1 (every SYNC); operational. TPDO1 and TPDO2
// keep their mappings; TPDO3 maps 0x2000; TPDO4 gets 0x2004:04 (REAL32 gain 1.5). ------------
const CanFrame kSync = makeFrame(0x080, {});

std::string prepareSynchronousTpdos(BenchNode& node) {
  std::string error = node.sdoWriteUnsigned(0x1A03, 1, 0x20040420, 4);
  if (error.empty()) {
    error = node.sdoWriteUnsigned(0x1A03, 0, 1, 1);
  }
  for (uint16_t pdo = 0; pdo < 4U && error.empty(); ++pdo) {
    const auto communication = static_cast<uint16_t>(0x1800U + pdo);
    const uint32_t cobId = 0x180U + 0x100U * pdo + kId;
    error = node.sdoWriteUnsigned(communication, 1, 0x80000000U | cobId, 4);  // invalidate
    if (error.empty()) {
      error = node.sdoWriteUnsigned(communication, 2, 1, 1);  // synchronous, every SYNC
    }
    if (error.empty()) {
      error = node.sdoWriteUnsigned(communication, 1, cobId, 4);  // valid
    }
  }
  return error.empty() ? operational(node) : error;
}

void sync(BenchNode& node) {
  node.node().onFrame(kSync, node.now());
}

std::string verifySync(BenchNode& node) {
  return node.expectFrames({
      makeFrame(0x180 + kId, {0x00, 0x00, 0x00, 0x00, 0xD7, 0x00}),  // uptime 0, 21.5 degrees
      makeFrame(0x280 + kId, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}),  // energy -1
      makeFrame(0x380 + kId, {0xE8, 0x03, 0x00, 0x00}),                          // setpoint
      makeFrame(0x480 + kId, {0x00, 0x00, 0xC0, 0x3F}),                          // gain 1.5f
  });
}

// --- NMT: enter pre-operational, then start, both addressed to node 1. ---------------------
const CanFrame kEnterPreOperational = makeFrame(0x000, {0x80, kId});
const CanFrame kStart = makeFrame(0x000, {0x01, kId});

void nmtPair(BenchNode& node) {
  node.node().onFrame(kEnterPreOperational, node.now());
  node.node().onFrame(kStart, node.now());
}

std::string verifyNmt(BenchNode& node) {
  if (node.node().state() != NmtState::kOperational) {
    return "the node is not operational after pre-operational + start";
  }
  return node.expectFrames({});
}

// --- Heartbeat: 0x1017 = 1 ms, operational; each run advances the clock by 1 ms and calls
// process(), which sends one heartbeat. -----------------------------------------------------
std::string prepareHeartbeat(BenchNode& node) {
  const std::string error = node.sdoWriteUnsigned(0x1017, 0, 1, 2);
  return error.empty() ? operational(node) : error;
}

void heartbeatTick(BenchNode& node) {
  node.advance(1000);
  node.node().process(node.now());
}

std::string verifyHeartbeat(BenchNode& node) {
  return node.expectFrames({makeFrame(0x700 + kId, {0x05})});
}

// --- Idle: process() in operational with nothing scheduled (default PDOs, no heartbeat). ----
void idleProcess(BenchNode& node) {
  node.node().process(node.now());
}

std::string verifyIdle(BenchNode& node) {
  if (node.node().process(node.now()) != kNever) {
    return "process() has something scheduled";
  }
  return node.expectFrames({});
}

const Operation kOperations[] = {
    {"sdo_expedited_upload", "SDO expedited upload (read 0x2000, 4 bytes)", 1, asBooted,
     uploadExpedited, verifyUploadExpedited},
    {"sdo_expedited_download", "SDO expedited download (write 0x2000, 4 bytes)", 1, asBooted,
     downloadExpedited, verifyDownloadExpedited},
    {"sdo_segmented_upload_segment",
     "SDO segmented upload, per segment (0x2006, 32 bytes: (initiate + 5 segments) / 5)", 5,
     prepareLabel, uploadSegmented, verifyUploadSegmented},
    {"sdo_block_upload_segment",
     "SDO block upload, per segment (0x2006, 32 bytes, CRC: whole transfer / 5 segments)", 5,
     prepareLabel, uploadBlock, verifyUploadBlock},
    {"rpdo_reception", "RPDO reception (RPDO1, 5 bytes, type 255)", 1, operational, receiveRpdo,
     verifyRpdo},
    {"sync_4_tpdos", "SYNC in, 4 synchronous TPDOs out", 1, prepareSynchronousTpdos, sync,
     verifySync},
    {"nmt_command", "NMT command (pre-operational and start, alternately)", 2, operational, nmtPair,
     verifyNmt},
    {"heartbeat_tick", "heartbeat tick (operational, process() that sends a heartbeat)", 1,
     prepareHeartbeat, heartbeatTick, verifyHeartbeat},
    {"idle_process", "idle process() (operational, nothing due)", 1, operational, idleProcess,
     verifyIdle},
};

}  // namespace

const Operation* operations(size_t* count) {
  *count = sizeof kOperations / sizeof kOperations[0];
  return kOperations;
}

std::unique_ptr<BenchNode> prepareNode(const Operation& operation, unsigned warmUpRuns,
                                       std::string* error) {
  auto node = std::make_unique<BenchNode>();
  *error = operation.available() ? operation.prepare(*node) : "not available";
  if (error->empty()) {
    node->clearFrames();
    operation.run(*node);
    *error = operation.verify(*node);
  }
  for (unsigned i = 0; error->empty() && i < warmUpRuns; ++i) {
    operation.run(*node);
    node->recycle();
  }
  if (error->empty()) {  // still right after the warm-up
    node->clearFrames();
    operation.run(*node);
    *error = operation.verify(*node);
    node->clearFrames();
  }
  if (!error->empty()) {
    *error = std::string(operation.key) + ": " + *error;
    return nullptr;
  }
  return node;
}

}  // namespace costa::bench
