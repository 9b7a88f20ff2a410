#include "device_listing.hpp"

#include <cstdio>
#include <memory>

#include "device_eds.hpp"
#include "device_registry.hpp"

namespace costa::host {
namespace {

/// Where a device listed but not run sends its boot-up: nowhere.
class NoBus final : public CanTransmitter {};

/// The line without its end (and without a CR of a CRLF file).
std::string_view lineAt(std::string_view text, size_t start, size_t* next) {
  size_t end = text.find('\n', start);
  *next = end == std::string_view::npos ? text.size() : end + 1U;
  end = end == std::string_view::npos ? text.size() : end;
  if (end > start && text[end - 1U] == '\r') {
    --end;
  }
  return text.substr(start, end - start);
}

std::string identityLine(const DeviceEntry& device) {
  NoBus bus;
  TargetOptions options;
  std::string error;
  const std::unique_ptr<DeviceTarget> target = createDevice(device, bus, options, &error);
  if (!target) {
    return "identity: unavailable (" + error + ")";
  }
  target->start(0);
  const auto& dictionary = target->node().dictionary();
  const std::string_view eds = deviceEds(device.name);
  const std::string names =
      " (EDS: " + edsDeviceInfo(eds, "VendorName") + ", " + edsDeviceInfo(eds, "ProductName") + ")";
  if (dictionary.findObject(0x1018) == nullptr) {
    return "no identity object 0x1018" + names;
  }
  char text[160];
  std::snprintf(text, sizeof(text), "vendor-id 0x%08llX, product code 0x%08llX, revision 0x%08llX",
                static_cast<unsigned long long>(dictionary.readUnsigned(0x1018, 1, 0)),
                static_cast<unsigned long long>(dictionary.readUnsigned(0x1018, 2, 0)),
                static_cast<unsigned long long>(dictionary.readUnsigned(0x1018, 3, 0)));
  return text + names;
}

}  // namespace

std::string edsDeviceInfo(std::string_view eds, std::string_view key) {
  bool inDeviceInfo = false;
  for (size_t start = 0, next = 0; start < eds.size(); start = next) {
    const std::string_view line = lineAt(eds, start, &next);
    if (!line.empty() && line.front() == '[') {
      inDeviceInfo = line == "[DeviceInfo]";
    } else if (inDeviceInfo && line.size() > key.size() && line.substr(0, key.size()) == key &&
               line[key.size()] == '=') {
      return std::string(line.substr(key.size() + 1U));
    }
  }
  return "";
}

std::string describeDevices() {
  std::string text;
  for (const DeviceEntry& entry : devices()) {
    char line[256];
    std::snprintf(line, sizeof(line), "%-10s %s", entry.name, entry.summary);
    text += line;
    if (entry.alias != nullptr) {
      text += std::string(" (also: ") + entry.alias + ")";
    }
    text += "\n           " + identityLine(entry) + "\n";
  }
  return text;
}

}  // namespace costa::host
