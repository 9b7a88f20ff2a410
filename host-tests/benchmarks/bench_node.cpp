#include "bench_node.hpp"

#include <algorithm>
#include <cstdio>

namespace costa::bench {
namespace {

constexpr uint32_t kSdoRequest = 0x600U + BenchNode::kNodeId;
constexpr uint32_t kSdoResponse = 0x580U + BenchNode::kNodeId;
constexpr size_t kSegmentBytes = 7;

std::string describeFrame(const CanFrame& frame) {
  char text[64];
  int used = std::snprintf(text, sizeof text, "%03X [%u]", static_cast<unsigned>(frame.id),
                           static_cast<unsigned>(frame.dlc));
  for (size_t i = 0; i < frame.dlc && i < 8U && used > 0; ++i) {
    used += std::snprintf(text + used, sizeof text - static_cast<size_t>(used), " %02X",
                          static_cast<unsigned>(frame.data[i]));
  }
  return frame.rtr ? std::string(text) + " RTR" : std::string(text);
}

CanFrame sdoFrame(uint8_t command, uint16_t index, uint8_t subIndex, const uint8_t* payload,
                  size_t length) {
  CanFrame frame =
      makeFrame(kSdoRequest, {command, static_cast<uint8_t>(index & 0xFFU),
                              static_cast<uint8_t>(index >> 8U), subIndex, 0, 0, 0, 0});
  for (size_t i = 0; i < length; ++i) {
    frame.data[4U + i] = payload[i];
  }
  return frame;
}

CanFrame sdoResponse(uint8_t command, uint16_t index, uint8_t subIndex) {
  return makeFrame(kSdoResponse, {command, static_cast<uint8_t>(index & 0xFFU),
                                  static_cast<uint8_t>(index >> 8U), subIndex, 0, 0, 0, 0});
}

}  // namespace

CanFrame makeFrame(uint32_t id, std::initializer_list<uint8_t> bytes) {
  CanFrame frame;
  frame.id = id;
  for (uint8_t byte : bytes) {
    frame.data[frame.dlc++] = byte;
  }
  return frame;
}

BenchNode::BenchNode() : target_(can_, DeviceConfig{kNodeId, true, nullptr, nullptr}) {
  target_.start(now_);
  node().process(now_);
  can_.clear();
}

std::string BenchNode::expectFrames(const std::vector<CanFrame>& expected) const {
  std::string sent;
  for (size_t i = 0; i < can_.count(); ++i) {
    sent += "\n  " + describeFrame(can_.at(i));
  }
  bool same = can_.count() == expected.size();
  for (size_t i = 0; same && i < expected.size(); ++i) {
    same = sameOnWire(can_.at(i), expected[i]);
  }
  if (same) {
    return "";
  }
  std::string wanted;
  for (const CanFrame& frame : expected) {
    wanted += "\n  " + describeFrame(frame);
  }
  return "expected:" + (wanted.empty() ? std::string(" nothing") : wanted) +
         "\nsent:" + (sent.empty() ? std::string(" nothing") : sent);
}

std::string BenchNode::exchange(const CanFrame& request, const CanFrame& response) {
  can_.clear();
  node().onFrame(request, now_);
  node().process(now_);
  const std::string error = expectFrames({response});
  can_.clear();
  return error.empty() ? "" : "after " + describeFrame(request) + ": " + error;
}

std::string BenchNode::sdoDownload(uint16_t index, uint8_t subIndex,
                                   const std::vector<uint8_t>& bytes) {
  const CanFrame done = sdoResponse(0x60, index, subIndex);
  if (bytes.size() <= 4U) {
    const auto unused = static_cast<uint8_t>(4U - bytes.size());
    const auto command = static_cast<uint8_t>(0x23U | (unused << 2U));
    return exchange(sdoFrame(command, index, subIndex, bytes.data(), bytes.size()), done);
  }
  const uint8_t size[4] = {static_cast<uint8_t>(bytes.size() & 0xFFU),
                           static_cast<uint8_t>(bytes.size() >> 8U), 0, 0};
  std::string error = exchange(sdoFrame(0x21, index, subIndex, size, 4), done);
  uint8_t toggle = 0;
  for (size_t offset = 0; error.empty() && offset < bytes.size(); offset += kSegmentBytes) {
    const size_t length = std::min(kSegmentBytes, bytes.size() - offset);
    const bool last = offset + length == bytes.size();
    CanFrame segment = makeFrame(kSdoRequest, {0, 0, 0, 0, 0, 0, 0, 0});
    segment.data[0] =
        static_cast<uint8_t>(toggle | ((kSegmentBytes - length) << 1U) | (last ? 1U : 0U));
    for (size_t i = 0; i < length; ++i) {
      segment.data[1U + i] = bytes[offset + i];
    }
    error = exchange(segment, makeFrame(kSdoResponse, {static_cast<uint8_t>(0x20U | toggle), 0, 0,
                                                       0, 0, 0, 0, 0}));
    toggle ^= 0x10U;
  }
  return error;
}

std::string BenchNode::sdoWriteUnsigned(uint16_t index, uint8_t subIndex, uint32_t value,
                                        size_t size) {
  std::vector<uint8_t> bytes;
  for (size_t i = 0; i < size; ++i) {
    bytes.push_back(static_cast<uint8_t>(value >> (8U * i)));
  }
  return sdoDownload(index, subIndex, bytes);
}

std::string BenchNode::nmt(NmtCommand command, NmtState state) {
  can_.clear();
  node().onFrame(makeFrame(0x000, {static_cast<uint8_t>(command), kNodeId}), now_);
  node().process(now_);
  if (node().state() != state) {
    return "NMT command did not lead to the expected state";
  }
  const std::string error = expectFrames({});
  can_.clear();
  return error;
}

}  // namespace costa::bench
