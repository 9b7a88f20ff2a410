// The simulation commands of a Santeng controller (costa-slave --control, transcript `sim`),
// parsed without the C++ library so that firmware replaying transcripts understands them too.
//
// The RS232 utility's settings (manual lines 114-132, errata B13, B14):
//   set node-id N                      1..126, from the next reset communication
//   set bit-rate KBITS                 1000 800 500 250 125 50 25 10, likewise
//   set heartbeat MS                   0..65535 (0x1017), at once
//   set tpdo-rate MS                   0..65535 (event timer of TPDO1..4), at once
//   set auto-start on|off              from the next boot-up
//   set mode C open-loop|speed|position   channel C (1, 2), at once
//   set max-rpm C RPM                  1..65535, at once
//   set encoder-lines C LINES          1..65535, at once
// The test bench (B9, B7):
//   fault overheat|overvoltage|undervoltage|short|sensor|mosfet on|off
//   stall C on|off                     channel C's motor is blocked
//   input N on|off                     digital input 1..32
//   output N on|off                    digital output 1..8
// Words and numbers are separated by white space; anything after the last argument is ignored.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa::santeng {

struct SantengControl {
  enum class Kind : uint8_t {
    kNodeId,
    kBitRate,
    kHeartbeat,
    kTpdoRate,
    kAutoStart,
    kMode,
    kMaxRpm,
    kEncoderLines,
    kFault,
    kStall,
    kInput,
    kOutput,
  };
  Kind kind = Kind::kNodeId;
  uint8_t channel = 0;  ///< 0 or 1 (C - 1) for channel settings and stall
  uint32_t number = 0;  ///< the setting's value; the mode (ChannelMode); the fault flags;
                        ///< the input or output number
  bool on = false;      ///< auto-start, fault, stall, input, output
};

/// Parses one command (NUL-terminated). On success returns true with `*control` set; otherwise
/// false with one line in `why`, written like snprintf (`why` may be null when whySize is 0).
bool parseSantengControl(const char* text, SantengControl* control, char* why,
                         size_t whySize) noexcept;

/// Santeng bit rate code of `kbits` (its index in kBitRates, the manual's list: 1000, 800, 500,
/// 250, 125, 50, 25, 10 kbit/s); -1 for a rate the controller does not have.
int santengBitRateCode(uint32_t kbits) noexcept;

}  // namespace costa::santeng
