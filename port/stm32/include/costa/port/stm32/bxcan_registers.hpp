// The register block of an STM32 bxCAN controller (RM0090, STM32F405/407/415/417/427/429/437/439,
// chapter "Controller area network (bxCAN)"), with the bits the Costa driver uses.
//
// The layout is a plain struct so that firmware maps it onto the peripheral
// (`bxCan1()`) and host tests place one in RAM as a simulated controller.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa::port::stm32 {

/// One transmit mailbox (RM0090: CAN_TIxR, CAN_TDTxR, CAN_TDLxR, CAN_TDHxR).
struct BxCanTxMailbox {
  volatile uint32_t tir;   ///< Identifier, IDE, RTR, TXRQ.
  volatile uint32_t tdtr;  ///< DLC, TGT, time stamp.
  volatile uint32_t tdlr;  ///< Data bytes 0..3 (byte 0 in bits 7:0).
  volatile uint32_t tdhr;  ///< Data bytes 4..7 (byte 4 in bits 7:0).
};

/// The output mailbox of one receive FIFO (RM0090: CAN_RIxR, CAN_RDTxR, CAN_RDLxR, CAN_RDHxR).
struct BxCanRxMailbox {
  volatile uint32_t rir;   ///< Identifier, IDE, RTR.
  volatile uint32_t rdtr;  ///< DLC, filter match index, time stamp.
  volatile uint32_t rdlr;  ///< Data bytes 0..3.
  volatile uint32_t rdhr;  ///< Data bytes 4..7.
};

/// One filter bank (RM0090: CAN_FiR1, CAN_FiR2). In 32-bit mask mode: identifier, mask.
struct BxCanFilterBank {
  volatile uint32_t fr1;
  volatile uint32_t fr2;
};

/// The whole bxCAN register block, offsets as in the RM0090 register map.
struct BxCanRegisters {
  volatile uint32_t mcr;   ///< 0x000 master control
  volatile uint32_t msr;   ///< 0x004 master status
  volatile uint32_t tsr;   ///< 0x008 transmit status
  volatile uint32_t rf0r;  ///< 0x00C receive FIFO 0
  volatile uint32_t rf1r;  ///< 0x010 receive FIFO 1
  volatile uint32_t ier;   ///< 0x014 interrupt enable
  volatile uint32_t esr;   ///< 0x018 error status
  volatile uint32_t btr;   ///< 0x01C bit timing (writable in initialisation mode only)
  uint32_t reserved0[88];  ///< 0x020..0x17F
  BxCanTxMailbox tx[3];    ///< 0x180, 0x190, 0x1A0
  BxCanRxMailbox rx[2];    ///< 0x1B0 (FIFO 0), 0x1C0 (FIFO 1)
  uint32_t reserved1[12];  ///< 0x1D0..0x1FF
  // Filter registers: on a dual-CAN part they exist in CAN1's block only and serve both cells.
  volatile uint32_t fmr;       ///< 0x200 filter master (FINIT, CAN2SB)
  volatile uint32_t fm1r;      ///< 0x204 filter mode: 0 mask, 1 identifier list (bit per bank)
  uint32_t reserved2;          ///< 0x208
  volatile uint32_t fs1r;      ///< 0x20C filter scale: 0 dual 16-bit, 1 single 32-bit
  uint32_t reserved3;          ///< 0x210
  volatile uint32_t ffa1r;     ///< 0x214 filter FIFO assignment: 0 FIFO 0, 1 FIFO 1
  uint32_t reserved4;          ///< 0x218
  volatile uint32_t fa1r;      ///< 0x21C filter activation
  uint32_t reserved5[8];       ///< 0x220..0x23F
  BxCanFilterBank filter[28];  ///< 0x240..0x31F
};

