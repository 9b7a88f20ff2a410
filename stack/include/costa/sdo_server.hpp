// SDO server (CiA 301 7.2.4): expedited and segmented upload and download on the default
// SDO channel 0x600+id / 0x580+id.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/device_profile.hpp"
#include "costa/object_access.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/time.hpp"
#include "costa/tx_queue.hpp"

namespace costa {

class SdoServer {
 public:
  /// `buffer` holds a segmented transfer's data; its size bounds the largest value that can be
  /// downloaded. Uploads of larger values are read piecewise from the dictionary.
  SdoServer(ObjectAccess& access, TxQueue& tx, const DeviceProfile& profile, uint8_t* buffer,
            size_t bufferSize, Microseconds timeout) noexcept;

  void setNodeId(uint8_t nodeId) noexcept { nodeId_ = nodeId; }

  /// Handles a frame received on 0x600+id. Frames with DLC other than 8 and RTR frames are
  /// ignored, as CiA 301 requires: returns false for them. O(log n) in the dictionary size
  /// plus the hook's cost.
  bool onRequest(const CanFrame& frame, Microseconds now) noexcept;

  /// Aborts a transfer that has been silent longer than the timeout (0x05040000).
  void process(Microseconds now) noexcept;

  /// Next time process() has work, or kNever.
  Microseconds nextDeadline() const noexcept;

  /// Drops any transfer in progress without a frame (NMT reset, stopped state).
  void reset() noexcept;

  bool busy() const noexcept { return state_ != State::kIdle; }

 private:
  enum class State : uint8_t { kIdle, kDownloadSegments, kUploadSegments };

  void initiateDownload(const uint8_t* request, Microseconds now) noexcept;
  void downloadSegment(const uint8_t* request, Microseconds now) noexcept;
  void initiateUpload(const uint8_t* request, Microseconds now) noexcept;
  void uploadSegment(const uint8_t* request, Microseconds now) noexcept;
  void finishDownload() noexcept;

  void sendAbort(uint16_t index, uint8_t subIndex, AbortCode code) noexcept;
  void abortTransfer(AbortCode code) noexcept;
  void respond(const uint8_t (&data)[8]) noexcept;

  ObjectAccess& access_;
  TxQueue& tx_;
  const DeviceProfile& profile_;
  uint8_t* buffer_;
  size_t bufferSize_;
  Microseconds timeout_;
  uint8_t nodeId_ = 0;

  State state_ = State::kIdle;
  od::EntryRef ref_;
  uint16_t index_ = 0;
  uint8_t subIndex_ = 0;
  uint8_t toggle_ = 0;
  bool sizeIndicated_ = false;
  bool snapshot_ = false;  ///< Upload data is in buffer_ (else read from the dictionary).
  size_t size_ = 0;        ///< Total bytes of the transfer (indicated or known).
  size_t done_ = 0;        ///< Bytes transferred so far.
  Microseconds deadline_ = kNever;
};

}  // namespace costa
