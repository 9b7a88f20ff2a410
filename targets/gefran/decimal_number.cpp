#include "decimal_number.hpp"

#include <float.h>
#include <limits.h>
#include <stdint.h>

namespace costa::gefran {
namespace {

constexpr bool isDigit(char c) noexcept {
  return c >= '0' && c <= '9';
}

constexpr unsigned digitOf(char c) noexcept {
  return static_cast<unsigned>(c - '0');
}

/// Powers of ten that a double holds exactly.
constexpr double kExactPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                   1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kLargestExactPower = 22;
/// Mantissas up to 2^53 convert to double exactly.
constexpr uint64_t kLargestExactMantissa = uint64_t{1} << 53U;
/// Beyond these decimal exponents every non-zero mantissa overflows or underflows a double.
constexpr int kExponentLimit = 400;

/// mantissa * 10^exponent, rounded once where both factors are exact, else step by step.
double scale(uint64_t mantissa, int exponent) noexcept {
  auto result = static_cast<double>(mantissa);
  if (mantissa <= kLargestExactMantissa && exponent >= -kLargestExactPower &&
      exponent <= kLargestExactPower) {
    return exponent < 0 ? result / kExactPowers[-exponent] : result * kExactPowers[exponent];
  }
  for (; exponent > 0; --exponent) {
    result *= 10.0;
  }
  for (; exponent < 0; ++exponent) {
    result /= 10.0;
  }
  return result;
}

}  // namespace

const char* skipSpace(const char* text) noexcept {
  while (isSpace(*text)) {
    ++text;
  }
  return text;
}

const char* parseInteger(const char* text, long* value) noexcept {
  const bool negative = *text == '-';
  if (*text == '+' || *text == '-') {
    ++text;
  }
  if (!isDigit(*text)) {
    return nullptr;
  }
  // Accumulated as a negative number: LONG_MIN has no positive counterpart.
  long result = 0;
  for (; isDigit(*text); ++text) {
    const auto digit = static_cast<long>(digitOf(*text));
    if (result < (LONG_MIN + digit) / 10) {
      return nullptr;
    }
    result = result * 10 - digit;
  }
  if (!negative) {
    if (result == LONG_MIN) {
      return nullptr;
    }
    result = -result;
  }
  *value = result;
  return text;
}

const char* parseDecimal(const char* text, double* value) noexcept {
  const bool negative = *text == '-';
  if (*text == '+' || *text == '-') {
    ++text;
  }
  uint64_t mantissa = 0;
  int exponent = 0;  // of the last digit kept in `mantissa`
  bool anyDigit = false;
  bool fraction = false;
  for (;; ++text) {
    if (*text == '.' && !fraction) {
      fraction = true;
      continue;
    }
    if (!isDigit(*text)) {
      break;
    }
    anyDigit = true;
    if (mantissa <= (UINT64_MAX - 9U) / 10U) {
      mantissa = mantissa * 10U + digitOf(*text);
      exponent -= fraction ? 1 : 0;
    } else {
      exponent += fraction ? 0 : 1;  // a digit beyond what the mantissa holds: dropped
    }
  }
  if (!anyDigit) {
    return nullptr;
  }
  if (*text == 'e' || *text == 'E') {
    ++text;
    const bool negativeExponent = *text == '-';
    if (*text == '+' || *text == '-') {
      ++text;
    }
    if (!isDigit(*text)) {
      return nullptr;  // "1e", "1e+": the stream fails too
    }
    int written = 0;
    for (; isDigit(*text); ++text) {
      if (written <= kExponentLimit) {
        written = written * 10 + static_cast<int>(digitOf(*text));
      }
    }
    exponent += negativeExponent ? -written : written;
  }
  double result = 0.0;
  if (mantissa != 0U && exponent > kExponentLimit) {
    return nullptr;
  }
  if (mantissa != 0U && exponent >= -kExponentLimit) {
    result = scale(mantissa, exponent);
    if (result > DBL_MAX) {
      return nullptr;
    }
  }
  *value = negative ? -result : result;
  return text;
}

}  // namespace costa::gefran
