// ARM semihosting (the "bkpt 0xAB" calls of Arm's semihosting specification), just what the
// replay images need to report under QEMU (-semihosting-config enable=on,target=native):
// text to the host's standard output and the program's end with its result. Without a debugger
// or an emulator that serves semihosting, the breakpoint stops the core: never call these on a
// board.
#pragma once

namespace costa::replay::semihosting {

/// SYS_WRITE0: writes a NUL-terminated string.
void writeString(const char* text) noexcept;

/// SYS_EXIT: ends the program, reporting "application exit" when `success`, else a run-time
/// error; qemu-system-arm then exits with status 0 or 1.
[[noreturn]] void exit(bool success) noexcept;

}  // namespace costa::replay::semihosting
