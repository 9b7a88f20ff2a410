// The node's stored parameters (built with parameter storage only: features::kParameterStorage).
#include "costa/stored_parameters.hpp"

namespace costa {
namespace {

bool damaged(StoreResult result) noexcept {
  return result == StoreResult::kCorrupt || result == StoreResult::kIncompatible ||
         result == StoreResult::kMediumError;
}

}  // namespace

StoredParameters::StoredParameters(od::ObjectDictionary& dictionary, const NodeSettings& settings,
                                   const NodeListeners& listeners) noexcept
    : settings_(settings),
      listeners_(listeners),
      store_(dictionary, settings.storage != nullptr ? *settings.storage : noStorage_,
             settings.storageSlotAlignment),
      commands_(settings.storage != nullptr ? &store_ : nullptr, settings.storeAllGroups,
                settings.restoreAllGroups, settings.saveParametersOnWrite) {
  commands_.setRestoreAllListener(this);
}

void StoredParameters::layOut() noexcept {
  if (settings_.storage != nullptr) {
    // Refused only when laid out again (the record is there already): nothing to do then.
    (void)store_.reserveRecord(kLssRecord, kLssRecordLength);
    ready_ = store_.layOut();
  }
}

ParameterStore* StoredParameters::store() noexcept {
  return ready_ ? &store_ : nullptr;
}

void StoredParameters::remember(uint8_t group, StoreResult result) noexcept {
  if (invalidCount_ < sizeof(invalid_) / sizeof(invalid_[0])) {
    invalid_[invalidCount_++] = Invalid{group, result};
  }
}

void StoredParameters::loadLssConfiguration(bool powerOn, uint8_t* nodeId,
                                            LssBitTiming* timing) noexcept {
  *nodeId = settings_.nodeId;
  *timing = settings_.bitTiming;
  if (!ready_) {
    return;
  }
  uint8_t record[kLssRecordLength] = {};
  size_t length = 0;
  const StoreResult result = store_.loadRecord(kLssRecord, record, sizeof(record), &length);
  if (result == StoreResult::kOk && length == sizeof(record)) {
    // A node-id given by the integrator applies to the first start only.
    if (settings_.storedNodeIdWins || !powerOn) {
      *nodeId = record[0];
    }
    *timing = LssBitTiming{record[1], record[2]};
  } else if (damaged(result)) {
    remember(od::kGroupLss, result);
  }
}

void StoredParameters::loadGroups(uint32_t groups) noexcept {
  if (!ready_) {
    return;
  }
  for (uint8_t group = 1; group < 32U; ++group) {
    if ((groups & groupBit(group)) == 0U || !store_.hasGroup(group)) {
      continue;
    }
    const StoreResult result = store_.load(group);
    if (damaged(result)) {
      remember(group, result);
    }
  }
}

void StoredParameters::reportInvalid() noexcept {
  for (size_t i = 0; i < invalidCount_; ++i) {
    const Invalid invalid = invalid_[i];
    listeners_.notify([&invalid](NodeEvents& listener) {
      listener.onStoredParametersInvalid(invalid.group, invalid.result);
    });
  }
  invalidCount_ = 0;
}

StoreResult StoredParameters::save(uint32_t groups) noexcept {
  return ready_ ? store_.saveGroups(groups) : StoreResult::kNotLaidOut;
}

LssStoreResult StoredParameters::storeLssConfiguration(uint8_t nodeId,
                                                       LssBitTiming timing) noexcept {
  if (!ready_) {
    return LssStoreResult::kNotSupported;
  }
  const uint8_t record[kLssRecordLength] = {nodeId, timing.tableSelector, timing.tableIndex};
  return store_.saveRecord(kLssRecord, record, sizeof(record)) == StoreResult::kOk
             ? LssStoreResult::kStored
             : LssStoreResult::kStorageAccessError;
}

WriteObserver* StoredParameters::autoSave() noexcept {
  return settings_.saveParametersOnWrite ? this : nullptr;
}

AbortCode StoredParameters::onWritten(const od::EntryRef& ref, bool changed) noexcept {
  if (!changed || ref.group() == od::kGroupNone || !ready_) {
    return AbortCode::kNone;
  }
  return store_.save(ref.group()) == StoreResult::kOk ? AbortCode::kNone : AbortCode::kCannotStore;
}

bool StoredParameters::onRestoreAll() noexcept {
  if (!settings_.restoreAllIncludesLss || !ready_) {
    return true;
  }
  return store_.invalidateRecord(kLssRecord) == StoreResult::kOk;
}

}  // namespace costa
