#include "frame_text.hpp"

#include <cstdio>
#include <sstream>
#include <vector>

namespace costa::host {

std::string formatFrame(const CanFrame& frame) {
  char buffer[64];
  int used = frame.extended
                 ? std::snprintf(buffer, sizeof(buffer), "%08X [%u]", frame.id, frame.dlc)
                 : std::snprintf(buffer, sizeof(buffer), "%03X [%u]", frame.id, frame.dlc);
  std::string text(buffer, static_cast<size_t>(used));
  if (frame.rtr) {
    return text + " RTR";
  }
  for (unsigned i = 0; i < frame.dlc && i < 8U; ++i) {
    used = std::snprintf(buffer, sizeof(buffer), " %02X", frame.data[i]);
    text.append(buffer, static_cast<size_t>(used));
  }
  return text;
}

namespace {

bool parseHex(const std::string& token, uint32_t limit, uint32_t* value) {
  if (token.empty() || token.size() > 8U) {
    return false;
  }
  uint32_t result = 0;
  for (const char c : token) {
    unsigned digit = 0;
    if (c >= '0' && c <= '9') {
      digit = static_cast<unsigned>(c - '0');
    } else if (c >= 'a' && c <= 'f') {
      digit = static_cast<unsigned>(c - 'a' + 10);
    } else if (c >= 'A' && c <= 'F') {
      digit = static_cast<unsigned>(c - 'A' + 10);
    } else {
      return false;
    }
    result = result * 16U + digit;
  }
  if (result > limit) {
    return false;
  }
  *value = result;
  return true;
}

}  // namespace

bool parseFrame(const std::string& text, CanFrame* frame, std::string* error, unsigned* wildcards) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;) {
    tokens.push_back(token);
  }
  if (tokens.size() < 2U) {
    *error = "expected '<id> [<dlc>] <bytes>'";
    return false;
  }
  CanFrame result;
  uint32_t id = 0;
  result.extended = tokens[0].size() > 3U;
  if (!parseHex(tokens[0], result.extended ? 0x1FFFFFFFU : 0x7FFU, &id)) {
    *error = "bad identifier '" + tokens[0] + "'";
    return false;
  }
  result.id = id;
  const std::string& dlcToken = tokens[1];
  if (dlcToken.size() != 3U || dlcToken[0] != '[' || dlcToken[2] != ']' || dlcToken[1] < '0' ||
      dlcToken[1] > '8') {
    *error = "bad length '" + dlcToken + "' (expected [0]..[8])";
    return false;
  }
  result.dlc = static_cast<uint8_t>(dlcToken[1] - '0');
  unsigned mask = 0;
  if (tokens.size() == 3U && tokens[2] == "RTR") {
    result.rtr = true;
  } else {
    if (tokens.size() - 2U != result.dlc) {
      *error = "length [" + std::to_string(result.dlc) + "] but " +
               std::to_string(tokens.size() - 2U) + " data bytes";
      return false;
    }
    for (size_t i = 0; i < result.dlc; ++i) {
      const std::string& byte = tokens[i + 2U];
      uint32_t value = 0;
      if (byte == "xx" || byte == "XX") {
        mask |= 1U << i;
      } else if (byte.size() != 2U || !parseHex(byte, 0xFFU, &value)) {
        *error = "bad data byte '" + byte + "'";
        return false;
      }
      result.data[i] = static_cast<uint8_t>(value);
    }
  }
  *frame = result;
  if (wildcards != nullptr) {
    *wildcards = mask;
  }
  return true;
}

bool matchesFrame(const CanFrame& expected, unsigned wildcards, const CanFrame& actual) {
  if (expected.id != actual.id || expected.extended != actual.extended ||
      expected.rtr != actual.rtr || expected.dlc != actual.dlc) {
    return false;
  }
  if (expected.rtr) {
    return true;
  }
  for (unsigned i = 0; i < expected.dlc; ++i) {
    if ((wildcards & (1U << i)) == 0U && expected.data[i] != actual.data[i]) {
      return false;
    }
  }
  return true;
}

}  // namespace costa::host
