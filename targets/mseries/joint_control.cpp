#include "joint_control.hpp"

namespace costa::mseries {
namespace {

constexpr const char* kUsage =
    "usage: position N | dir on|off | pu on|off | alarm 0x10|0x12|0x14 | voltage 0..100";

bool isSpace(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

const char* skipSpace(const char* text) noexcept {
  while (isSpace(*text)) {
    ++text;
  }
  return text;
}

/// Reads the next word; `*text` moves past it. Returns its length.
size_t nextWord(const char** text, const char** word) noexcept {
  const char* begin = skipSpace(*text);
  const char* end = begin;
  while (*end != '\0' && !isSpace(*end)) {
    ++end;
  }
  *word = begin;
  *text = end;
  return static_cast<size_t>(end - begin);
}

bool is(const char* word, size_t length, const char* literal) noexcept {
  size_t i = 0;
  for (; i < length; ++i) {
    if (literal[i] != word[i]) {
      return false;
    }
  }
  return literal[i] == '\0';
}

int digitOf(char c, unsigned base) noexcept {
  int digit = -1;
  if (c >= '0' && c <= '9') {
    digit = c - '0';
  } else if (c >= 'a' && c <= 'f') {
    digit = c - 'a' + 10;
  } else if (c >= 'A' && c <= 'F') {
    digit = c - 'A' + 10;
  }
  return digit >= 0 && static_cast<unsigned>(digit) < base ? digit : -1;
}

/// A whole word as an integer (decimal with an optional '-', or 0x hexadecimal) within
/// [low, high]; false otherwise.
bool parseNumber(const char* word, size_t length, int64_t low, int64_t high,
                 int64_t* value) noexcept {
  size_t i = 0;
  bool negative = false;
  unsigned base = 10;
  if (i < length && word[i] == '-') {
    negative = true;
    ++i;
  } else if (length > 2U && word[0] == '0' && (word[1] == 'x' || word[1] == 'X')) {
    base = 16;
    i = 2;
  }
  if (i == length) {
    return false;
  }
  int64_t magnitude = 0;
  for (; i < length; ++i) {
    const int digit = digitOf(word[i], base);
    if (digit < 0 || magnitude > (int64_t{1} << 40)) {
      return false;
    }
    magnitude = magnitude * base + digit;
  }
  const int64_t number = negative ? -magnitude : magnitude;
  if (number < low || number > high) {
    return false;
  }
  *value = number;
  return true;
}

JointControl refused() noexcept {
  JointControl control;
  control.error = kUsage;
  return control;
}

}  // namespace

JointControl parseJointControl(const char* text) noexcept {
  const char* verb = nullptr;
  const size_t verbLength = nextWord(&text, &verb);
  const char* argument = nullptr;
  const size_t argumentLength = nextWord(&text, &argument);
  const char* extra = nullptr;
  if (nextWord(&text, &extra) != 0U) {
    return refused();
  }
  JointControl control;
  if (is(verb, verbLength, "position")) {
    control.kind = JointControl::Kind::kPosition;
    if (!parseNumber(argument, argumentLength, INT32_MIN, INT32_MAX, &control.value)) {
      return refused();
    }
  } else if (is(verb, verbLength, "dir") || is(verb, verbLength, "pu")) {
    control.kind = is(verb, verbLength, "dir") ? JointControl::Kind::kDir : JointControl::Kind::kPu;
    if (!is(argument, argumentLength, "on") && !is(argument, argumentLength, "off")) {
      return refused();
    }
    control.value = is(argument, argumentLength, "on") ? 1 : 0;
  } else if (is(verb, verbLength, "alarm")) {
    control.kind = JointControl::Kind::kAlarm;
    if (!parseNumber(argument, argumentLength, 0, 0xFF, &control.value) ||
        (control.value != 0x10 && control.value != 0x12 && control.value != 0x14)) {
      return refused();
    }
  } else if (is(verb, verbLength, "voltage")) {
    control.kind = JointControl::Kind::kVoltage;
    if (!parseNumber(argument, argumentLength, 0, 100, &control.value)) {
      return refused();
    }
  } else {
    return refused();
  }
  return control;
}

}  // namespace costa::mseries
