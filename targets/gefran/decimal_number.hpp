// Decimal numbers read from text the way C++ stream extraction (`std::istream >> x`) reads them,
// without the C++ library: for the simulation commands, on firmware as in costa-slave.
#pragma once

#include <stdint.h>

namespace costa::gefran {

/// True for the characters `std::isspace` accepts in the "C" locale.
constexpr bool isSpace(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/// First character at or after `text` that is not white space.
const char* skipSpace(const char* text) noexcept;

/// Reads an integer at `text` (no leading white space): optional sign, then decimal digits, as
/// far as they go. Returns the first character after it, or nullptr when there is no digit or
/// the value does not fit an int64_t.
const char* parseInteger(const char* text, int64_t* value) noexcept;

/// Reads a number at `text` (no leading white space): optional sign, digits with an optional
/// '.' and fraction (at least one digit in all), optional exponent ('e' or 'E', optional sign,
/// at least one digit). Returns the first character after it, or nullptr when there is no
/// number or it overflows a double. The result is the correctly rounded double (as strtod
/// gives) for up to 15 significant digits and exponents within +-22; beyond that it may differ
/// from strtod in the last bit.
const char* parseDecimal(const char* text, double* value) noexcept;

}  // namespace costa::gefran
