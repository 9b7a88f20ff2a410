// A polled driver for one STM32 bxCAN controller (CAN1 of an STM32F4), at register level.
//
// Transmission: the three transmit mailboxes, sent in the order they were requested (TXFP), so
// frames leave in the node's queue order. Reception: every frame (standard and extended, data
// and remote) through filter bank 0 into FIFO 0, or once setFilters() has programmed them, the
// frames the node listens to (its acceptance filters). Status: error passive, bus-off and FIFO
// overrun are reported as CanControllerEvent values for Node::onControllerEvent(). Bus-off recovery
// is automatic (ABOM); the controller retransmits until a frame is acknowledged.
//
// Context: every member function is for the one context that runs the node (the main loop),
// with one exception: receive() may instead run in the FIFO 0 interrupt handler (FMPIE0 in
// CAN_IER), pushing into a CanFrameRing that the main loop empties, as long as nothing else
// calls receive(). receive() and poll() may then interrupt each other: each writes RF0R only
// with the one write-1 bit it acts on (RFOM0, FOVR0), and the other bits ignore a 0. Apart from
// that, no member may run while another is running. The driver enables no interrupt itself.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_controller_event.hpp"
#include "costa/port/can_id_filter.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/stm32/bxcan_registers.hpp"

namespace costa::port::stm32 {

/// The controller events found by one BxCanPort::poll(), in the order they happened (at most
/// one overrun and two error state changes).
using BxCanEvents = CanControllerEvents<3>;

class BxCanPort final : public CanTransmitter, public CanBitRateControl {
 public:
  /// Bound on status reads while start() waits for the controller. At 168 MHz one read and the
  /// loop around it take some tens of nanoseconds, so the default allows some tens of
  /// milliseconds: enough to finish a frame in progress at 10 kbit/s before the controller
  /// enters initialisation, and to see the bus idle (11 recessive bits) when it leaves.
  static constexpr uint32_t kDefaultWaitLimit = 1000000;

  /// Called once per status read while start() waits. Firmware may kick a watchdog here; host
  /// tests play the hardware's part.
  using WaitHook = void (*)(void* context);

  /// `registers` is the controller's block: `bxCan1()` in firmware, a simulated block in tests.
  /// Nothing is touched until start().
  explicit BxCanPort(BxCanRegisters& registers, uint32_t waitLimit = kDefaultWaitLimit) noexcept
      : registers_(registers), waitLimit_(waitLimit) {}

  void setWaitHook(WaitHook hook, void* context) noexcept {
    waitHook_ = hook;
    waitContext_ = context;
  }

  /// Configures the controller and joins the bus:
  ///   1. leaves sleep mode and requests initialisation; waits for INAK (bounded);
  ///   2. MCR: automatic bus-off management, automatic retransmission, transmit order by
  ///      request, FIFO not locked (when FIFO 0 is full, a new message overwrites the last one
  ///      stored: reported as overrun); the debug freeze bit (DBF) is kept as it was;
  ///   3. CAN_BTR = `btr` (see bxcan_bit_timing.hpp; loop back and silent bits are passed on);
  ///   4. filter bank 0: 32-bit mask mode, identifier 0, mask 0 (accept all), FIFO 0, active;
  ///      the other banks and CAN2's start bank are left as they are;
  ///   5. leaves initialisation; waits until the controller has seen the bus idle (bounded).
  /// Returns false when the controller did not acknowledge step 1 (no clock to the
  /// peripheral?) or did not join the bus in step 5 (CANRX held dominant: transceiver missing
  /// or unpowered?). In the second case it joins as soon as the bus goes idle. May be called
  /// again to restart; the error state the driver remembers is reset to error active.
  /// `clockHz` is the APB1 clock `btr` was computed for; setBitRate() needs it (0: unknown,
  /// setBitRate() refuses).
  bool start(uint32_t btr, uint32_t clockHz = 0) noexcept;

  /// Re-times the running controller (the node's CanBitRateControl: LSS activate bit timing,
  /// a stored bit timing at reset communication):
  ///   1. computes CAN_BTR for `bitsPerSecond` from start()'s clock (bxCanBitTiming());
  ///   2. requests initialisation and waits for INAK (bounded; a frame in progress ends first);
  ///   3. writes CAN_BTR, keeping its loop back and silent bits;
  ///   4. leaves initialisation without waiting: the controller joins the bus by itself once it
  ///      has seen it idle at the new rate, and sends what its mailboxes hold from then on.
  /// Returns false, touching nothing, before a start() that reached initialisation, without a
  /// clock, or when the clock cannot produce the rate exactly (800 kbit/s from 42 MHz); false
  /// with the old timing kept when the controller does not acknowledge step 2 (the request is
  /// withdrawn). Filters, MCR and the remembered error state are kept.
  bool setBitRate(uint32_t bitsPerSecond) noexcept override;

  /// Programs acceptance filters (Node::receiveFilters()) into CAN1's filter banks, those below
  /// CAN2SB (FMR; 14 after reset): two filters per bank in 16-bit mask mode, each taking the
  /// standard data and remote frames whose identifier agrees with its own in the mask's bits,
  /// into FIFO 0; extended frames pass none. An odd last filter fills both halves of its bank.
  /// Banks beyond those used are deactivated; CAN2's banks are left as they are. With more
  /// filters than 2 x banks (28 after reset) it accepts every frame, as start() does, and
  /// returns false; true when the banks hold exactly `filters`. Reception pauses while the
  /// banks are written (FINIT). Call it after start(), from the node's context, whenever
  /// Node::receiveFiltersVersion() changed.
  bool setFilters(const CanIdFilter* filters, size_t count) noexcept;
  /// Accepts every frame into FIFO 0 again, as after start(): bank 0 accepts all, CAN1's other
  /// banks are deactivated.
  void acceptAllFrames() noexcept;

  /// Hands `frame` to a free transmit mailbox and requests its transmission. False, touching
  /// nothing, when all three mailboxes are pending. A DLC above 8 is sent as 8.
  bool tryTransmit(const CanFrame& frame) noexcept override;

  /// Takes the oldest message out of receive FIFO 0 and releases it. False when the FIFO is
  /// empty. Data bytes at and after the DLC (all of them for a remote frame) are zero; a DLC
  /// above 8 is passed on as received (the stack ignores such frames).
  bool receive(CanFrame* frame) noexcept;

  /// Reads the error state and FIFO 0 and returns what changed since the last poll() (or
  /// start()): kRxOverrun when a message was lost (the flag is then cleared), kErrorPassive /
  /// kErrorActive when EPVF rose / fell, kBusOff / kBusOffRecovered when BOFF rose / fell.
  /// Within one poll: overrun first, then recovery from bus-off, then the error passive change,
  /// then bus-off. Call it at least every 128 x 11 bit times (1.4 ms at 1 Mbit/s) so that a
  /// bus-off and its automatic recovery are not both missed.
  BxCanEvents poll() noexcept;

 private:
  bool waitForStatus(uint32_t mask, uint32_t expected) noexcept;
  void acceptEverythingIntoFifo0() noexcept;
  /// The banks of CAN1 (below CAN2SB) as a bit mask.
  uint32_t ownBanks() const noexcept;

  BxCanRegisters& registers_;
  uint32_t waitLimit_;
  WaitHook waitHook_ = nullptr;
  void* waitContext_ = nullptr;
  uint32_t clockHz_ = 0;
  bool configured_ = false;  ///< start() has written CAN_BTR
  bool errorPassive_ = false;
  bool busOff_ = false;
};

}  // namespace costa::port::stm32
