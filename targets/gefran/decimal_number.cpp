#include "decimal_number.hpp"

#include <float.h>
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

/// The digits of a number, with at most one '.' among them.
struct Digits {
  uint64_t mantissa = 0;
  int exponent = 0;  ///< of the last digit kept in `mantissa`
  bool any = false;
};

/// Reads digits and an optional '.'; `*text` moves past them.
Digits readDigits(const char** text) noexcept {
  Digits digits;
  bool fraction = false;
  const char* at = *text;
  for (;; ++at) {
    if (*at == '.' && !fraction) {
      fraction = true;
      continue;
    }
    if (!isDigit(*at)) {
      break;
    }
    digits.any = true;
    if (digits.mantissa <= (UINT64_MAX - 9U) / 10U) {
      digits.mantissa = digits.mantissa * 10U + digitOf(*at);
      digits.exponent -= fraction ? 1 : 0;
    } else {
      digits.exponent += fraction ? 0 : 1;  // a digit beyond what the mantissa holds: dropped
    }
  }
  *text = at;
  return digits;
}

/// Reads an exponent after its 'e': optional sign, at least one digit. Returns the first
/// character after it, or nullptr when there is no digit. Exponents beyond kExponentLimit are
/// read as about kExponentLimit * 10, which over- or underflows just the same.
const char* parseExponent(const char* text, int* exponent) noexcept {
  const bool negative = *text == '-';
  if (*text == '+' || *text == '-') {
    ++text;
  }
  if (!isDigit(*text)) {
    return nullptr;
  }
  int written = 0;
  for (; isDigit(*text); ++text) {
    if (written <= kExponentLimit) {
      written = written * 10 + static_cast<int>(digitOf(*text));
    }
  }
  *exponent = negative ? -written : written;
  return text;
}

}  // namespace

const char* skipSpace(const char* text) noexcept {
  while (isSpace(*text)) {
    ++text;
  }
  return text;
}

const char* parseInteger(const char* text, int64_t* value) noexcept {
  const bool negative = *text == '-';
  if (*text == '+' || *text == '-') {
    ++text;
  }
  if (!isDigit(*text)) {
    return nullptr;
  }
  // Accumulated as a negative number: INT64_MIN has no positive counterpart.
  int64_t result = 0;
  for (; isDigit(*text); ++text) {
    const auto digit = static_cast<int64_t>(digitOf(*text));
    if (result < (INT64_MIN + digit) / 10) {
      return nullptr;
    }
    result = result * 10 - digit;
  }
  if (!negative) {
    if (result == INT64_MIN) {
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
  const Digits digits = readDigits(&text);
  if (!digits.any) {
    return nullptr;
  }
  const uint64_t mantissa = digits.mantissa;
  int exponent = digits.exponent;
  if (*text == 'e' || *text == 'E') {
    int written = 0;
    text = parseExponent(text + 1, &written);
    if (text == nullptr) {
      return nullptr;  // "1e", "1e+": the stream fails too
    }
    exponent += written;
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
