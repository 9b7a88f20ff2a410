// The limit check of REAL32/REAL64 entries, in its own unit so that only dictionaries with such
// an entry link floating-point code (Definition::realLimits).
#include "costa/od/bytes.hpp"
#include "costa/od/definition.hpp"

namespace costa::od {
namespace {

double toDouble(DataType type, uint64_t raw) noexcept {
  if (type == DataType::kReal32) {
    float f = 0.0F;
    const auto bits = static_cast<uint32_t>(raw);
    copyBytes(&f, &bits, 4);
    return static_cast<double>(f);
  }
  double d = 0.0;
  copyBytes(&d, &raw, 8);
  return d;
}

}  // namespace

AbortCode checkRealLimits(DataType type, uint64_t raw, const Limits& limits) noexcept {
  const double value = toDouble(type, raw);
  if (value != value) {  // NaN is in no range
    return AbortCode::kInvalidValue;
  }
  if (value > toDouble(DataType::kReal64, limits.high)) {
    return AbortCode::kValueTooHigh;
  }
  if (value < toDouble(DataType::kReal64, limits.low)) {
    return AbortCode::kValueTooLow;
  }
  return AbortCode::kNone;
}

}  // namespace costa::od
