// A node's stored parameters: its ParameterStore over NodeSettings::storage, the loads of each
// reset, the reports of what could not be loaded, 0x1010/0x1011, the public save, the save on
// every write of devices that keep parameters without a store command, and the CiA 305 LSS
// record (node-id and bit timing). Compiled out (features::kParameterStorage), the node holds
// AbsentStoredParameters instead (StoredParametersChoice): it keeps nothing, and 0x1010/0x1011
// do not exist.
//
// Context: the one that runs the node. No allocation. Loads and saves cost what the medium
// costs (NvStorage); they happen at start(), at resets and on explicit requests only, never
// while an ordinary frame is handled (except a write that saves, with saveParametersOnWrite).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/compiled_out.hpp"
#include "costa/features.hpp"
#include "costa/lss_slave.hpp"
#include "costa/node_events.hpp"
#include "costa/node_settings.hpp"
#include "costa/object_access.hpp"
#include "costa/parameter_store.hpp"
#include "costa/store_commands.hpp"

namespace costa {

class StoredParameters final : private StoreCommands::RestoreAllListener, private WriteObserver {
 public:
  static constexpr uint8_t kLssRecord = 1;  ///< ParameterStore record of the LSS configuration
  /// Bytes of that record: pending node-id, bit timing table selector, bit timing table index.
  static constexpr size_t kLssRecordLength = 3;

  StoredParameters(od::ObjectDictionary& dictionary, const NodeSettings& settings,
                   const NodeListeners& listeners) noexcept;
  StoredParameters(const StoredParameters&) = delete;
  StoredParameters& operator=(const StoredParameters&) = delete;
  ~StoredParameters() = default;

  /// Power-on: lays the regions (every storage group and the LSS record) out over the storage.
  /// Without storage, or when it is too small, nothing is ever loaded or saved.
  void layOut() noexcept;
  /// The store, when laid out; else null.
  ParameterStore* store() noexcept;

  /// The node-id and bit timing to start from: the settings', replaced by a stored LSS record
  /// (its node-id at power-on only when NodeSettings::storedNodeIdWins). A damaged record is
  /// remembered for reportInvalid().
  void loadLssConfiguration(bool powerOn, uint8_t* nodeId, LssBitTiming* timing) noexcept;
  /// Loads every stored group of `groups`; a damaged one keeps its defaults and is remembered
  /// for reportInvalid().
  void loadGroups(uint32_t groups) noexcept;
  /// Tells the listeners of each group (or LSS record) that could not be loaded since the last
  /// report (NodeEvents::onStoredParametersInvalid), then forgets them.
  void reportInvalid() noexcept;

  /// Saves `groups` now: each group on its own, by ascending number, with the power-loss
  /// guarantee of 0x1010 (ParameterStore::saveGroups). kNotLaidOut without storage.
  StoreResult save(uint32_t groups) noexcept;
  /// Stores the LSS configuration, as LSS store configuration does.
  LssStoreResult storeLssConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept;

  /// The hook of 0x1010/0x1011.
  ObjectHook& commands() noexcept { return commands_; }
  /// The observer that saves a written entry's group (NodeSettings::saveParametersOnWrite),
  /// or null.
  WriteObserver* autoSave() noexcept;

 private:
  bool onRestoreAll() noexcept override;
  AbortCode onWritten(const od::EntryRef& ref, bool changed) noexcept override;
  void remember(uint8_t group, StoreResult result) noexcept;

  class NoStorage final : public NvStorage {};

  const NodeSettings& settings_;
  const NodeListeners& listeners_;
  NoStorage noStorage_;
  ParameterStore store_;
  StoreCommands commands_;
  bool ready_ = false;
  struct Invalid {
    uint8_t group;
    StoreResult result;
  };
  Invalid invalid_[8] = {};
  size_t invalidCount_ = 0;
};

/// Parameter storage compiled out: nothing is laid out, loaded or saved, the node-id and bit
/// timing are the settings', and 0x1010/0x1011 do not exist. Its calls vanish when inlined.
class AbsentStoredParameters final : public AbsentService {
 public:
  AbsentStoredParameters(od::ObjectDictionary& dictionary, const NodeSettings& settings,
                         const NodeListeners& listeners) noexcept
      : settings_(settings) {
    (void)dictionary;
    (void)listeners;
  }
  void layOut() noexcept {}
  ParameterStore* store() noexcept { return nullptr; }
  void loadLssConfiguration(bool powerOn, uint8_t* nodeId, LssBitTiming* timing) noexcept {
    (void)powerOn;
    *nodeId = settings_.nodeId;
    *timing = settings_.bitTiming;
  }
  void loadGroups(uint32_t groups) noexcept { (void)groups; }
  void reportInvalid() noexcept {}
  StoreResult save(uint32_t groups) noexcept {
    (void)groups;
    return StoreResult::kNotLaidOut;
  }
  LssStoreResult storeLssConfiguration(uint8_t nodeId, LssBitTiming timing) noexcept {
    (void)nodeId;
    (void)timing;
    return LssStoreResult::kNotSupported;
  }
  ObjectHook& commands() noexcept { return *serviceHook(*this); }
  WriteObserver* autoSave() noexcept { return nullptr; }

 private:
  const NodeSettings& settings_;
};

/// The node's stored parameters: StoredParameters, or its stand-in without parameter storage.
using StoredParametersChoice =
    ServiceIf<features::kParameterStorage, StoredParameters, AbsentStoredParameters>;

}  // namespace costa
