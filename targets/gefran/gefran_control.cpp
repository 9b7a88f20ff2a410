#include "gefran_control.hpp"

#include "angle_model.hpp"
#include "decimal_number.hpp"

namespace costa::gefran {
namespace {

/// Largest raw reading of a 14-bit chip.
constexpr int64_t kLargestRaw = 16383;
/// Larger angles are refused: rawFromDegrees() needs the number of turns to fit an int64_t.
constexpr double kLargestDegrees = 1e18;

/// A word: the characters up to the next white space (empty at the end of the text).
struct Word {
  const char* begin;
  size_t length;

  bool is(const char* literal) const noexcept {
    size_t i = 0;
    for (; i < length; ++i) {
      if (literal[i] != begin[i]) {
        return false;
      }
    }
    return literal[i] == '\0';
  }
};

/// Reads the next word after white space; `*text` moves past it.
Word nextWord(const char** text) noexcept {
  const char* begin = skipSpace(*text);
  const char* end = begin;
  while (*end != '\0' && !isSpace(*end)) {
    ++end;
  }
  *text = end;
  return Word{begin, static_cast<size_t>(end - begin)};
}

/// Reads a raw reading after white space; false when there is none or it is out of range.
bool nextRaw(const char** text, uint16_t* raw) noexcept {
  int64_t value = -1;
  const char* end = parseInteger(skipSpace(*text), &value);
  if (end == nullptr || value < 0 || value > kLargestRaw) {
    return false;
  }
  *text = end;
  *raw = static_cast<uint16_t>(value);
  return true;
}

ControlError parseRaw(const char* text, ControlCommand* command) noexcept {
  command->kind = ControlCommand::Kind::kSetRaw;
  if (!nextRaw(&text, &command->chip1) || !nextRaw(&text, &command->chip2)) {
    return ControlError::kRawUsage;
  }
  return ControlError::kNone;
}

ControlError parseAngle(const char* text, ControlCommand* command) noexcept {
  double degrees = 0;
  if (parseDecimal(skipSpace(text), &degrees) == nullptr || !(degrees < kLargestDegrees) ||
      !(degrees > -kLargestDegrees)) {
    return ControlError::kAngleUsage;
  }
  command->kind = ControlCommand::Kind::kSetRaw;
  command->chip1 = rawFromDegrees(degrees);
  command->chip2 = command->chip1;
  return ControlError::kNone;
}

ControlError parseFault(const char* text, ControlCommand* command) noexcept {
  const Word what = nextWord(&text);
  const Word state = nextWord(&text);
  const uint8_t bits = what.is("chip1")    ? kChip1Error
                       : what.is("chip2")  ? kChip2Error
                       : what.is("magnet") ? kMagneticField
                                           : 0;
  if (bits == 0U || (!state.is("on") && !state.is("off"))) {
    return ControlError::kFaultUsage;
  }
  command->kind = ControlCommand::Kind::kSetFault;
  command->faultBits = bits;
  command->faultOn = state.is("on");
  return ControlError::kNone;
}

/// Appends to a message written like snprintf.
class MessageWriter {
 public:
  MessageWriter(char* out, size_t size) noexcept : out_(out), size_(size) {}
  void append(const char* text, size_t length) noexcept {
    for (size_t i = 0; i < length; ++i) {
      if (length_ + 1U < size_) {
        out_[length_] = text[i];
      }
      ++length_;
    }
  }
  void append(const char* text) noexcept {
    size_t length = 0;
    while (text[length] != '\0') {
      ++length;
    }
    append(text, length);
  }
  size_t finish() noexcept {
    if (size_ > 0U) {
      out_[length_ < size_ ? length_ : size_ - 1U] = '\0';
    }
    return length_;
  }

 private:
  char* out_;
  size_t size_;
  size_t length_ = 0;
};

}  // namespace

ParsedControl parseControl(const char* text) noexcept {
  ParsedControl parsed;
  const Word verb = nextWord(&text);
  parsed.verb = verb.begin;
  parsed.verbLength = verb.length;
  if (verb.is("raw")) {
    parsed.error = parseRaw(text, &parsed.command);
  } else if (verb.is("angle")) {
    parsed.error = parseAngle(text, &parsed.command);
  } else if (verb.is("fault")) {
    parsed.error = parseFault(text, &parsed.command);
  } else {
    parsed.error = ControlError::kUnknownCommand;
  }
  return parsed;
}

void applyControl(const ControlCommand& command, SimulatedHallSensors& sensors) noexcept {
  if (command.kind == ControlCommand::Kind::kSetRaw) {
    sensors.setRaw(command.chip1, command.chip2);
  } else {
    sensors.setFault(command.faultBits, command.faultOn);
  }
}

size_t describeControlError(const ParsedControl& parsed, char* out, size_t size) noexcept {
  MessageWriter message(out, size);
  switch (parsed.error) {
    case ControlError::kNone: break;
    case ControlError::kRawUsage: message.append("usage: raw A B (0..16383)"); break;
    case ControlError::kAngleUsage: message.append("usage: angle DEGREES"); break;
    case ControlError::kFaultUsage: message.append("usage: fault chip1|chip2|magnet on|off"); break;
    case ControlError::kUnknownCommand:
      message.append("unknown command '");
      message.append(parsed.verb, parsed.verbLength);
      message.append("' (raw, angle, fault)");
      break;
  }
  return message.finish();
}

}  // namespace costa::gefran
