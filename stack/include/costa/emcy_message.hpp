// An emergency message another node sent, as the EMCY consumer (0x1028) hands it to the
// node's listeners (NodeEvents::onEmcyReceived).
#pragma once

#include <stdint.h>

namespace costa {

struct EmcyMessage {
  uint16_t canId = 0;
  uint8_t producer = 0;  ///< node-id of a pre-defined EMCY CAN-ID (0x81..0xFF), else 0
  uint8_t entry = 0;     ///< the sub-index of 0x1028 that lists the CAN-ID
  uint16_t errorCode = 0;
  uint8_t errorRegister = 0;
  uint8_t manufacturer[5] = {};
};

}  // namespace costa
