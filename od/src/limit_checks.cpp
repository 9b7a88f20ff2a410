// The limit checks a Definition names (Definition::limitCheck). Built with function sections and
// linked with --gc-sections (as Costa's firmware toolchain files do), an image keeps only the
// one its dictionary names: none without limits, no floating-point code without a REAL entry
// that has limits.
#include "costa/od/bytes.hpp"
#include "costa/od/definition.hpp"
#include "costa/od/integer_limits.hpp"
#include "costa/od/little_endian.hpp"

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

}  // namespace

AbortCode checkIntegerLimits(DataType type, const uint8_t* source, size_t size,
                             const Limits& limits) noexcept {
  // (only checkLimits() checks REALs)
  return isReal(type) ? AbortCode::kNone
                      : integerLimitsVerdict(type, size, loadLittleEndian(source, size), limits);
}

AbortCode checkLimits(DataType type, const uint8_t* source, size_t size,
                      const Limits& limits) noexcept {
  return isReal(type) ? checkRealLimits(type, loadLittleEndian(source, size), limits)
                      : checkIntegerLimits(type, source, size, limits);
}

}  // namespace costa::od