static_assert(offsetof(BxCanRegisters, mcr) == 0x000);
static_assert(offsetof(BxCanRegisters, msr) == 0x004);
static_assert(offsetof(BxCanRegisters, tsr) == 0x008);
static_assert(offsetof(BxCanRegisters, rf0r) == 0x00C);
static_assert(offsetof(BxCanRegisters, rf1r) == 0x010);
static_assert(offsetof(BxCanRegisters, ier) == 0x014);
static_assert(offsetof(BxCanRegisters, esr) == 0x018);
static_assert(offsetof(BxCanRegisters, btr) == 0x01C);
static_assert(offsetof(BxCanRegisters, tx[0].tir) == 0x180);
static_assert(offsetof(BxCanRegisters, tx[0].tdtr) == 0x184);
static_assert(offsetof(BxCanRegisters, tx[0].tdlr) == 0x188);
static_assert(offsetof(BxCanRegisters, tx[0].tdhr) == 0x18C);
static_assert(offsetof(BxCanRegisters, tx[1].tir) == 0x190);
static_assert(offsetof(BxCanRegisters, tx[1].tdtr) == 0x194);
static_assert(offsetof(BxCanRegisters, tx[1].tdlr) == 0x198);
static_assert(offsetof(BxCanRegisters, tx[1].tdhr) == 0x19C);
static_assert(offsetof(BxCanRegisters, tx[2].tir) == 0x1A0);
static_assert(offsetof(BxCanRegisters, tx[2].tdtr) == 0x1A4);
static_assert(offsetof(BxCanRegisters, tx[2].tdlr) == 0x1A8);
static_assert(offsetof(BxCanRegisters, tx[2].tdhr) == 0x1AC);
static_assert(offsetof(BxCanRegisters, rx[0].rir) == 0x1B0);
static_assert(offsetof(BxCanRegisters, rx[0].rdtr) == 0x1B4);
static_assert(offsetof(BxCanRegisters, rx[0].rdlr) == 0x1B8);
static_assert(offsetof(BxCanRegisters, rx[0].rdhr) == 0x1BC);
static_assert(offsetof(BxCanRegisters, rx[1].rir) == 0x1C0);
static_assert(offsetof(BxCanRegisters, rx[1].rdtr) == 0x1C4);
static_assert(offsetof(BxCanRegisters, rx[1].rdlr) == 0x1C8);
static_assert(offsetof(BxCanRegisters, rx[1].rdhr) == 0x1CC);
static_assert(offsetof(BxCanRegisters, fmr) == 0x200);
static_assert(offsetof(BxCanRegisters, fm1r) == 0x204);
static_assert(offsetof(BxCanRegisters, fs1r) == 0x20C);
static_assert(offsetof(BxCanRegisters, ffa1r) == 0x214);
static_assert(offsetof(BxCanRegisters, fa1r) == 0x21C);
static_assert(offsetof(BxCanRegisters, filter[0].fr1) == 0x240);
static_assert(offsetof(BxCanRegisters, filter[0].fr2) == 0x244);
static_assert(offsetof(BxCanRegisters, filter[1].fr1) == 0x248);
static_assert(offsetof(BxCanRegisters, filter[13].fr2) == 0x2AC);
static_assert(offsetof(BxCanRegisters, filter[14].fr1) == 0x2B0);
static_assert(offsetof(BxCanRegisters, filter[27].fr1) == 0x318);
static_assert(offsetof(BxCanRegisters, filter[27].fr2) == 0x31C);
static_assert(sizeof(BxCanRegisters) == 0x320);

/// Base addresses of the two bxCAN cells of STM32F4 parts (RM0090 memory map).
inline constexpr uintptr_t kBxCan1Base = 0x40006400U;
inline constexpr uintptr_t kBxCan2Base = 0x40006800U;

/// CAN1's register block. For firmware only: on a host this address means nothing.
inline BxCanRegisters& bxCan1() noexcept {
  // The peripheral sits at a fixed address, which only an integer-to-pointer cast can reach.
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast,performance-no-int-to-ptr): MMIO
  return *reinterpret_cast<BxCanRegisters*>(kBxCan1Base);
}

