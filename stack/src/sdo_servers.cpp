#include "costa/sdo_servers.hpp"

#include <new>

#include "costa/cob_ids.hpp"
#include "costa/od/little_endian.hpp"

namespace costa {
namespace {

constexpr uint32_t kNotValid = 0x80000000U;
constexpr uint32_t kExtended = 0x20000000U;
constexpr uint32_t kReserved = 0x1FFFF800U;
constexpr uint32_t kCanIdBits = 0x7FFFFFFFU;  ///< bits 0..30: what may not change while valid
constexpr uint32_t kCanIdMask = 0x7FFU;
constexpr uint8_t kRequestSub = 1;
constexpr uint8_t kResponseSub = 2;
constexpr uint8_t kClientSub = 3;

bool serves(uint32_t request, uint32_t response) noexcept {
  return ((request | response) & (kNotValid | kExtended | kReserved)) == 0U;
}

}  // namespace

SdoServers::SdoServers(ObjectAccess& access, TransmitPath& tx, const SdoProfile& profile,
                       NodeClock& clock, SdoServerSlot* slots, uint8_t* buffers, size_t bufferSize,
                       size_t count, Microseconds timeout, FrameRouter& routes) noexcept
    : slots_(slots), count_(count), routes_(routes) {
  for (size_t i = 0; i < count_; ++i) {
    // NOLINTNEXTLINE(cppcoreguidelines-owning-memory): placement in the caller's slot, no heap
    slots_[i].server = new (slots_[i].bytes)
        SdoServer(access, tx, profile, clock, buffers + i * bufferSize, bufferSize, timeout);
    slots_[i].request = kNotValid;
    slots_[i].response = kNotValid;
  }
}

SdoServers::~SdoServers() noexcept {
  for (size_t i = 0; i < count_; ++i) {
    at(i).~SdoServer();
  }
}

void SdoServers::addRoutes(const od::ObjectDictionary& dictionary, FrameRouter& router) noexcept {
  size_t server = 0;
  for (uint16_t index = kFirst; index <= kLast && server < count_; ++index) {
    if (dictionary.findObject(index) == nullptr) {
      continue;
    }
    SdoServerSlot& slot = slots_[server];
    const uint32_t request = dictionary.readUnsigned32(index, kRequestSub, kNotValid);
    const uint32_t response = dictionary.readUnsigned32(index, kResponseSub, kNotValid);
    if (request != slot.request || response != slot.response) {
      at(server).reset();  // a new channel: what ran on the old one ends
      at(server).setResponseCanId(static_cast<uint16_t>(response & kCanIdMask));
      slot.request = request;
      slot.response = response;
    }
    if (serves(request, response)) {
      (void)router.add(static_cast<uint16_t>(request & kCanIdMask), Route::kSdoServer,
                       static_cast<uint8_t>(server));
    }
    ++server;
  }
}

void SdoServers::process(Microseconds now) noexcept {
  for (size_t i = 0; i < count_; ++i) {
    at(i).process(now);
  }
}

Microseconds SdoServers::nextDeadline() const noexcept {
  Microseconds next = kNever;
  for (size_t i = 0; i < count_; ++i) {
    next = earliest(next, at(i).nextDeadline());
  }
  return next;
}

void SdoServers::reset() noexcept {
  for (size_t i = 0; i < count_; ++i) {
    at(i).reset();
  }
}

bool SdoServers::valid() const noexcept {
  for (size_t i = 0; i < count_; ++i) {
    if (!at(i).valid()) {
      return false;
    }
  }
  return true;
}

AbortCode SdoServers::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                            const uint8_t* data, size_t length) noexcept {
  const uint8_t sub = ref.subIndex();
  const bool cobId = sub == kRequestSub || sub == kResponseSub;
  if (cobId && length == 4U) {
    const uint32_t value = loadU32(data);
    if ((value & (kExtended | kReserved)) != 0U) {
      return AbortCode::kInvalidValue;  // 11-bit CAN-IDs only
    }
    const uint32_t current = dictionary.readUnsigned32(ref.index(), sub, 0);
    const bool valid = (value & kNotValid) == 0U;
    if (valid && (current & kNotValid) == 0U && (value & kCanIdBits) != (current & kCanIdBits)) {
      return AbortCode::kInvalidValue;  // invalidate before changing the CAN-ID
    }
    if (valid && cob::isRestrictedCanId(value & kCanIdMask)) {
      return AbortCode::kInvalidValue;  // CiA 301 7.3.5
    }
  }
  if (sub == kClientSub && length == 1U && !cob::isValidNodeId(data[0])) {
    return data[0] == 0U ? AbortCode::kValueTooLow : AbortCode::kValueTooHigh;
  }
  const AbortCode written = dictionary.write(ref, data, length);
  if (written == AbortCode::kNone && cobId) {
    routes_.invalidate();
  }
  return written;
}

}  // namespace costa
