// costa-slave --list-devices: each device, its summary and the identity it answers with.
#pragma once

#include <string>
#include <string_view>

namespace costa::host {

/// Two lines per device: "NAME  SUMMARY", then an indented line with the identity object's
/// vendor-id, product code and revision number (0x1018:01..03, as the device answers them)
/// and the vendor and product names of its EDS.
std::string describeDevices();

/// The value of `key` in the [DeviceInfo] section of an EDS text ("" when it has none).
std::string edsDeviceInfo(std::string_view eds, std::string_view key);

}  // namespace costa::host
