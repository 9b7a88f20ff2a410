// costa-hot-paths.elf: the hot paths (hot_paths.hpp) on a Cortex-M core, timed with SysTick.
// Run under qemu-system-arm with `-icount shift=0` (tools/cortex-m-counts): the virtual clock
// then advances exactly 1 ns per executed instruction, so SysTick, clocked by the board's
// 25 MHz system clock, counts one tick per 40 instructions and the counts are the same on every
// run. (On a board, the same image would count processor clock cycles, but it reports through
// semihosting, which needs a debugger or an emulator.)
//
// Report, through semihosting, one line each:
//   hot-paths RUNS                  runs per measured batch
//   calibration ITERATIONS TICKS    a loop of exactly 2 x ITERATIONS instructions, twice
//   op KEY FRAMES TICKS             ticks of RUNS runs of an operation (operations() order)
//   error KEY WHAT                  an operation failed its check (exit status 1)
// A batch is: read SysTick, RUNS runs, read SysTick, in one function for every operation; the
// empty operation's batch (the loop and the two timer reads) is subtracted by the net rule like
// the callgrind harness's empty loop. tools/perf/hot_paths.py turns ticks into instructions:
// instructions per tick from the calibration (which must be a whole number), then
// instructions per run = ticks x that / RUNS, then the net rule of hot_paths.hpp.
#include <stdint.h>

#include "hot_paths.hpp"
#include "semihosting.hpp"

namespace {

namespace semihosting = costa::replay::semihosting;

constexpr uint32_t kWarmUpRuns = 100;
// 10,000 runs: a SysTick tick is 40 instructions, so a batch is known to +-40 instructions, and
// a run to +-0.004. The longest batch stays far below SysTick's 2^24 ticks.
constexpr uint32_t kMeasuredRuns = 10000;
constexpr uint32_t kCalibrationShort = 1000;
constexpr uint32_t kCalibrationLong = 1001000;

// SysTick (ARMv6-M and ARMv7-M, System Control Space): a 24-bit down-counter.
constexpr uintptr_t kSysTickControl = 0xE000E010U;
constexpr uintptr_t kSysTickReload = 0xE000E014U;
constexpr uintptr_t kSysTickCurrent = 0xE000E018U;
constexpr uint32_t kSysTickMask = 0x00FFFFFFU;
constexpr uint32_t kEnableWithProcessorClock = 0x5U;  // ENABLE | CLKSOURCE, no interrupt

volatile uint32_t& sysTickRegister(uintptr_t address) noexcept {
  return *reinterpret_cast<volatile uint32_t*>(address);
}

void startSysTick() noexcept {
  sysTickRegister(kSysTickReload) = kSysTickMask;
  sysTickRegister(kSysTickCurrent) = 0;  // any write clears it; it reloads at once
  sysTickRegister(kSysTickControl) = kEnableWithProcessorClock;
}

inline uint32_t sysTick() noexcept {
  return sysTickRegister(kSysTickCurrent);
}

inline uint32_t elapsed(uint32_t start, uint32_t end) noexcept {
  return (start - end) & kSysTickMask;  // counts down, wraps at 2^24
}

costa::hotpaths::Bench bench;

/// Ticks of `runs` runs of `operation`: the same code for every operation.
__attribute__((noinline)) uint32_t measure(const costa::hotpaths::Operation& operation,
                                           uint32_t runs) noexcept {
  const uint32_t start = sysTick();
  for (uint32_t run = 0; run < runs; ++run) {
    operation.run(bench);
  }
  return elapsed(start, sysTick());
}

/// Ticks of a loop of exactly 2 x `iterations` instructions (subs, bne), `iterations` >= 1.
__attribute__((noinline)) uint32_t calibrate(uint32_t iterations) noexcept {
  const uint32_t start = sysTick();
  asm volatile(
      ".syntax unified\n"
      "1:\n"
      "  subs %0, %0, #1\n"
      "  bne 1b\n"
      : "+l"(iterations)
      :
      : "cc");
  return elapsed(start, sysTick());
}

/// A line of text, built in place.
class Line {
 public:
  Line& text(const char* text) noexcept {
    while (*text != '\0' && used_ + 1U < sizeof buffer_) {
      buffer_[used_++] = *text++;
    }
    buffer_[used_] = '\0';
    return *this;
  }
  Line& number(uint32_t value) noexcept {
    char digits[11];
    size_t count = 0;
    do {
      digits[count++] = static_cast<char>('0' + value % 10U);
      value /= 10U;
    } while (value != 0U);
    char reversed[12];
    for (size_t i = 0; i < count; ++i) {
      reversed[i] = digits[count - 1U - i];
    }
    reversed[count] = '\0';
    return text(reversed);
  }
  void send() noexcept {
    text("\n");
    semihosting::writeString(buffer_);
    used_ = 0;
    buffer_[0] = '\0';
  }

 private:
  char buffer_[96] = {};
  size_t used_ = 0;
};

}  // namespace

int main() {
  startSysTick();
  Line line;
  line.text("hot-paths ").number(kMeasuredRuns).send();
  const uint32_t calibrations[] = {kCalibrationShort, kCalibrationLong};
  for (const uint32_t iterations : calibrations) {
    line.text("calibration ").number(iterations).text(" ").number(calibrate(iterations)).send();
  }
  if (const char* error = bench.start()) {
    line.text("error start ").text(error).send();
    semihosting::exit(false);
  }
  size_t count = 0;
  const costa::hotpaths::Operation* operations = costa::hotpaths::operations(&count);
  for (size_t i = 0; i < count; ++i) {
    const costa::hotpaths::Operation& operation = operations[i];
    if (const char* error = costa::hotpaths::prepare(bench, operation, kWarmUpRuns)) {
      line.text("error ").text(operation.key).text(" ").text(error).send();
      semihosting::exit(false);
    }
    const uint32_t ticks = measure(operation, kMeasuredRuns);
    line.text("op ").text(operation.key).text(" ").number(operation.requestFrames).text(" ");
    line.number(ticks).send();
  }
  semihosting::exit(true);
}
