// Store parameters 0x1010 and restore default parameters 0x1011 (CiA 301 7.5.2.13/14) on top of
// a ParameterStore.
//
// Sub-indices: 1 = every group the device saves on command (NodeSettings::storeAllGroups),
// 2 = communication (group 1), 3 = application (group 2), n >= 4 = group n. Reading a
// sub-index gives the CiA 301 capability: 1 (saves on command) when the store holds one of its
// groups, 0 otherwise; 0x1010 adds bit 1 (saves autonomously) when a written entry's group is
// saved at once (NodeSettings::saveParametersOnWrite). Writing "save" (0x65766173) to 0x1010 saves
// the groups; writing "load" (0x64616F6C) to 0x1011 stores "restore defaults" markers, so the
// defaults come back at the next reset node / reset communication. Any other value aborts
// 0x08000020, as does a sub-index without groups or a failing medium; a sub-index the dictionary
// does not declare aborts 0x06090011 before it reaches this hook.
//
// Sub-index 1 saves (or restores) its groups one after the other, by ascending number, each
// atomically (docs/storage.md): a power loss in the middle leaves every group entirely old or
// entirely new, the groups before the cut new and the others old. CiA 301 makes each
// sub-index one parameter area, saved and restored on its own; "all" is every area, not one
// set that must be consistent as a whole.
#pragma once

#include <stdint.h>

#include "costa/object_hook.hpp"
#include "costa/parameter_store.hpp"

namespace costa {

class StoreCommands : public ObjectHook {
 public:
  static constexpr uint16_t kStoreIndex = 0x1010;
  static constexpr uint16_t kRestoreIndex = 0x1011;
  static constexpr uint32_t kSaveSignature = 0x65766173;  ///< "save"
  static constexpr uint32_t kLoadSignature = 0x64616F6C;  ///< "load"

  /// Reaction to a restore of every group (0x1011 sub-index 1) beyond the groups themselves.
  class RestoreAllListener {
   public:
    /// False when it failed: the restore answers 0x08000020 (the groups are restored already).
    virtual bool onRestoreAll() noexcept { return true; }

   protected:
    RestoreAllListener() = default;
    ~RestoreAllListener() = default;
    RestoreAllListener(const RestoreAllListener&) = default;
    RestoreAllListener& operator=(const RestoreAllListener&) = default;
    RestoreAllListener(RestoreAllListener&&) = default;
    RestoreAllListener& operator=(RestoreAllListener&&) = default;
  };

  /// `store` may be null (no storage: every capability reads 0). `savesOnWrite`: the node saves
  /// a written entry's group at once (0x1010 reads bit 1 too).
  StoreCommands(ParameterStore* store, uint32_t saveAllGroups, uint32_t restoreAllGroups,
                bool savesOnWrite = false) noexcept
      : store_(store),
        saveAll_(saveAllGroups),
        restoreAll_(restoreAllGroups),
        savesOnWrite_(savesOnWrite) {}

  void setRestoreAllListener(RestoreAllListener* listener) noexcept { listener_ = listener; }
  void setStore(ParameterStore* store) noexcept { store_ = store; }

  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  /// Bit g set for each group sub-index `subIndex` stands for (0 when it stands for none).
  uint32_t groupsOf(uint16_t index, uint8_t subIndex) const noexcept;

  ParameterStore* store_;
  uint32_t saveAll_;
  uint32_t restoreAll_;
  bool savesOnWrite_;
  RestoreAllListener* listener_ = nullptr;
};

/// Bit mask of a storage group for StoreCommands and NodeSettings.
constexpr uint32_t groupBit(uint8_t group) noexcept {
  return group < 32U ? uint32_t{1U} << group : 0U;
}

}  // namespace costa
