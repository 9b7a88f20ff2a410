#include "fuzz_dictionary.hpp"

#include <stdio.h>
#include <string.h>

#include <initializer_list>
#include <sstream>
#include <vector>

#include "costa/lss_protocol.hpp"
#include "costa/od/entry_ref.hpp"
#include "costa/od/object_dictionary.hpp"

namespace costa::fuzz {
namespace {

constexpr uint8_t kOwnSdo = 0xC0;
constexpr uint8_t kUpload = 0x40;
constexpr uint8_t kSegmentedDownload = 0x21;  // size indicated
constexpr uint8_t kBlockUpload = 0xA4;        // with CRC
constexpr uint8_t kFrameDlc2 = 0x02;
constexpr uint8_t kFrameDlc8 = 0x08;
constexpr uint8_t kSimulate = 0x89;
constexpr uint8_t kLongCommand = 16;

/// Expedited download command with the size indicated, for 1..4 bytes; 0 for other sizes.
uint8_t expeditedDownload(size_t size) {
  return size >= 1U && size <= 4U ? static_cast<uint8_t>(0x23U | ((4U - size) << 2U)) : 0U;
}

void token(std::string* out, const uint8_t* bytes, size_t count) {
  *out += '"';
  char text[8];
  for (size_t i = 0; i < count; ++i) {
    snprintf(text, sizeof(text), "\\x%02X", static_cast<unsigned>(bytes[i]));
    *out += text;
  }
  *out += "\"\n";
}

void token(std::string* out, std::initializer_list<uint8_t> bytes) {
  token(out, bytes.begin(), bytes.size());
}

/// The default of a numeric RAM entry of up to 4 bytes (without the node-id of $NODEID).
uint32_t defaultValue(const od::Definition& definition, const od::EntryRef& entry) {
  uint8_t bytes[8] = {};
  od::copyDefault(definition, entry, bytes);
  uint32_t value = 0;
  switch (entry.size()) {
    case 1: value = bytes[0]; break;
    case 2: {
      uint16_t half = 0;
      memcpy(&half, bytes, sizeof(half));
      value = half;
      break;
    }
    case 4: memcpy(&value, bytes, sizeof(value)); break;
    default: break;
  }
  return value;
}

/// Whole expedited downloads of `entry` to the node's own server with values worth trying: 0,
/// its default, its limits, and for 32-bit entries the default with bit 31 or 30 set (the
/// "not valid" and RTR / SYNC producer bits of COB-IDs).
void valueTokens(std::string* out, const od::Definition& definition, const od::EntryRef& entry) {
  const uint8_t command = expeditedDownload(entry.size());
  if (command == 0U || !entry.has(od::kWritable) || entry.inRom() || !od::isNumeric(entry.type())) {
    return;
  }
  uint32_t values[6] = {0, defaultValue(definition, entry)};
  size_t count = 2;
  if (entry.row->limits != 0U && !od::isReal(entry.type())) {
    const od::Limits& limits = definition.limits[entry.row->limits - 1U];
    values[count++] = static_cast<uint32_t>(limits.low);
    values[count++] = static_cast<uint32_t>(limits.high);
  }
  if (entry.size() == 4U) {
    values[count++] = values[1] | 0x80000000U;
    values[count++] = values[1] | 0x40000000U;
  }
  for (size_t i = 0; i < count; ++i) {
    uint8_t bytes[9] = {kOwnSdo, command, static_cast<uint8_t>(entry.index()),
                        static_cast<uint8_t>(entry.index() >> 8U), entry.subIndex()};
    for (size_t b = 0; b < 4U; ++b) {
      bytes[5U + b] = static_cast<uint8_t>(values[i] >> (8U * b));
    }
    token(out, bytes, sizeof(bytes));
  }
}

/// The words of `text`, separated by spaces.
std::vector<std::string> wordsOf(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream stream(text);
  for (std::string word; stream >> word;) {
    words.push_back(word);
  }
  return words;
}

/// A word of a simulation command: alone, as a whole command, and starting a longer one.
void commandTokens(std::string* out, const std::string& word) {
  const auto* bytes = reinterpret_cast<const uint8_t*>(word.data());
  token(out, bytes, word.size());
  std::vector<uint8_t> command = {kSimulate, static_cast<uint8_t>(word.size())};
  command.insert(command.end(), bytes, bytes + word.size());
  token(out, command.data(), command.size());
  command[1] = kLongCommand;
  command.push_back(' ');
  token(out, command.data(), command.size());
}

}  // namespace

std::string fuzzDictionary(const od::Definition& definition, const std::string& controlWords) {
  std::string out = "# Costa fuzz dictionary for " + std::string(definition.deviceName) + "\n";
  for (const od::EntryRef& entry : od::Entries(definition)) {
    const auto low = static_cast<uint8_t>(entry.index());
    const auto high = static_cast<uint8_t>(entry.index() >> 8U);
    const uint8_t sub = entry.subIndex();
    const uint8_t download = expeditedDownload(entry.size());
    token(&out, {kOwnSdo, kUpload, low, high, sub});
    if (download == 0U) {  // segmented, block: DOMAINs, strings, 64-bit values
      token(&out, {kOwnSdo, kSegmentedDownload, low, high, sub});
      token(&out, {kOwnSdo, kBlockUpload, low, high, sub, 0x7F});
    }
    valueTokens(&out, definition, entry);
  }
  for (const uint8_t command :
       {uint8_t{0x01}, uint8_t{0x02}, uint8_t{0x80}, uint8_t{0x81}, uint8_t{0x82}}) {
    token(&out, {kFrameDlc2, 0x00, 0x00, command, 0x00});  // NMT, all nodes
  }
  token(&out, {0x00, 0x80, 0x00});  // SYNC
  token(&out, {0x01, 0x80, 0x00});  // SYNC with a counter
  for (uint8_t cs :
       {lss::kSwitchStateGlobal, lss::kSwitchSelectiveVendor, lss::kSwitchSelectiveProduct,
        lss::kSwitchSelectiveRevision, lss::kSwitchSelectiveSerial, lss::kConfigureNodeId,
        lss::kConfigureBitTiming, lss::kActivateBitTiming, lss::kStoreConfiguration,
        lss::kInquireVendor, lss::kInquireNodeId, lss::kIdentifyVendor, lss::kIdentifySerialHigh,
        lss::kIdentifyNonConfigured, lss::kFastscan}) {
    token(&out, {kFrameDlc8, 0xE5, 0x07, cs});
  }
  token(&out, {0x73, 0x61, 0x76, 0x65});  // "save"
  token(&out, {0x6C, 0x6F, 0x61, 0x64});  // "load"
  for (const std::string& word : wordsOf(controlWords)) {
    if (word.size() < kLongCommand) {
      commandTokens(&out, word);
    }
  }
  return out;
}

}  // namespace costa::fuzz
