// A CiA 305 LSS master for tests: Fastscan, switch state, configure and store, inquire. Works
// over any link (an in-memory bus or a SocketCAN socket).
#pragma once

#include <stdint.h>

#include "costa/lss_slave.hpp"
#include "costa/port/can_frame.hpp"

namespace costa::test {

class LssMasterLink {
 public:
  virtual ~LssMasterLink() = default;
  virtual void send(const CanFrame& frame) = 0;
  /// The next LSS response (0x7E4); false when none arrives in time.
  virtual bool receive(CanFrame* frame) = 0;
  /// Drops the further answers to the last request (several slaves may answer at once).
  virtual void discardAnswers() {
    CanFrame more;
    while (receive(&more)) {
    }
  }
};

class LssMaster {
 public:
  explicit LssMaster(LssMasterLink& link) : link_(link) {}

  /// Finds one non-configured slave by Fastscan; it is then in configuration state.
  bool fastscan(LssIdentity* found);
  void switchGlobal(bool configuration);
  bool switchSelective(const LssIdentity& identity);
  /// Configure node-id; returns the slave's error code (-1: no answer).
  int configureNodeId(uint8_t nodeId);
  int configureBitTiming(uint8_t tableIndex);
  int storeConfiguration();
  void activateBitTiming(uint16_t delayMs);
  /// Inquire service (0x5A..0x5E); false when no answer.
  bool inquire(uint8_t command, uint32_t* value);
  int requests() const { return requests_; }

 private:
  bool request(const uint8_t (&data)[8], CanFrame* answer);
  bool probe(uint32_t id, uint8_t bitChecked, uint8_t sub, uint8_t next);

  LssMasterLink& link_;
  int requests_ = 0;
};

}  // namespace costa::test
