// A device as the Linux slave runs it: a node, the behaviour behind it, and its names.
#pragma once

#include <stdint.h>

#include <memory>
#include <string>

#include "costa/node.hpp"
#include "costa/od/definition.hpp"
#include "costa/port/can_bit_rate.hpp"
#include "costa/port/can_port.hpp"
#include "costa/port/linux/file_storage.hpp"

namespace costa::host {

/// Options a device may use when it is created.
struct TargetOptions {
  int nodeId = -1;          ///< --node-id, or -1 for the device's own default.
  std::string storagePath;  ///< --storage, or empty.
  /// The CAN port's bit rate, for NodeSettings::bitRateControl (null: none).
  CanBitRateControl* bitRate = nullptr;
  /// The SDO server's timeout (--sdo-timeout), or 0: the device's own.
  Microseconds sdoTimeout = 0;
  /// The serial number in 0x1018:04 from every reset communication on, or 0: the device's own.
  uint32_t serialNumber = 0;
};

/// Writes a serial number into 0x1018:04 at every reset communication, after the device's own
/// listeners (which may write theirs): the identity LSS reads is then this one.
class SerialNumberOverride final : public NodeEvents {
 public:
  void assign(Node& node, uint32_t serialNumber) {
    node_ = &node;
    serialNumber_ = serialNumber;
  }
  void onResetCommunication() noexcept override {
    (void)node_->dictionary().storeUnsigned(0x1018, 4, serialNumber_);
  }

 private:
  Node* node_ = nullptr;
  uint32_t serialNumber_ = 0;
};

class DeviceTarget {
 public:
  DeviceTarget() = default;
  virtual ~DeviceTarget() = default;
  DeviceTarget(const DeviceTarget&) = delete;
  DeviceTarget& operator=(const DeviceTarget&) = delete;

  virtual void start(Microseconds now) = 0;
  virtual void onFrame(const CanFrame& frame, Microseconds now) = 0;
  /// Runs node and device; returns the next deadline.
  virtual Microseconds process(Microseconds now) = 0;
  virtual Node& node() = 0;
  /// Names of the dictionary's entries (for traces).
  virtual const od::NameTable* names() const = 0;
  /// A command to the device's simulation (costa-slave --control, transcript `sim`): the
  /// composition's control(). Returns "" when done, else one line saying why not.
  virtual std::string control(const std::string& command) = 0;
  /// Every hook and listener of the device's behaviour found room in its node.
  virtual bool attached() const = 0;

  /// Gives the node `serialNumber` in 0x1018:04 (call before start()). False when the node's
  /// listener table has no room left.
  bool overrideSerialNumber(uint32_t serialNumber) {
    serialNumber_.assign(node(), serialNumber);
    return node().addListener(serialNumber_);
  }

 private:
  SerialNumberOverride serialNumber_;
};

/// Adapts a device composition (targets/devices.hpp: start, onFrame, process, node, control,
/// attached, names) to DeviceTarget.
template <typename Composition>
class HostedTarget final : public DeviceTarget {
 public:
  /// `storage` (may be null) is owned by the target and outlives the composition, which is
  /// built from `args` (for a device: the CAN transmitter and its DeviceConfig).
  template <typename... Args>
  explicit HostedTarget(std::unique_ptr<port::FileStorage> storage, Args&&... args)
      : storage_(std::move(storage)), composition_(std::forward<Args>(args)...) {}

  void start(Microseconds now) override { composition_.start(now); }
  void onFrame(const CanFrame& frame, Microseconds now) override {
    composition_.onFrame(frame, now);
  }
  Microseconds process(Microseconds now) override { return composition_.process(now); }
  Node& node() override { return composition_.node(); }
  const od::NameTable* names() const override { return &Composition::names(); }
  std::string control(const std::string& command) override {
    char why[256] = {};
    return composition_.control(command.c_str(), why, sizeof(why)) ? std::string() : why;
  }
  bool attached() const override { return composition_.attached(); }
  Composition& composition() { return composition_; }

 private:
  std::unique_ptr<port::FileStorage> storage_;
  Composition composition_;
};

}  // namespace costa::host
