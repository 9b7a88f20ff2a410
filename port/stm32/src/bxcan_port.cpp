#include "costa/port/stm32/bxcan_port.hpp"

#include "costa/port/stm32/bxcan_bit_timing.hpp"

namespace costa::port::stm32 {

namespace {

constexpr uint32_t kMailboxes = 3;
constexpr uint32_t kFilterBank0 = 1U << 0;

constexpr uint32_t littleEndianWord(const uint8_t* bytes) noexcept {
  return uint32_t{bytes[0]} | (uint32_t{bytes[1]} << 8) | (uint32_t{bytes[2]} << 16) |
         (uint32_t{bytes[3]} << 24);
}

void storeLittleEndianWord(uint32_t word, uint8_t* bytes) noexcept {
  for (size_t i = 0; i < 4; ++i) {
    bytes[i] = static_cast<uint8_t>(word >> (8U * i));
  }
}

}  // namespace

bool BxCanPort::waitForStatus(uint32_t mask, uint32_t expected) noexcept {
  for (uint32_t reads = 0; reads < waitLimit_; ++reads) {
    if (waitHook_ != nullptr) {
      waitHook_(waitContext_);
    }
    if ((registers_.msr & mask) == expected) {
      return true;
    }
  }
  return false;
}

void BxCanPort::acceptEverythingIntoFifo0() noexcept {
  using namespace bxcan;
  registers_.fmr = registers_.fmr | fmr::kFinit;
  registers_.fa1r = registers_.fa1r & ~kFilterBank0;    // a bank is changed while inactive
  registers_.fm1r = registers_.fm1r & ~kFilterBank0;    // identifier mask mode
  registers_.fs1r = registers_.fs1r | kFilterBank0;     // one 32-bit filter
  registers_.ffa1r = registers_.ffa1r & ~kFilterBank0;  // into FIFO 0
  registers_.filter[0].fr1 = 0;                         // identifier: anything ...
  registers_.filter[0].fr2 = 0;                         // ... as no bit must match
  registers_.fa1r = registers_.fa1r | kFilterBank0;
  registers_.fmr = registers_.fmr & ~fmr::kFinit;
}

bool BxCanPort::start(uint32_t btr, uint32_t clockHz) noexcept {
  using namespace bxcan;
  errorPassive_ = false;
  busOff_ = false;
  clockHz_ = clockHz;
  // After reset the controller sleeps; initialisation is requested and sleep left in one write.
  registers_.mcr = (registers_.mcr & ~mcr::kSleep) | mcr::kInrq;
  if (!waitForStatus(msr::kInak | msr::kSlak, msr::kInak)) {
    return false;
  }
  registers_.mcr = (registers_.mcr & mcr::kDbf) | mcr::kInrq | mcr::kAbom | mcr::kTxfp;
  registers_.btr = btr;
  configured_ = true;
  acceptEverythingIntoFifo0();
  registers_.mcr = registers_.mcr & ~mcr::kInrq;
  return waitForStatus(msr::kInak, 0);
}

bool BxCanPort::setBitRate(uint32_t bitsPerSecond) noexcept {
  using namespace bxcan;
  const BxCanBitTiming timing = bxCanBitTiming(clockHz_, bitsPerSecond);
  if (!configured_ || !timing.valid()) {
    return false;
  }
  registers_.mcr = registers_.mcr | mcr::kInrq;
  if (!waitForStatus(msr::kInak, msr::kInak)) {
    registers_.mcr = registers_.mcr & ~mcr::kInrq;
    return false;
  }
  registers_.btr = (registers_.btr & (btr::kLbkm | btr::kSilm)) | timing.btr();
  registers_.mcr = registers_.mcr & ~mcr::kInrq;
  return true;
}

bool BxCanPort::tryTransmit(const CanFrame& frame) noexcept {
  using namespace bxcan;
  const uint32_t status = registers_.tsr;
  uint32_t mailbox = 0;
  while (mailbox < kMailboxes && (status & tsr::tme(mailbox)) == 0) {
    ++mailbox;
  }
  if (mailbox == kMailboxes) {
    return false;
  }
  uint32_t identifier = 0;
  if (frame.extended) {
    identifier = ((frame.id & ir::kExtendedIdMask) << ir::kExidShift) | ir::kIde;
  } else {
    identifier = (frame.id & ir::kStandardIdMask) << ir::kStidShift;
  }
  if (frame.rtr) {
    identifier |= ir::kRtr;
  }
  BxCanTxMailbox& box = registers_.tx[mailbox];
  box.tdtr = frame.dlc > 8U ? 8U : frame.dlc;
  box.tdlr = littleEndianWord(&frame.data[0]);
  box.tdhr = littleEndianWord(&frame.data[4]);
  box.tir = identifier | ir::kTxrq;  // last: the request makes the mailbox read-only
  return true;
}

bool BxCanPort::receive(CanFrame* frame) noexcept {
  using namespace bxcan;
  if ((registers_.rf0r & rfr::kFmpMask) == 0) {
    return false;
  }
  const BxCanRxMailbox& box = registers_.rx[0];
  const uint32_t identifier = box.rir;
  const uint32_t lengthAndStamp = box.rdtr;
  const uint32_t low = box.rdlr;
  const uint32_t high = box.rdhr;
  registers_.rf0r = rfr::kRfom;  // write 1 to release; the other bits ignore a 0

  *frame = CanFrame{};
  frame->extended = (identifier & ir::kIde) != 0;
  frame->id = frame->extended ? (identifier >> ir::kExidShift) & ir::kExtendedIdMask
                              : (identifier >> ir::kStidShift) & ir::kStandardIdMask;
  frame->rtr = (identifier & ir::kRtr) != 0;
  frame->dlc = static_cast<uint8_t>(lengthAndStamp & dtr::kDlcMask);
  if (!frame->rtr) {
    uint8_t bytes[8];
    storeLittleEndianWord(low, &bytes[0]);
    storeLittleEndianWord(high, &bytes[4]);
    for (size_t i = 0; i < frame->dlc && i < 8U; ++i) {
      frame->data[i] = bytes[i];
    }
  }
  return true;
}

BxCanEvents BxCanPort::poll() noexcept {
  using namespace bxcan;
  BxCanEvents events;
  if ((registers_.rf0r & rfr::kFovr) != 0) {
    registers_.rf0r = rfr::kFovr;  // write 1 to clear; FULL and the release bit ignore a 0
    events.add(CanControllerEvent::kRxOverrun);
  }
  const uint32_t errorStatus = registers_.esr;
  const bool busOff = (errorStatus & esr::kBoff) != 0;
  const bool errorPassive = (errorStatus & esr::kEpvf) != 0;
  if (busOff_ && !busOff) {
    events.add(CanControllerEvent::kBusOffRecovered);
  }
  if (errorPassive != errorPassive_) {
    events.add(errorPassive ? CanControllerEvent::kErrorPassive : CanControllerEvent::kErrorActive);
  }
  if (!busOff_ && busOff) {
    events.add(CanControllerEvent::kBusOff);
  }
  busOff_ = busOff;
  errorPassive_ = errorPassive;
  return events;
}

}  // namespace costa::port::stm32
