#include "frame_trace.hpp"

#include <cstdio>
#include <cstring>

#include "costa/od/little_endian.hpp"

namespace costa::host {
namespace {

std::string hex(uint64_t value, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "0x%0*llX", digits, static_cast<unsigned long long>(value));
  return buffer;
}

std::string quoted(const uint8_t* data, size_t length) {
  std::string text = "\"";
  for (size_t i = 0; i < length; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c >= 0x20 && c < 0x7F && c != '"' && c != '\\') {
      text += c;
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\x%02X", data[i]);
      text += buffer;
    }
  }
  return text + "\"";
}

std::string bytes(const uint8_t* data, size_t length) {
  std::string text;
  for (size_t i = 0; i < length; ++i) {
    char buffer[8];
    std::snprintf(buffer, sizeof(buffer), i == 0 ? "%02X" : " %02X", data[i]);
    text += buffer;
  }
  return text;
}

const char* stateName(uint8_t value) {
  switch (value & 0x7FU) {
    case 0x00: return "boot-up";
    case 0x04: return "stopped";
    case 0x05: return "operational";
    case 0x7F: return "pre-operational";
    default: return "unknown state";
  }
}

}  // namespace

FrameTracer::FrameTracer(const od::ObjectDictionary* dictionary, const od::NameTable* names,
                         const DeviceProfile& profile)
    : dictionary_(dictionary), names_(names), profile_(profile) {}

std::string FrameTracer::nameOf(uint16_t index, uint8_t subIndex) const {
  if (names_ == nullptr) {
    return "";
  }
  for (uint32_t i = 0; i < names_->count; ++i) {
    const od::EntryName& row = names_->names[i];
    if (row.index == index && row.subIndex == subIndex) {
      return row.name;
    }
  }
  return "";
}

std::string FrameTracer::entryText(uint16_t index, uint8_t subIndex) const {
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "0x%04X:%02X", index, subIndex);
  return buffer;
}

std::string FrameTracer::formatValue(uint16_t index, uint8_t subIndex, const uint8_t* data,
                                     size_t length, bool local) const {
  const od::EntryRef ref =
      (local && dictionary_ != nullptr) ? dictionary_->find(index, subIndex) : od::EntryRef{};
  if (!ref.valid()) {
    return bytes(data, length);
  }
  const od::DataType type = ref.type();
  const size_t size = ref.size();
  if (type == od::DataType::kVisibleString) {
    return quoted(data, length);
  }
  if (!od::isNumeric(type) || length < size) {
    return bytes(data, length);
  }
  const uint64_t raw = loadLittleEndian(data, size);
  char buffer[64];
  if (od::isSigned(type)) {
    std::snprintf(buffer, sizeof(buffer), "%lld", static_cast<long long>(signExtend(raw, size)));
  } else if (type == od::DataType::kReal32) {
    float value = 0.0F;
    const auto bits = static_cast<uint32_t>(raw);
    std::memcpy(&value, &bits, 4);
    std::snprintf(buffer, sizeof(buffer), "%g", static_cast<double>(value));
  } else if (type == od::DataType::kReal64) {
    double value = 0.0;
    std::memcpy(&value, &raw, 8);
    std::snprintf(buffer, sizeof(buffer), "%g", value);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%llu (%s)", static_cast<unsigned long long>(raw),
                  hex(raw, static_cast<int>(size * 2U)).c_str());
  }
  return buffer;
}

std::string FrameTracer::describe(const CanFrame& frame, uint8_t localNodeId) {
  if (frame.extended) {
    return "29-bit frame (not CANopen)";
  }
  const uint32_t id = frame.id;
  if (id == 0x000) {
    return describeNmt(frame);
  }
  if (id == 0x080) {
    return frame.dlc >= 1U ? "SYNC counter " + std::to_string(frame.data[0]) : "SYNC";
  }
  if (id > 0x080 && id <= 0x0FF) {
    return describeEmcy(frame, id - 0x080U == localNodeId);
  }
  const uint32_t timeCob = dictionary_ != nullptr
                               ? static_cast<uint32_t>(dictionary_->readUnsigned(0x1012, 0, 0x100))
                               : 0x100U;
  if (id == (timeCob & 0x7FFU) && !frame.rtr) {
    return describeTime(frame);
  }
  if (id >= 0x180 && id <= 0x57F) {
    return frame.rtr ? "PDO request (RTR)" : "PDO";
  }
  if (id > 0x580 && id <= 0x5FF) {
    return describeSdoResponse(frame, id - 0x580U == localNodeId);
  }
  if (id > 0x600 && id <= 0x67F) {
    return describeSdoRequest(frame, id - 0x600U == localNodeId);
  }
  if (id > 0x700 && id <= 0x77F) {
    return describeErrorControl(frame, id - 0x700U == localNodeId);
  }
  if (id == 0x7E5 || id == 0x7E4) {
    return describeLss(frame, id == 0x7E5);
  }
  return "";
}

