// The EDS each device's dictionary was generated from, byte for byte (costa-slave --eds).
#pragma once

#include <string_view>

namespace costa::host {

/// The EDS file of the device named `name` (its name, not an alias), exactly as it is in the
/// repository; empty for an unknown name.
std::string_view deviceEds(std::string_view name);

}  // namespace costa::host