/// Named bits, one namespace per register (names as in RM0090).
namespace bxcan {

namespace mcr {
inline constexpr uint32_t kInrq = 1U << 0;    ///< initialisation request
inline constexpr uint32_t kSleep = 1U << 1;   ///< sleep mode request (set after reset)
inline constexpr uint32_t kTxfp = 1U << 2;    ///< transmit priority: 1 = by request order
inline constexpr uint32_t kRflm = 1U << 3;    ///< receive FIFO locked: 1 = keep old, drop new
inline constexpr uint32_t kNart = 1U << 4;    ///< no automatic retransmission
inline constexpr uint32_t kAwum = 1U << 5;    ///< automatic wake-up
inline constexpr uint32_t kAbom = 1U << 6;    ///< automatic bus-off management
inline constexpr uint32_t kTtcm = 1U << 7;    ///< time-triggered communication
inline constexpr uint32_t kReset = 1U << 15;  ///< master reset (self-clearing)
inline constexpr uint32_t kDbf = 1U << 16;    ///< freeze the controller while the core is halted
}  // namespace mcr

namespace msr {
inline constexpr uint32_t kInak = 1U << 0;   ///< initialisation acknowledge
inline constexpr uint32_t kSlak = 1U << 1;   ///< sleep acknowledge
inline constexpr uint32_t kErri = 1U << 2;   ///< error interrupt (write 1 to clear)
inline constexpr uint32_t kWkui = 1U << 3;   ///< wake-up interrupt (write 1 to clear)
inline constexpr uint32_t kSlaki = 1U << 4;  ///< sleep acknowledge interrupt (write 1 to clear)
inline constexpr uint32_t kTxm = 1U << 8;    ///< transmitting
inline constexpr uint32_t kRxm = 1U << 9;    ///< receiving
inline constexpr uint32_t kSamp = 1U << 10;  ///< last sample point value
inline constexpr uint32_t kRx = 1U << 11;    ///< CANRX level
}  // namespace msr

namespace tsr {
/// Request completed, transmission OK, arbitration lost, transmission error, abort request of
/// mailbox `m` (0..2).
constexpr uint32_t rqcp(uint32_t m) noexcept {
  return 1U << (8U * m + 0U);
}
constexpr uint32_t txok(uint32_t m) noexcept {
  return 1U << (8U * m + 1U);
}
constexpr uint32_t alst(uint32_t m) noexcept {
  return 1U << (8U * m + 2U);
}
constexpr uint32_t terr(uint32_t m) noexcept {
  return 1U << (8U * m + 3U);
}
constexpr uint32_t abrq(uint32_t m) noexcept {
  return 1U << (8U * m + 7U);
}
inline constexpr uint32_t kCodeShift = 24;  ///< next free mailbox (2 bits)
inline constexpr uint32_t kCodeMask = 3U << kCodeShift;
/// Transmit mailbox `m` (0..2) empty.
constexpr uint32_t tme(uint32_t m) noexcept {
  return 1U << (26U + m);
}
inline constexpr uint32_t kTmeAll = (1U << 26) | (1U << 27) | (1U << 28);
/// Mailbox `m` has the lowest priority of several pending ones.
constexpr uint32_t low(uint32_t m) noexcept {
  return 1U << (29U + m);
}
}  // namespace tsr

/// CAN_RF0R and CAN_RF1R.
namespace rfr {
inline constexpr uint32_t kFmpMask = 3U;    ///< messages pending (0..3)
inline constexpr uint32_t kFull = 1U << 3;  ///< FIFO full (write 1 to clear)
inline constexpr uint32_t kFovr = 1U << 4;  ///< FIFO overrun: a message was lost (write 1 to clear)
inline constexpr uint32_t kRfom = 1U << 5;  ///< release the output mailbox (write 1)
}  // namespace rfr

namespace ier {
inline constexpr uint32_t kTmeie = 1U << 0;
inline constexpr uint32_t kFmpie0 = 1U << 1;
inline constexpr uint32_t kFfie0 = 1U << 2;
inline constexpr uint32_t kFovie0 = 1U << 3;
inline constexpr uint32_t kFmpie1 = 1U << 4;
inline constexpr uint32_t kFfie1 = 1U << 5;
inline constexpr uint32_t kFovie1 = 1U << 6;
inline constexpr uint32_t kEwgie = 1U << 8;
inline constexpr uint32_t kEpvie = 1U << 9;
inline constexpr uint32_t kBofie = 1U << 10;
inline constexpr uint32_t kLecie = 1U << 11;
inline constexpr uint32_t kErrie = 1U << 15;
inline constexpr uint32_t kWkuie = 1U << 16;
inline constexpr uint32_t kSlkie = 1U << 17;
}  // namespace ier

namespace esr {
inline constexpr uint32_t kEwgf = 1U << 0;  ///< error warning: a counter reached 96
inline constexpr uint32_t kEpvf = 1U << 1;  ///< error passive: a counter above 127
inline constexpr uint32_t kBoff = 1U << 2;  ///< bus-off
inline constexpr uint32_t kLecShift = 4;    ///< last error code (3 bits)
inline constexpr uint32_t kLecMask = 7U << kLecShift;
inline constexpr uint32_t kTecShift = 16;  ///< transmit error counter, low 8 bits
inline constexpr uint32_t kRecShift = 24;  ///< receive error counter
}  // namespace esr

/// CAN_BTR. Each field holds its value minus one.
namespace btr {
inline constexpr uint32_t kBrpShift = 0;  ///< prescaler - 1 (10 bits)
inline constexpr uint32_t kBrpMask = 0x3FFU << kBrpShift;
inline constexpr uint32_t kTs1Shift = 16;  ///< time segment 1 - 1 (4 bits)
inline constexpr uint32_t kTs1Mask = 0xFU << kTs1Shift;
inline constexpr uint32_t kTs2Shift = 20;  ///< time segment 2 - 1 (3 bits)
inline constexpr uint32_t kTs2Mask = 0x7U << kTs2Shift;
inline constexpr uint32_t kSjwShift = 24;  ///< resynchronisation jump width - 1 (2 bits)
inline constexpr uint32_t kSjwMask = 0x3U << kSjwShift;
inline constexpr uint32_t kLbkm = 1U << 30;  ///< loop back mode (debug)
inline constexpr uint32_t kSilm = 1U << 31;  ///< silent mode (debug)
}  // namespace btr

/// CAN_TIxR (transmit) and CAN_RIxR (receive): identifier and frame format.
namespace ir {
inline constexpr uint32_t kTxrq = 1U << 0;  ///< transmit request (transmit mailboxes only)
inline constexpr uint32_t kRtr = 1U << 1;   ///< remote frame
inline constexpr uint32_t kIde = 1U << 2;   ///< extended (29-bit) identifier
inline constexpr uint32_t kStidShift = 21;  ///< 11-bit identifier in bits 31:21
inline constexpr uint32_t kExidShift = 3;   ///< 29-bit identifier in bits 31:3
inline constexpr uint32_t kStandardIdMask = 0x7FFU;
inline constexpr uint32_t kExtendedIdMask = 0x1FFFFFFFU;
}  // namespace ir

/// CAN_TDTxR and CAN_RDTxR.
namespace dtr {
inline constexpr uint32_t kDlcMask = 0xFU;  ///< data length code
inline constexpr uint32_t kTgt = 1U << 8;   ///< transmit global time (TTCM only)
inline constexpr uint32_t kFmiShift = 8;    ///< filter match index (receive, 8 bits)
inline constexpr uint32_t kTimeShift = 16;  ///< time stamp (16 bits)
}  // namespace dtr

namespace fmr {
inline constexpr uint32_t kFinit = 1U << 0;  ///< filter initialisation mode
inline constexpr uint32_t kCan2sbShift = 8;  ///< first filter bank of CAN2 (6 bits)
inline constexpr uint32_t kCan2sbMask = 0x3FU << kCan2sbShift;
}  // namespace fmr

}  // namespace bxcan
}  // namespace costa::port::stm32
