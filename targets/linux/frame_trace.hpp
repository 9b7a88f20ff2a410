// Decodes CAN frames into one-line descriptions of their CANopen meaning, for --trace.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "costa/device_profile.hpp"
#include "costa/od/definition.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/port/can_frame.hpp"

namespace costa::host {

/// Remembers what it has seen (an SDO transfer in progress, a guarding request) so that later
/// frames can be described in context. Values of the local node's objects are shown by type.
class FrameTracer {
 public:
  /// `dictionary` (may be null) is the local node's, used to format values; `names` (may be
  /// null) to name objects; `profile` says how the local node encodes its frames (the same
  /// per-service profiles its services are given). Other nodes' frames are read as CiA 301.
  FrameTracer(const od::ObjectDictionary* dictionary, const od::NameTable* names,
              const DeviceProfile& profile = DeviceProfile{});

  /// Meaning of `frame` on a bus where the local node has `localNodeId`.
  std::string describe(const CanFrame& frame, uint8_t localNodeId);

  /// Name of an entry, "" when unknown.
  std::string nameOf(uint16_t index, uint8_t subIndex) const;

 private:
  static std::string describeTime(const CanFrame& frame);
  std::string describeNmt(const CanFrame& frame) const;
  std::string describeEmcy(const CanFrame& frame, bool local) const;
  std::string describeErrorControl(const CanFrame& frame, bool local);
  std::string describeSdoRequest(const CanFrame& frame, bool local);
  /// An SDO request's 8 bytes (a short one's completed with zeros).
  std::string describeSdoRequestData(const uint8_t* d, bool local);
  std::string describeSdoResponse(const CanFrame& frame, bool local);
  std::string describeBlockRequest(const uint8_t* data, const std::string& entry);
  std::string describeBlockResponse(const uint8_t* data, const std::string& entry,
                                    const std::string& name);
  std::string describeBlockSegment(const uint8_t* data);
  std::string describeLss(const CanFrame& frame, bool fromMaster) const;
  std::string formatValue(uint16_t index, uint8_t subIndex, const uint8_t* data, size_t length,
                          bool local) const;
  std::string entryText(uint16_t index, uint8_t subIndex) const;

  const od::ObjectDictionary* dictionary_;
  const od::NameTable* names_;
  DeviceProfile profile_;
  uint8_t guardRequested_[128] = {};
  // Segmented SDO transfer being watched.
  bool uploading_ = false;
  bool downloading_ = false;
  uint16_t index_ = 0;
  uint8_t subIndex_ = 0;
  std::vector<uint8_t> collected_;
  // Block SDO transfer being watched: in kDownloadSegments the client's frames are segments,
  // in kUploadSegments the server's; kDownloadEnd/kUploadEnd: the segment marked last was
  // acknowledged, the end frame comes next.
  enum class Block : uint8_t {
    kNone,
    kDownloadSegments,
    kDownloadEnd,
    kUploadSegments,
    kUploadEnd
  };
  Block block_ = Block::kNone;
  uint8_t blockLastSequence_ = 0;  ///< Sequence number of the segment marked last; 0: none yet.
};

}  // namespace costa::host
