// Text in a buffer sized at compile time: the replay report and its verdicts without the heap.
// Appends that do not fit are cut (the text stays NUL-terminated).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/can_frame.hpp"

namespace costa::replay {

class Text {
 public:
  Text(const Text&) = delete;
  Text& operator=(const Text&) = delete;

  Text& append(const char* text) noexcept;
  Text& append(const char* text, size_t length) noexcept;
  Text& appendDecimal(uint64_t value) noexcept;
  /// Upper-case hexadecimal, at least `digits` digits (leading zeros).
  Text& appendHex(uint32_t value, unsigned digits) noexcept;
  /// A frame as traces and transcripts write it (targets/linux/frame_text.hpp):
  /// "601 [8] 40 08 10 00 00 00 00 00", "701 [0] RTR", "18FF0001 [2] 01 02".
  Text& appendFrame(const CanFrame& frame) noexcept;

  void clear() noexcept;
  const char* c_str() const noexcept { return chars_; }
  size_t length() const noexcept { return length_; }
  bool empty() const noexcept { return length_ == 0U; }

 protected:
  /// `capacity` counts the terminating NUL.
  Text(char* chars, size_t capacity) noexcept;
  ~Text() = default;

 private:
  char* chars_;
  size_t capacity_;
  size_t length_ = 0;
};

template <size_t N>
struct TextStorage {
  char chars[N];
};

/// Text of at most N - 1 characters.
template <size_t N>
class FixedText : private TextStorage<N>, public Text {
 public:
  FixedText() noexcept : Text(TextStorage<N>::chars, N) {}
};

}  // namespace costa::replay
