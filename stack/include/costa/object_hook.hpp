// Behaviour behind dictionary entries: the way services and applications react to accesses.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/object_dictionary.hpp"

namespace costa {

/// Extra facts about a read request: the SDO initiate-upload frame's bytes 4..7, which CiA 301
/// reserves but some devices interpret (a channel selector, for example). All zero when the
/// read does not come from an SDO upload.
struct ReadRequest {
  uint8_t requestData[4] = {};
};

/// Attached to a range of indices with `Node::attachHook()`. The default implementation of each
/// function is the plain dictionary behaviour, so a hook overrides only what it changes.
///
/// Hooks run in the context that runs the node (never in an interrupt), synchronously, while a
/// frame is handled; they must not block. They report failures as CiA 301 abort codes, which
/// the SDO server sends unchanged.
class ObjectHook {
 public:
  /// Called before a remote read takes the value: may refresh the value in RAM, or refuse.
  virtual AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                                const ReadRequest& request) noexcept {
    (void)dictionary;
    (void)ref;
    (void)request;
    return AbortCode::kNone;
  }

  /// Carries out a remote write of `length` wire bytes (access rights already checked). The
  /// default checks and stores the value; an override may validate further, transform, store
  /// elsewhere, or act after storing.
  virtual AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                          const uint8_t* data, size_t length) noexcept {
    return dictionary.write(*ref.entry, data, length);
  }

 protected:
  ObjectHook() = default;
  ~ObjectHook() = default;
  ObjectHook(const ObjectHook&) = default;
  ObjectHook& operator=(const ObjectHook&) = default;
};

}  // namespace costa
