// The example's view of the node's clock of day (TIME, 0x1012), as a manufacturer object:
//
//   0x2012:01 Milliseconds after midnight   read: the clock of day now (0 while never set);
//   0x2012:02 Days since 1984-01-01          write: sets the clock of day, the other part kept
//                                            (0 while never set); a write of 0x2012:01 at or
//                                            past 86,400,000 is refused by its HighLimit
//   0x2012:03 TIME producer period (ms)      write: a producer (0x1012 bit 30) sends TIME at
//                                            this period, 0: none
#pragma once

#include "costa/node.hpp"

namespace costa::example {

class ExampleClock : public ObjectHook {
 public:
  static constexpr uint16_t kIndex = 0x2012;

  explicit ExampleClock(Node& node) noexcept : node_(node) {}

  AbortCode prepareRead(od::ObjectDictionary& dictionary, const od::EntryRef& ref,
                        const ReadRequest& request) noexcept override;
  AbortCode write(od::ObjectDictionary& dictionary, const od::EntryRef& ref, const uint8_t* data,
                  size_t length) noexcept override;

 private:
  Node& node_;
};

}  // namespace costa::example
