#include "costa/srdo_configuration.hpp"

#include "costa/crc16.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr uint16_t kLowestId = 0x101;
constexpr uint16_t kHighestId = 0x180;
constexpr size_t kLongestData = 8;

void feed(Crc16& crc, uint32_t value, size_t bytes) noexcept {
  for (size_t i = 0; i < bytes; ++i) {
    crc.update(static_cast<uint8_t>(value >> (8U * i)));
  }
}

bool idAllowed(uint32_t id, bool inverted) noexcept {
  return id >= kLowestId && id <= kHighestId && (id & 1U) == (inverted ? 0U : 1U);
}

/// One mapping entry (index << 16 | sub-index << 8 | bits): an existing entry (0x06020000 /
/// 0x06090011), mappable in `direction` (0x06040041), whole bytes equal to its size (0x06040043).
AbortCode checkSrdoEntry(const od::ObjectDictionary& dictionary, uint32_t entry, uint8_t direction,
                         size_t* size) noexcept {
  if ((entry & 7U) != 0U || entry == 0U) {
    return AbortCode::kParameterIncompatible;
  }
  od::EntryRef ref;
  const AbortCode found =
      dictionary.find(static_cast<uint16_t>(entry >> 16U), static_cast<uint8_t>(entry >> 8U), &ref);
  if (found != AbortCode::kNone) {
    return found;
  }
  const od::Attribute needed = direction == srdo::kReceive ? od::kRpdoMappable : od::kTpdoMappable;
  if (!ref.has(needed)) {
    return AbortCode::kNotMappable;
  }
  if ((entry & 0xFFU) != ref.size() * 8U) {
    return AbortCode::kParameterIncompatible;
  }
  *size = ref.size();
  return AbortCode::kNone;
}

}  // namespace

AbortCode checkSrdoMapping(const od::ObjectDictionary& dictionary, uint16_t mappingIndex,
                           uint8_t count, uint8_t direction, uint8_t* length) noexcept {
  if ((count & 1U) != 0U || count > srdo::kLongestMapping) {
    return AbortCode::kMappingTooLong;
  }
  size_t bytes = 0;
  for (uint8_t sub = 1; sub < count; sub = static_cast<uint8_t>(sub + 2U)) {
    const auto normal = dictionary.readUnsigned32(mappingIndex, sub, 0);
    const auto inverted = dictionary.readUnsigned32(mappingIndex, sub + 1U, 0);
    size_t normalSize = 0;
    size_t invertedSize = 0;
    AbortCode verdict = checkSrdoEntry(dictionary, normal, direction, &normalSize);
    if (verdict == AbortCode::kNone) {
      verdict = checkSrdoEntry(dictionary, inverted, direction, &invertedSize);
    }
    if (verdict != AbortCode::kNone) {
      return verdict;
    }
    if (normalSize != invertedSize) {
      return AbortCode::kParameterIncompatible;  // the inverted data is as long as the normal
    }
    bytes += normalSize;
    if (bytes > kLongestData) {
      return AbortCode::kMappingTooLong;
    }
  }
  *length = static_cast<uint8_t>(bytes);
  return AbortCode::kNone;
}

