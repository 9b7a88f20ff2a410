#include "fixed_text.hpp"

namespace costa::replay {

Text::Text(char* chars, size_t capacity) noexcept : chars_(chars), capacity_(capacity) {
  chars_[0] = '\0';
}

Text& Text::append(const char* text, size_t length) noexcept {
  for (size_t i = 0; i < length && length_ + 1U < capacity_; ++i) {
    chars_[length_++] = text[i];
  }
  chars_[length_] = '\0';
  return *this;
}

Text& Text::append(const char* text) noexcept {
  size_t length = 0;
  while (text[length] != '\0') {
    ++length;
  }
  return append(text, length);
}

Text& Text::appendDecimal(uint64_t value) noexcept {
  char digits[20];
  size_t count = 0;
  do {
    digits[sizeof(digits) - ++count] = static_cast<char>('0' + value % 10U);
    value /= 10U;
  } while (value != 0U);
  return append(digits + sizeof(digits) - count, count);
}

Text& Text::appendHex(uint32_t value, unsigned digits) noexcept {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  char text[8];
  size_t count = 0;
  do {
    text[sizeof(text) - ++count] = kDigits[value & 0xFU];
    value >>= 4U;
  } while ((value != 0U || count < digits) && count < sizeof(text));
  return append(text + sizeof(text) - count, count);
}

Text& Text::appendFrame(const CanFrame& frame) noexcept {
  appendHex(frame.id, frame.extended ? 8U : 3U);
  append(" [").appendDecimal(frame.dlc).append("]");
  if (frame.rtr) {
    return append(" RTR");
  }
  for (unsigned i = 0; i < frame.dlc && i < 8U; ++i) {
    append(" ").appendHex(frame.data[i], 2);
  }
  return *this;
}

void Text::clear() noexcept {
  length_ = 0;
  chars_[0] = '\0';
}

}  // namespace costa::replay
