#include "costa/pdo_channel.hpp"

namespace costa {

bool PdoChannel::readCommunication(const PdoContext& context) noexcept {
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  const uint32_t value = dictionary.readUnsigned32(index_, 1, 0x80000000U);
  const PdoCobId cob = decodePdoCobId(value, context.profile.cobIdPolarity);
  valid_ = cob.valid && !cob.extended;
  canId_ = static_cast<uint16_t>(value & 0x7FFU);
  type_ = static_cast<uint8_t>(dictionary.readUnsigned32(index_, 2, 255));
  eventTimerMs_ = static_cast<uint16_t>(dictionary.readUnsigned32(index_, 5, 0));
  return cob.rtrAllowed;
}

namespace {

// The mapping values the mapping object at `mappingIndex` holds into `values`, `*count` of them
// (see resolvePdoMapping); the refusal of a `written` count, or kNone.
AbortCode readMappingObject(const od::ObjectDictionary& dictionary, const od::Object& object,
                            uint16_t mappingIndex, size_t written, uint32_t* values,
                            size_t* count) noexcept {
  size_t entries = written;
  if (written == kMappedCount) {
    entries = static_cast<size_t>(dictionary.readUnsigned32(mappingIndex, 0, 0));
    if (entries > PdoMap::kMaxEntries) {
      entries = PdoMap::kMaxEntries;
    }
  } else if (written > PdoMap::kMaxEntries || written >= dictionary.entryCount(object)) {
    return AbortCode::kMappingTooLong;
  }
  for (size_t i = 0; i < entries; ++i) {
    values[i] = dictionary.readUnsigned32(mappingIndex, static_cast<uint8_t>(i + 1U), 0);
    if (written != kMappedCount && values[i] == 0U) {
      return AbortCode::kParameterIncompatible;  // an enabled entry must map something
    }
  }
  *count = entries;
  return AbortCode::kNone;
}

}  // namespace

AbortCode resolvePdoMapping(PdoContext& context, uint16_t communicationIndex, PdoMap* map,
                            size_t written) noexcept {
  const od::ObjectDictionary& dictionary = context.access.dictionary();
  uint32_t read[PdoMap::kMaxEntries];
  const uint32_t* values = read;
  size_t count = 0;
  const auto mappingIndex = static_cast<uint16_t>(communicationIndex + 0x200U);
  const od::Object* object = dictionary.findObject(mappingIndex);
  if (object != nullptr) {
    const AbortCode refused =
        readMappingObject(dictionary, *object, mappingIndex, written, read, &count);
    if (refused != AbortCode::kNone) {
      return refused;
    }
  } else {
    const StaticPdoMappings& fixed = context.profile.staticMappings;
    for (size_t i = 0; i < fixed.count; ++i) {
      const StaticPdoMapping& mapping = fixed.mappings[i];
      if (mapping.communicationIndex == communicationIndex) {
        values = mapping.entries;
        count = mapping.count < PdoMap::kMaxEntries ? mapping.count : PdoMap::kMaxEntries;
        break;
      }
    }
  }
  const PdoDirection direction =
      communicationIndex < 0x1800U ? PdoDirection::kReceive : PdoDirection::kTransmit;
  return map->resolve(context.access, values, count, direction);
}

}  // namespace costa
