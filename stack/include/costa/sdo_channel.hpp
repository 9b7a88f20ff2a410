// The sending side of an SDO server's channel (0x580 + node-id for the default server, the
// COB-ID server -> client of 0x1201..0x127F for the others): responses, aborts, and the room
// left in the transmit queue for a burst of block upload segments.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include "costa/cob_ids.hpp"
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

  /// Queues an abort frame (CiA 301 7.2.4.3.17).
  void sendAbort(uint16_t index, uint8_t subIndex, AbortCode code) noexcept {
    if (!profile_.distinguishHighAndLowValues &&
        (code == AbortCode::kValueTooHigh || code == AbortCode::kValueTooLow)) {
      code = AbortCode::kInvalidValue;
    }
    uint8_t data[8] = {0x80, static_cast<uint8_t>(index), static_cast<uint8_t>(index >> 8U),
                       subIndex};
    storeU32(data + 4, static_cast<uint32_t>(code));
    send(data);
  }

  /// Whether a burst may queue another frame. A quarter of the queue stays free for the other
  /// services (heartbeat, emergency), so that a long block upload never crowds them out.
  bool roomForBurst() const noexcept { return tx_.roomForBurst(); }

 private:
  TransmitPath& tx_;
  const SdoProfile& profile_;
  uint32_t canId_ = cob::kSdoTxBase;
};

}  // namespace costa
