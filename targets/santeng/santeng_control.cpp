#include "santeng_control.hpp"

#include "device_control.hpp"
#include "power_stage.hpp"
#include "santeng_profile.hpp"

namespace costa::santeng {
namespace {

constexpr const char* kUnknownHead = "unknown command '";
constexpr const char* kUnknownTail = "' (set, fault, stall, input, output)";

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// A word: the characters up to the next white space (empty at the end of the text).
struct Word {
  const char* begin = "";
  size_t length = 0;

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

class Reader {
 public:
  explicit Reader(const char* text) noexcept : text_(text) {}

  Word word() noexcept {
    while (isSpace(*text_)) {
      ++text_;
    }
    Word w;
    w.begin = text_;
    while (*text_ != '\0' && !isSpace(*text_)) {
      ++text_;
    }
    w.length = static_cast<size_t>(text_ - w.begin);
    return w;
  }

  /// A decimal number of at most `largest`, as a whole word; false otherwise.
  bool number(uint32_t largest, uint32_t* value) noexcept {
    const Word w = word();
    if (w.length == 0U) {
      return false;
    }
    uint32_t n = 0;
    for (size_t i = 0; i < w.length; ++i) {
      const char c = w.begin[i];
      if (c < '0' || c > '9' || n > largest / 10U) {
        return false;
      }
      n = n * 10U + static_cast<uint32_t>(c - '0');  // at most largest + 9: no overflow
      if (n > largest) {
        return false;
      }
    }
    *value = n;
    return true;
  }

  /// on or off.
  bool state(bool* on) noexcept {
    const Word w = word();
    *on = w.is("on");
    return *on || w.is("off");
  }

  /// A channel, 1 or 2, as its index.
  bool channel(uint8_t* index) noexcept {
    uint32_t n = 0;
    if (!number(kChannels, &n) || n == 0U) {
      return false;
    }
    *index = static_cast<uint8_t>(n - 1U);
    return true;
  }

