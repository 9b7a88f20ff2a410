#include "lss_master.hpp"

namespace costa::test {

bool LssMaster::request(const uint8_t (&data)[8], CanFrame* answer) {
  CanFrame frame;
  frame.id = 0x7E5;
  frame.dlc = 8;
  for (int i = 0; i < 8; ++i) {
    frame.data[i] = data[i];
  }
  ++requests_;
  link_.send(frame);
  return answer != nullptr && link_.receive(answer);
}

bool LssMaster::probe(uint32_t id, uint8_t bitChecked, uint8_t sub, uint8_t next) {
  const uint8_t data[8] = {0x51,
                           static_cast<uint8_t>(id),
                           static_cast<uint8_t>(id >> 8U),
                           static_cast<uint8_t>(id >> 16U),
                           static_cast<uint8_t>(id >> 24U),
                           bitChecked,
                           sub,
                           next};
  CanFrame answer;
  const bool answered = request(data, &answer) && answer.data[0] == 0x4F;
  if (answered) {
    link_.discardAnswers();  // several slaves may answer at once on a real bus
  }
  return answered;
}

bool LssMaster::fastscan(LssIdentity* found) {
  if (!probe(0, 0x80, 0, 0)) {
    return false;
  }
  uint32_t values[4] = {};
  for (uint8_t sub = 0; sub < 4U; ++sub) {
    uint32_t id = 0;
    for (int bit = 31; bit >= 0; --bit) {
      if (!probe(id, static_cast<uint8_t>(bit), sub, sub)) {
        id |= uint32_t{1U} << static_cast<unsigned>(bit);
      }
    }
    const uint8_t next = static_cast<uint8_t>((sub + 1U) % 4U);
    if (!probe(id, 0, sub, next)) {
      return false;
    }
    values[sub] = id;
  }
  *found = LssIdentity{values[0], values[1], values[2], values[3]};
  return true;
}

void LssMaster::switchGlobal(bool configuration) {
  const uint8_t data[8] = {0x04, static_cast<uint8_t>(configuration ? 1 : 0)};
  request(data, nullptr);
}

bool LssMaster::switchSelective(const LssIdentity& identity) {
  const uint32_t values[4] = {identity.vendorId, identity.productCode, identity.revisionNumber,
                              identity.serialNumber};
  CanFrame answer;
  bool answered = false;
  for (uint8_t i = 0; i < 4U; ++i) {
    const uint8_t data[8] = {static_cast<uint8_t>(0x40 + i), static_cast<uint8_t>(values[i]),
                             static_cast<uint8_t>(values[i] >> 8U),
                             static_cast<uint8_t>(values[i] >> 16U),
                             static_cast<uint8_t>(values[i] >> 24U)};
    answered = request(data, i == 3U ? &answer : nullptr);
  }
  return answered && answer.data[0] == 0x44;
}

int LssMaster::configureNodeId(uint8_t nodeId) {
  const uint8_t data[8] = {0x11, nodeId};
  CanFrame answer;
  return request(data, &answer) && answer.data[0] == 0x11 ? answer.data[1] : -1;
}

int LssMaster::configureBitTiming(uint8_t tableIndex) {
  const uint8_t data[8] = {0x13, 0, tableIndex};
  CanFrame answer;
  return request(data, &answer) && answer.data[0] == 0x13 ? answer.data[1] : -1;
}

int LssMaster::storeConfiguration() {
  const uint8_t data[8] = {0x17};
  CanFrame answer;
  return request(data, &answer) && answer.data[0] == 0x17 ? answer.data[1] : -1;
}

void LssMaster::activateBitTiming(uint16_t delayMs) {
  const uint8_t data[8] = {0x15, static_cast<uint8_t>(delayMs),
                           static_cast<uint8_t>(delayMs >> 8U)};
  request(data, nullptr);
}

bool LssMaster::inquire(uint8_t command, uint32_t* value) {
  const uint8_t data[8] = {command};
  CanFrame answer;
  if (!request(data, &answer) || answer.data[0] != command) {
    return false;
  }
  *value = command == 0x5E ? answer.data[1]
                           : static_cast<uint32_t>(answer.data[1]) |
                                 static_cast<uint32_t>(answer.data[2]) << 8U |
                                 static_cast<uint32_t>(answer.data[3]) << 16U |
                                 static_cast<uint32_t>(answer.data[4]) << 24U;
  return true;
}

}  // namespace costa::test