std::string FrameTracer::describeTime(const CanFrame& frame) {
  const uint32_t milliseconds = loadLittleEndian(frame.data, 4) & 0x0FFFFFFFU;
  if (frame.dlc != 6U || milliseconds >= 86400000U) {
    return "TIME (malformed, ignored)";
  }
  // Days since 1984-01-01 as a date (the Gregorian calendar, leap years by the 400-year rule).
  auto days = static_cast<uint32_t>(loadLittleEndian(frame.data + 4, 2));
  const uint32_t dayNumber = days;
  unsigned year = 1984;
  const auto yearLength = [](unsigned y) {
    return (y % 4U == 0U && y % 100U != 0U) || y % 400U == 0U ? 366U : 365U;
  };
  while (days >= yearLength(year)) {
    days -= yearLength(year);
    ++year;
  }
  const unsigned monthLengths[12] = {
      31, yearLength(year) == 366U ? 29U : 28U, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  unsigned month = 0;
  while (days >= monthLengths[month]) {
    days -= monthLengths[month];
    ++month;
  }
  char text[80];
  std::snprintf(text, sizeof(text), "TIME %04u-%02u-%02u %02u:%02u:%02u.%03u (day %u)", year,
                month + 1U, days + 1U, milliseconds / 3600000U, milliseconds / 60000U % 60U,
                milliseconds / 1000U % 60U, milliseconds % 1000U, dayNumber);
  return text;
}

std::string FrameTracer::describeNmt(const CanFrame& frame) const {
  if (frame.dlc != 2U) {
    return "NMT (malformed, ignored)";
  }
  const std::string target =
      frame.data[1] == 0U ? "all nodes" : "node " + std::to_string(frame.data[1]);
  switch (frame.data[0]) {
    case 0x01: return "NMT start " + target;
    case 0x02: return "NMT stop " + target;
    case 0x80: return "NMT enter pre-operational " + target;
    case 0x81: return "NMT reset node " + target;
    case 0x82: return "NMT reset communication " + target;
    default: return "NMT unknown command " + hex(frame.data[0], 2);
  }
}

std::string FrameTracer::describeEmcy(const CanFrame& frame, bool local) const {
  std::string text = "EMCY node " + std::to_string(frame.id - 0x080U);
  if (local && profile_.emcy.layout == EmcyLayout::kErrorRegisterInFourthByte) {
    // 00 00 00 ER 00 00 00 00: no error code; the register alone.
    if (frame.dlc >= 4U) {
      text += " register " + hex(frame.data[3], 2);
    }
    bool other = false;  // a byte besides the register that is not zero
    for (size_t i = 0; i < frame.dlc; ++i) {
      other = other || (i != 3U && frame.data[i] != 0U);
    }
    if (frame.dlc < 4U || other) {
      text += " data " + bytes(frame.data, frame.dlc);
    }
    return text;
  }
  if (frame.dlc >= 3U) {
    text += " code " + hex(loadU16(frame.data), 4) + " register " + hex(frame.data[2], 2);
  }
  if (frame.dlc > 3U) {
    text += " data " + bytes(frame.data + 3, frame.dlc - 3U);
  }
  return text;
}

std::string FrameTracer::describeErrorControl(const CanFrame& frame, bool local) {
  const uint32_t node = frame.id - 0x700U;
  if (frame.rtr) {
    guardRequested_[node] = 1;
    return "node guard request";
  }
  if (frame.dlc != 1U) {
    return "error control (malformed)";
  }
  if (guardRequested_[node] != 0U) {
    guardRequested_[node] = 0;
    return std::string("node guard reply ") + stateName(frame.data[0]) + " toggle " +
           ((frame.data[0] & 0x80U) != 0U ? "1" : "0");
  }
  if (frame.data[0] == 0U) {
    return "boot-up";
  }
  const uint8_t whileError = profile_.errorControl.heartbeatWhileError;
  if (local && whileError != 0U && frame.data[0] == whileError) {
    return "heartbeat: an error is active (the device's byte; NMT state unchanged)";
  }
  return std::string("heartbeat ") + stateName(frame.data[0]);
}

}  // namespace costa::host