 private:
  const char* text_;
};

uint8_t faultBits(const Word& name) {
  return name.is("overheat")       ? kOverheat
         : name.is("overvoltage")  ? kOvervoltage
         : name.is("undervoltage") ? kUndervoltage
         : name.is("short")        ? kShortCircuit
         : name.is("sensor")       ? kSensorFault
         : name.is("mosfet")       ? kMosfetFailure
                                   : 0;
}

bool parseMode(Reader& reader, SantengControl* control) {
  if (!reader.channel(&control->channel)) {
    return false;
  }
  const Word mode = reader.word();
  if (mode.is("open-loop")) {
    control->number = static_cast<uint32_t>(ChannelMode::kOpenLoopSpeed);
  } else if (mode.is("speed")) {
    control->number = static_cast<uint32_t>(ChannelMode::kClosedLoopSpeed);
  } else if (mode.is("position")) {
    control->number = static_cast<uint32_t>(ChannelMode::kCountPosition);
  } else {
    return false;
  }
  return true;
}

/// A number of `largest` at most and `smallest` at least into `control->number`.
bool numberInto(Reader& reader, uint32_t smallest, uint32_t largest, SantengControl* control) {
  uint32_t n = 0;
  if (!reader.number(largest, &n) || n < smallest) {
    return false;
  }
  control->number = n;
  return true;
}

/// The channel settings of "set ..." (`what`): the usage line when wrong, else null.
const char* parseChannelSetting(const Word& what, Reader& reader, SantengControl* control) {
  using Kind = SantengControl::Kind;
  if (what.is("mode")) {
    control->kind = Kind::kMode;
    return parseMode(reader, control) ? nullptr : "usage: set mode 1|2 open-loop|speed|position";
  }
  control->kind = what.is("max-rpm") ? Kind::kMaxRpm : Kind::kEncoderLines;
  const bool valid = reader.channel(&control->channel) && numberInto(reader, 1, 65535, control);
  return valid ? nullptr : "usage: set max-rpm|encoder-lines 1|2 1..65535";
}

/// "set ...": the usage line when it is wrong, else null.
const char* parseSetting(Reader& reader, SantengControl* control) {
  using Kind = SantengControl::Kind;
  const Word what = reader.word();
  if (what.is("mode") || what.is("max-rpm") || what.is("encoder-lines")) {
    return parseChannelSetting(what, reader, control);
  }
  if (what.is("node-id")) {
    control->kind = Kind::kNodeId;
    return numberInto(reader, 1, 126, control) ? nullptr : "usage: set node-id 1..126";
  }
  if (what.is("bit-rate")) {
    control->kind = Kind::kBitRate;
    const bool valid =
        numberInto(reader, 1, 1000, control) && santengBitRateCode(control->number) >= 0;
    return valid ? nullptr : "usage: set bit-rate 1000|800|500|250|125|50|25|10";
  }
  if (what.is("heartbeat") || what.is("tpdo-rate")) {
    control->kind = what.is("heartbeat") ? Kind::kHeartbeat : Kind::kTpdoRate;
    return numberInto(reader, 0, 65535, control) ? nullptr
                                                 : "usage: set heartbeat|tpdo-rate 0..65535 (ms)";
  }
  if (what.is("auto-start")) {
    control->kind = Kind::kAutoStart;
    return reader.state(&control->on) ? nullptr : "usage: set auto-start on|off";
  }
  return "usage: set node-id|bit-rate|heartbeat|tpdo-rate|auto-start|mode|max-rpm|"
         "encoder-lines ...";
}

/// Writes "unknown command 'VERB' (...)" like snprintf; returns false.
bool refuseUnknown(const Word& verb, char* why, size_t whySize) {
  if (why == nullptr || whySize == 0U) {
    return false;
  }
  size_t length = 0;
  auto append = [&](const char* text, size_t count) {
    for (size_t i = 0; i < count && length + 1U < whySize; ++i) {
      why[length++] = text[i];
    }
  };
  auto appendText = [&](const char* text) {
    size_t count = 0;
    while (text[count] != '\0') {
      ++count;
    }
    append(text, count);
  };
  appendText(kUnknownHead);
  append(verb.begin, verb.length);
  appendText(kUnknownTail);
  why[length] = '\0';
  return false;
}

}  // namespace

int santengBitRateCode(uint32_t kbits) noexcept {
  for (uint8_t code = 0; code < kBitRateCount; ++code) {
    if (kBitRates[code] == kbits * 1000U) {
      return static_cast<int>(code);
    }
  }
  return -1;
}

bool parseSantengControl(const char* text, SantengControl* control, char* why,
                         size_t whySize) noexcept {
  using Kind = SantengControl::Kind;
  Reader reader(text);
  const Word verb = reader.word();
  SantengControl parsed;
  const char* usage = nullptr;
  if (verb.is("set")) {
    usage = parseSetting(reader, &parsed);
  } else if (verb.is("fault")) {
    parsed.kind = Kind::kFault;
    parsed.number = faultBits(reader.word());
    usage = parsed.number != 0U && reader.state(&parsed.on)
                ? nullptr
                : "usage: fault overheat|overvoltage|undervoltage|short|sensor|mosfet on|off";
  } else if (verb.is("stall")) {
    parsed.kind = Kind::kStall;
    usage = reader.channel(&parsed.channel) && reader.state(&parsed.on) ? nullptr
                                                                        : "usage: stall 1|2 on|off";
  } else if (verb.is("input") || verb.is("output")) {
    parsed.kind = verb.is("input") ? Kind::kInput : Kind::kOutput;
    const uint32_t largest = verb.is("input") ? 32U : 8U;
    usage =
        reader.number(largest, &parsed.number) && parsed.number >= 1U && reader.state(&parsed.on)
            ? nullptr
            : (verb.is("input") ? "usage: input 1..32 on|off" : "usage: output 1..8 on|off");
  } else {
    return refuseUnknown(verb, why, whySize);
  }
  if (usage != nullptr) {
    return refuseControl(usage, why, whySize);
  }
  *control = parsed;
  return true;
}

}  // namespace costa::santeng
