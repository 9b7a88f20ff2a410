// Bit timing of a bxCAN controller (CAN_BTR), computed at compile time from the peripheral clock
// and the bit rate.
//
// RM0090 "Bit timing": a bit is 1 + BS1 + BS2 time quanta (tq), tq = prescaler / f(APB1);
// BS1 = 1..16 tq, BS2 = 1..8 tq, SJW = 1..4 tq, prescaler = 1..1024. The sample point lies
// after BS1: (1 + BS1) / (1 + BS1 + BS2) of the bit.
#pragma once

#include <stdint.h>

#include "costa/port/can_bit_rate.hpp"
#include "costa/port/stm32/bxcan_registers.hpp"

namespace costa::port::stm32 {

/// One bit timing, in time quanta. `prescaler == 0` means "no valid timing".
struct BxCanBitTiming {
  uint16_t prescaler = 0;  ///< APB1 clocks per time quantum, 1..1024.
  uint8_t segment1 = 0;    ///< BS1 in tq (propagation + phase 1), 1..16.
  uint8_t segment2 = 0;    ///< BS2 in tq (phase 2), 1..8.
  uint8_t jumpWidth = 0;   ///< SJW in tq, 1..4.

  constexpr bool valid() const noexcept { return prescaler != 0; }
  constexpr uint32_t quantaPerBit() const noexcept { return 1U + segment1 + segment2; }
  /// Sample point in per mille of the bit time, rounded down.
  constexpr uint32_t samplePointPermille() const noexcept {
    return (1U + segment1) * 1000U / quantaPerBit();
  }
  /// The CAN_BTR value (normal mode: no loop back, not silent). Zero when not valid.
  constexpr uint32_t btr() const noexcept {
    if (!valid()) {
      return 0;
    }
    return ((uint32_t{jumpWidth} - 1U) << bxcan::btr::kSjwShift) |
           ((uint32_t{segment2} - 1U) << bxcan::btr::kTs2Shift) |
           ((uint32_t{segment1} - 1U) << bxcan::btr::kTs1Shift) |
           ((uint32_t{prescaler} - 1U) << bxcan::btr::kBrpShift);
  }
};

namespace detail {
inline constexpr uint32_t kMinQuanta = 4;  // 1 + BS1 (1) + BS2 (2)
inline constexpr uint32_t kMaxQuanta = 25;
inline constexpr uint32_t kMaxSegment1 = 16;
inline constexpr uint32_t kMinSegment2 = 2;
inline constexpr uint32_t kMaxSegment2 = 8;
inline constexpr uint32_t kMaxJumpWidth = 4;
inline constexpr uint32_t kMaxPrescaler = 1024;

constexpr uint32_t distance(uint32_t a, uint32_t b) noexcept {
  return a > b ? a - b : b - a;
}
}  // namespace detail

/// The timing that produces `bitRate` exactly from `clockHz` (the APB1 clock) with the sample
/// point closest to `samplePointPermille` (default 875: 87.5 %, as CiA 301 recommends).
///
/// Rules: the bit rate must be exact (clockHz = bitRate x prescaler x quanta per bit), else the
/// result is not valid; BS2 is at least 2 tq, so that phase segment 2 is never shorter than the
/// information processing time; SJW = min(BS2, 4). Among equally close sample points, more
/// quanta per bit win (finer resynchronisation), then the earlier sample point (longer BS2).
constexpr BxCanBitTiming bxCanBitTiming(uint32_t clockHz, uint32_t bitRate,
                                        uint32_t samplePointPermille = 875) noexcept {
  BxCanBitTiming best{};
  if (bitRate == 0 || clockHz % bitRate != 0 || samplePointPermille >= 1000) {
    return best;
  }
  const uint32_t clocksPerBit = clockHz / bitRate;  // = prescaler x quanta per bit
  // How far a sample point lies from the target: error / quanta per mille of the bit.
  uint32_t bestError = 0;
  uint32_t bestQuanta = 0;
  for (uint32_t quanta = detail::kMaxQuanta; quanta >= detail::kMinQuanta; --quanta) {
    if (clocksPerBit % quanta != 0) {
      continue;
    }
    const uint32_t prescaler = clocksPerBit / quanta;
    if (prescaler > detail::kMaxPrescaler) {
      continue;
    }
    for (uint32_t segment2 = detail::kMaxSegment2; segment2 >= detail::kMinSegment2; --segment2) {
      if (segment2 + 2U > quanta) {
        continue;  // BS1 would be shorter than 1 tq
      }
      const uint32_t segment1 = quanta - 1U - segment2;
      if (segment1 > detail::kMaxSegment1) {
        continue;
      }
      const uint32_t error =
          detail::distance((1U + segment1) * 1000U, samplePointPermille * quanta);
      // error / quanta < bestError / bestQuanta, without division.
      if (!best.valid() || error * bestQuanta < bestError * quanta) {
        best.prescaler = static_cast<uint16_t>(prescaler);
        best.segment1 = static_cast<uint8_t>(segment1);
        best.segment2 = static_cast<uint8_t>(segment2);
        best.jumpWidth = static_cast<uint8_t>(
            segment2 < detail::kMaxJumpWidth ? segment2 : detail::kMaxJumpWidth);
        bestError = error;
        bestQuanta = quanta;
      }
    }
  }
  return best;
}

/// The CiA 305 table (LSS "configure bit timing", table selector 0) is the stack's:
/// costa::cia305BitRate() in costa/port/can_bit_rate.hpp.
using costa::cia305BitRate;

/// Timing for an entry of the CiA 305 table (LSS "configure bit timing", table selector 0).
/// Not valid when the entry has no bit rate or the clock cannot produce it exactly: an LSS
/// slave answers such a request with error code 1 (bit timing not supported).
constexpr BxCanBitTiming bxCanBitTimingForCia305Index(uint32_t clockHz,
                                                      uint8_t tableIndex) noexcept {
  const uint32_t bitRate = cia305BitRate(tableIndex);
  return bitRate == 0 ? BxCanBitTiming{} : bxCanBitTiming(clockHz, bitRate);
}

namespace detail {
/// The timing is valid, produces the bit rate exactly and samples within 85..90 %.
constexpr bool exactNear875(uint32_t clockHz, uint32_t bitRate) noexcept {
  const BxCanBitTiming timing = bxCanBitTiming(clockHz, bitRate);
  return timing.valid() &&
         uint64_t{timing.prescaler} * timing.quantaPerBit() * bitRate == clockHz &&
         timing.samplePointPermille() >= 850 && timing.samplePointPermille() <= 900;
}
}  // namespace detail

// APB1 at 42 MHz (STM32F405/407 at 168 MHz) and 36 MHz (at 144 MHz, or an F1 at 72 MHz).
static_assert(detail::exactNear875(42000000, 1000000));
static_assert(detail::exactNear875(42000000, 500000));
static_assert(detail::exactNear875(42000000, 250000));
static_assert(detail::exactNear875(42000000, 125000));
static_assert(detail::exactNear875(42000000, 50000));
static_assert(detail::exactNear875(42000000, 20000));
static_assert(detail::exactNear875(42000000, 10000));
// 42 MHz / 800 kbit/s = 52.5 APB1 clocks per bit: no integer prescaler and quanta produce it.
static_assert(!bxCanBitTiming(42000000, 800000).valid());
static_assert(detail::exactNear875(36000000, 1000000));
static_assert(detail::exactNear875(36000000, 800000));
static_assert(detail::exactNear875(36000000, 500000));
static_assert(detail::exactNear875(36000000, 250000));
static_assert(detail::exactNear875(36000000, 125000));
static_assert(detail::exactNear875(36000000, 50000));
static_assert(detail::exactNear875(36000000, 20000));
static_assert(detail::exactNear875(36000000, 10000));
// 16 MHz (HSI after reset, as the example firmware runs).
static_assert(detail::exactNear875(16000000, 250000));

}  // namespace costa::port::stm32