SrdoCheck readSrdoConfiguration(const od::ObjectDictionary& dictionary, uint8_t number,
                                SrdoConfiguration* out) noexcept {
  const auto communication = static_cast<uint16_t>(srdo::kFirstCommunication + number - 1U);
  const auto mapping = static_cast<uint16_t>(srdo::kFirstMapping + number - 1U);
  SrdoConfiguration& c = *out;
  c = SrdoConfiguration{};
  c.number = number;
  c.direction = static_cast<uint8_t>(dictionary.readUnsigned32(communication, 1, 0));
  c.cycleMs = static_cast<uint16_t>(dictionary.readUnsigned32(communication, 2, 0));
  c.validationMs = static_cast<uint8_t>(dictionary.readUnsigned32(communication, 3, 0));
  const auto type = static_cast<uint8_t>(dictionary.readUnsigned32(communication, 4, 0));
  const auto normalId = dictionary.readUnsigned32(communication, 5, 0);
  const auto invertedId = dictionary.readUnsigned32(communication, 6, 0);
  c.normalId = static_cast<uint16_t>(normalId);
  c.invertedId = static_cast<uint16_t>(invertedId);
  c.mappedCount = static_cast<uint8_t>(dictionary.readUnsigned32(mapping, 0, 0));
  Crc16 crc;
  crc.update(c.direction);
  feed(crc, c.cycleMs, 2);
  crc.update(c.validationMs);
  feed(crc, normalId, 4);
  feed(crc, invertedId, 4);
  crc.update(c.mappedCount);
  for (uint8_t sub = 1; sub <= c.mappedCount && sub <= srdo::kLongestMapping; ++sub) {
    crc.update(sub);
    feed(crc, dictionary.readUnsigned32(mapping, sub, 0), 4);
  }
  c.signature = crc.value();
  if (c.direction == srdo::kNotValid) {
    return SrdoCheck::kNotValid;
  }
  if (c.direction > srdo::kReceive || c.cycleMs == 0U || c.validationMs == 0U ||
      type != srdo::kTransmissionType || !idAllowed(normalId, false) ||
      !idAllowed(invertedId, true)) {
    return SrdoCheck::kParameters;
  }
  if (checkSrdoMapping(dictionary, mapping, c.mappedCount, c.direction, &c.length) !=
          AbortCode::kNone ||
      c.length == 0U) {
    return SrdoCheck::kMapping;
  }
  if (dictionary.readUnsigned32(srdo::kSignatures, number, 0) != c.signature) {
    return SrdoCheck::kSignature;
  }
  return SrdoCheck::kValid;
}

AbortCode checkSrdoWrite(const od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                         const uint8_t* data, size_t length) noexcept {
  const uint16_t index = ref.index();
  const uint8_t sub = ref.subIndex();
  if (length != ref.size() || length > 4U) {
    return AbortCode::kNone;  // the dictionary's own length check answers
  }
  uint32_t value = 0;
  for (size_t i = 0; i < length; ++i) {
    value |= static_cast<uint32_t>(data[i]) << (8U * i);
  }
  if (index >= srdo::kFirstCommunication && index <= srdo::kLastCommunication) {
    const bool bad = (sub == 1U && value > srdo::kReceive) ||
                     ((sub == 2U || sub == 3U) && value == 0U) ||
                     (sub == 4U && value != srdo::kTransmissionType) ||
                     ((sub == 5U || sub == 6U) && !idAllowed(value, sub == 6U));
    return bad ? AbortCode::kInvalidValue : AbortCode::kNone;
  }
  if (index < srdo::kFirstMapping || index > srdo::kLastMapping) {
    return AbortCode::kNone;
  }
  const auto communication =
      static_cast<uint16_t>(index - srdo::kFirstMapping + srdo::kFirstCommunication);
  const auto direction = static_cast<uint8_t>(dictionary.readUnsigned32(communication, 1, 0));
  if (direction != srdo::kNotValid) {
    return AbortCode::kUnsupportedAccess;  // CiA 304: the SRDO is not valid while mapped
  }
  if (sub != 0U) {
    return dictionary.readUnsigned32(index, 0, 0) == 0U ? AbortCode::kNone
                                                        : AbortCode::kCannotStoreState;
  }
  uint8_t bytes = 0;
  // The direction the SRDO will have is not known yet: an entry must be mappable either way.
  const AbortCode transmit =
      checkSrdoMapping(dictionary, index, static_cast<uint8_t>(value), srdo::kTransmit, &bytes);
  const AbortCode receive =
      checkSrdoMapping(dictionary, index, static_cast<uint8_t>(value), srdo::kReceive, &bytes);
  return transmit == AbortCode::kNone ? AbortCode::kNone : receive;
}

}  // namespace costa
