// The fixture of the service tests: dictionary, recording transmitter, clock, frame helpers.
#pragma once

#include <gtest/gtest.h>
#include <stddef.h>
#include <stdint.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "costa/node_clock.hpp"
#include "costa/object_hook.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/port/memory/recording_can.hpp"
#include "costa/time.hpp"
#include "costa/transmit_path.hpp"
#include "service_objects_od.hpp"

namespace costa::test {

/// The node-id of every service under test.
inline constexpr uint8_t kNodeId = 5;

/// A data frame as the stack builds it: `bytes`, then zeros; the DLC is their number.
inline CanFrame frame(uint32_t id, std::initializer_list<uint8_t> bytes) {
  CanFrame result;
  result.id = id;
  for (const uint8_t byte : bytes) {
    if (result.dlc == sizeof(result.data)) {
      ADD_FAILURE() << "a classic CAN frame carries at most 8 bytes";
      break;
    }
    result.data[result.dlc++] = byte;
  }
  return result;
}

/// A frame of DLC 8: `bytes`, then zeros (SDO, LSS and EMCY frames).
inline CanFrame frame8(uint32_t id, std::initializer_list<uint8_t> bytes) {
  CanFrame result = frame(id, bytes);
  result.dlc = 8;
  return result;
}

/// A remote request on `id`.
inline CanFrame remote(uint32_t id, uint8_t dlc = 0) {
  CanFrame result;
  result.id = id;
  result.dlc = dlc;
  result.rtr = true;
  return result;
}

/// `value` in upper-case hexadecimal, at least `digits` digits.
inline std::string hex(uint32_t value, int digits) {
  std::string text;
  for (; digits > 0 || value != 0U; --digits, value >>= 4U) {
    text.insert(text.begin(), "0123456789ABCDEF"[value & 0xFU]);
  }
  return text;
}

/// Everything a frame carries, all eight data bytes included: "705 [1] 7F 00 00 00 00 00 00 00".
inline std::string describe(const CanFrame& canFrame) {
  std::string result = hex(canFrame.id, 3) + " [" + std::to_string(canFrame.dlc) + "]";
  for (const uint8_t byte : canFrame.data) {
    result += " " + hex(byte, 2);
  }
  if (canFrame.rtr) {
    result += " rtr";
  }
  if (canFrame.extended) {
    result += " ext";
  }
  return result;
}

/// The frames as describe() writes them, for comparison with ServiceTest::sent().
inline std::vector<std::string> frames(std::initializer_list<CanFrame> expected) {
  std::vector<std::string> result;
  for (const CanFrame& canFrame : expected) {
    result.push_back(describe(canFrame));
  }
  return result;
}

/// The service dictionary as a node holds it after a reset: defaults, node-id set.
struct ServiceDictionary {
  explicit ServiceDictionary(uint8_t nodeId = kNodeId)
      : dictionary(gen::service_objects::kDefinition, &values) {
    dictionary.setNodeId(nodeId);
    dictionary.restoreDefaults(0x0000, 0xFFFF);
  }
  ServiceDictionary(const ServiceDictionary&) = delete;
  ServiceDictionary& operator=(const ServiceDictionary&) = delete;
  ServiceDictionary(ServiceDictionary&&) = delete;
  ServiceDictionary& operator=(ServiceDictionary&&) = delete;
  ~ServiceDictionary() = default;

  gen::service_objects::Values values{};
  od::ObjectDictionary dictionary;
};

/// One service's surroundings: the dictionary, the transmit path to a recording controller,
/// and the node's clock at kStart.
class ServiceTest : public ::testing::Test {
 protected:
  static constexpr size_t kQueueDepth = 4;
  /// Where the clock starts: one second before the 32-bit microsecond count wraps, so that
  /// every test longer than a second crosses the wrap.
  static constexpr Microseconds kStart = kNever - 1000000U + 1U;

  ServiceTest() : tx_(can_, slots_, kQueueDepth) { clock_.start(kStart); }

  /// `offset` µs after kStart (modulo 2^32).
  static constexpr Microseconds after(uint32_t offset) { return kStart + offset; }
  static constexpr Microseconds afterMs(uint32_t ms) {
    return kStart + millisecondsToMicroseconds(ms);
  }

  /// The frames the controller took since the last call, described; they count as read then.
  std::vector<std::string> sent() {
    std::vector<std::string> result;
    for (; read_ < can_.count(); ++read_) {
      result.push_back(describe(can_.at(read_)));
    }
    return result;
  }

  /// The located entry (index, sub-index); fails the test when there is none.
  od::EntryRef entry(uint16_t index, uint8_t subIndex) const {
    const od::EntryRef ref = od_.dictionary.find(index, subIndex);
    EXPECT_TRUE(ref.valid()) << std::hex << index << ":" << unsigned{subIndex};
    return ref;
  }
  uint64_t value(uint16_t index, uint8_t subIndex) const {
    return od_.dictionary.readUnsigned(index, subIndex, ~uint64_t{0});
  }
  /// Writes `length` bytes of `number` (little-endian) through `hook`, as a remote write
  /// (SDO, RPDO) reaches the service that owns the entry.
  AbortCode write(ObjectHook& hook, uint16_t index, uint8_t subIndex, uint64_t number,
                  size_t length) {
    uint8_t bytes[8] = {};
    for (size_t i = 0; i < length && i < sizeof(bytes); ++i) {
      bytes[i] = static_cast<uint8_t>(number >> (8U * i));
    }
    return hook.write(od_.dictionary, entry(index, subIndex), bytes, length);
  }
  /// Stores a value directly, as the application does (no hook, no check).
  void store(uint16_t index, uint8_t subIndex, uint64_t number) {
    EXPECT_TRUE(od_.dictionary.storeUnsigned(index, subIndex, number));
  }

  ServiceDictionary od_;
  od::ObjectDictionary& dictionary_ = od_.dictionary;
  port::RecordingCan can_;
  QueuedFrame slots_[kQueueDepth];
  TransmitPath tx_;
  NodeClock clock_;

 private:
  size_t read_ = 0;
};

}  // namespace costa::test
