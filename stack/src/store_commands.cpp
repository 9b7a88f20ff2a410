#include "costa/store_commands.hpp"

#include "costa/od/little_endian.hpp"

namespace costa {

uint32_t StoreCommands::groupsOf(uint16_t index, uint8_t subIndex) const noexcept {
  uint32_t groups = 0;
  if (subIndex == 1U) {
    groups = index == kStoreIndex ? saveAll_ : restoreAll_;
  } else if (subIndex == 2U) {
    groups = groupBit(od::kGroupCommunication);
  } else if (subIndex == 3U) {
    groups = groupBit(od::kGroupApplication);
  } else if (subIndex >= 4U) {
    groups = groupBit(subIndex);
  }
  uint32_t present = 0;
  for (uint8_t group = 1; group < 32U && store_ != nullptr; ++group) {
    if ((groups & groupBit(group)) != 0U && store_->hasGroup(group)) {
      present |= groupBit(group);
    }
  }
  return present;
}

AbortCode StoreCommands::prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                     const ReadRequest& request) noexcept {
  (void)request;
  if (ref.subIndex() != 0U) {
    const bool able =
        store_ != nullptr && store_->isLaidOut() && groupsOf(ref.index(), ref.subIndex()) != 0U;
    const bool autonomous = savesOnWrite_ && ref.index() == kStoreIndex;
    dictionary.storeUnsigned32(ref, !able ? 0U : autonomous ? 3U : 1U);
  }
  return AbortCode::kNone;
}

AbortCode StoreCommands::write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                               const uint8_t* data, size_t length) noexcept {
  (void)dictionary;
  if (ref.subIndex() == 0U) {
    return AbortCode::kWriteOfReadOnly;
  }
  const bool store = ref.index() == kStoreIndex;
  if (length != 4U || loadU32(data) != (store ? kSaveSignature : kLoadSignature)) {
    return AbortCode::kCannotStore;
  }
  const uint32_t groups = groupsOf(ref.index(), ref.subIndex());
  if (groups == 0U || store_ == nullptr || !store_->isLaidOut()) {
    return AbortCode::kCannotStore;
  }
  const StoreResult result = store ? store_->saveGroups(groups) : store_->invalidateGroups(groups);
  if (result != StoreResult::kOk) {
    return AbortCode::kCannotStore;
  }
  if (!store && ref.subIndex() == 1U && listener_ != nullptr && !listener_->onRestoreAll()) {
    return AbortCode::kCannotStore;
  }
  return AbortCode::kNone;
}

}  // namespace costa
