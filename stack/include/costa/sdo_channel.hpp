// The sending side of an SDO server's channel (0x580 + node-id for the default server, the
// COB-ID server -> client of 0x1201..0x127F for the others): responses, aborts, and the room
// left in the transmit queue for a burst of block upload segments.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include "costa/cob_ids.hpp"
#include "costa/hot_path.hpp"
#include "costa/od/abort_code.hpp"
#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/port/can_frame.hpp"
#include "costa/sdo_profile.hpp"
#include "costa/transmit_path.hpp"

namespace costa {

class SdoChannel {
 public:
  /// `profile`: the server's, which outlives the channel (its abort codes for values out of
  /// range).
  SdoChannel(TransmitPath& tx, const SdoProfile& profile) noexcept : tx_(tx), profile_(profile) {}

  /// Responses on 0x580 + `nodeId` (the default server).
  void setNodeId(uint8_t nodeId) noexcept { canId_ = cob::kSdoTxBase + nodeId; }
  /// Responses on `canId` (an 11-bit CAN-ID: an additional server).
  void setCanId(uint16_t canId) noexcept { canId_ = canId; }

  /// Makes `frame` (as constructed: all zero) an 8-byte response on the channel's CAN-ID.
  void address(CanFrame& frame) const noexcept {
    frame.id = canId_;
    frame.dlc = 8;
  }
  void send(const CanFrame& frame) noexcept { tx_.send(frame); }
  /// Sends one 8-byte response.
  void send(const uint8_t (&data)[8]) noexcept {
    CanFrame frame;
    address(frame);
    copyBytes(frame.data, data, 8);
    tx_.send(frame);
  }
  /// Sends the response that most SDO frames are: byte 0 `command`, the multiplexer (`index`,
  /// `subIndex`), then `data` in bytes 4..7, little-endian. Built straight into the frame, as
  /// one copy that every response and abort shares.
  COSTA_SHARED_INLINE void send(uint8_t command, uint16_t index, uint8_t subIndex,
                                uint32_t data) noexcept {
    CanFrame frame;
    address(frame);
    frame.data[0] = command;
    storeU16(frame.data + 1, index);
    frame.data[3] = subIndex;
    storeU32(frame.data + 4, data);
    tx_.send(frame);
  }

  /// Queues an abort frame (CiA 301 7.2.4.3.17).
  void sendAbort(uint16_t index, uint8_t subIndex, AbortCode code) noexcept {
    if (!profile_.distinguishHighAndLowValues &&
        (code == AbortCode::kValueTooHigh || code == AbortCode::kValueTooLow)) {
      code = AbortCode::kInvalidValue;
    }
    send(kAbortCommand, index, subIndex, static_cast<uint32_t>(code));
  }

  /// Whether a burst may queue another frame. A quarter of the queue stays free for the other
  /// services (heartbeat, emergency), so that a long block upload never crowds them out.
  bool roomForBurst() const noexcept { return tx_.roomForBurst(); }

 private:
  static constexpr uint8_t kAbortCommand = 0x80;  ///< byte 0 of an abort: cs 4, nothing else

  TransmitPath& tx_;
  const SdoProfile& profile_;
  uint32_t canId_ = cob::kSdoTxBase;
};

}  // namespace costa
