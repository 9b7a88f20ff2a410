// The text form of a CAN frame used by traces and transcripts:
//   601 [8] 40 08 10 00 00 00 00 00
//   701 [0] RTR
//   18FF0001 [2] 01 02          (29-bit identifiers have 8 hex digits)
#pragma once

#include <string>

#include "costa/port/can_frame.hpp"

namespace costa::host {

std::string formatFrame(const CanFrame& frame);

/// Parses the text form. `wildcards`, when given, receives a bit per data byte written as `xx`
/// (such bytes parse as 0). Returns false with a reason in `error` on malformed text.
bool parseFrame(const std::string& text, CanFrame* frame, std::string* error,
                unsigned* wildcards = nullptr);

/// True when `actual` matches `expected` except in the data bytes flagged in `wildcards`.
bool matchesFrame(const CanFrame& expected, unsigned wildcards, const CanFrame& actual);

}  // namespace costa::host
