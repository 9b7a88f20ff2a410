#include "costa/od/object_dictionary.hpp"

namespace costa::od {

Scalar ObjectDictionary::scalar(const EntryRef& ref) const noexcept {
  Scalar scalar;
  if (!ref.valid()) {
    return scalar;
  }
  scalar.flags_ = Scalar::kPresent;
  const DataType type = ref.type();
  if (!isSigned(type) && !isUnsigned(type)) {
    return scalar;  // size 0: reads as 0, stores nothing
  }
  scalar.offset_ = ref.offset();
  scalar.size_ = static_cast<uint8_t>(ref.size());  // an integer or boolean row has 1 to 8 bytes
  if (isSigned(type)) {
    scalar.flags_ |= Scalar::kSigned;
  }
  if (ref.inRom()) {
    scalar.flags_ |= Scalar::kInRom;
    if (ref.has(kNodeIdRelative)) {  // a constant without the node-id
      scalar.flags_ |= Scalar::kAddsNodeId;
    }
  }
  return scalar;
}

uint64_t ObjectDictionary::readScalar(const Scalar& scalar) const noexcept {
  const uint8_t* block = (scalar.flags_ & Scalar::kInRom) != 0U
                             ? static_cast<const uint8_t*>(definition_->constants)
                             : values_;
  uint64_t raw = loadNative(block + scalar.offset_, scalar.size_);
  if ((scalar.flags_ & Scalar::kAddsNodeId) != 0U) {
    raw += nodeId_;
    if (scalar.size_ < 8U) {  // within the value's width, as it goes on the wire
      const auto low = static_cast<uint32_t>(raw);
      raw = scalar.size_ >= 4U ? low : low & ((1U << (8U * scalar.size_)) - 1U);
    }
  }
  return (scalar.flags_ & Scalar::kSigned) != 0U
             ? static_cast<uint64_t>(signExtend(raw, scalar.size_))
             : raw;
}

void ObjectDictionary::storeScalar(const Scalar& scalar, uint64_t value) noexcept {
  if ((scalar.flags_ & Scalar::kInRom) == 0U) {
    storeNative(values_ + scalar.offset_, value, scalar.size_);
  }
}

}  // namespace costa::od
