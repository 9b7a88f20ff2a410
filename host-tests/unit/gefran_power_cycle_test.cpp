// A GRA across power cycles with its parameters in a file (costa-slave --storage, without
// --node-id): a saved automatic start of 0, "load" bringing a stored node-id back to the factory
// 0x7F (errata E21), and a damaged PARA image reported as the LSS parameter checksum error (E52).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "costa/port/memory/memory_storage.hpp"
#include "device_target.hpp"
#include "gefran_target.hpp"
#include "gra_od.hpp"
#include "in_process_bus.hpp"
#include "transcript_player.hpp"

namespace costa::test {
namespace {

using gefran::GraTarget;

class GraPowerCycle : public ::testing::Test {
 protected:
  /// Switches the sensor on (again): a new node on the same EEPROM, node-id from storage (as
  /// costa-slave --storage FILE gra, without --node-id).
  void powerOn() {
    bus_.reset();
    bus_ = std::make_unique<InProcessBus>([this](CanTransmitter& can) {
      return std::make_unique<host::HostedTarget<GraTarget>>(
          nullptr, can, DeviceConfig{0, false, &eeprom_, nullptr});
    });
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }

  /// Replaces the one occurrence of `from` in the EEPROM by `to`; false if not exactly one.
  bool replaceOnce(const std::vector<uint8_t>& from, const std::vector<uint8_t>& to) {
    uint8_t* const begin = eeprom_.bytes();
    uint8_t* const end = begin + eeprom_.size();
    uint8_t* const found = std::search(begin, end, from.begin(), from.end());
    if (found == end || std::search(found + 1, end, from.begin(), from.end()) != end) {
      return false;
    }
    std::copy(to.begin(), to.end(), found);
    return true;
  }

  port::MemoryStorageOf<GraTarget::kStorageBytes> eeprom_;
  std::unique_ptr<InProcessBus> bus_;
};

TEST_F(GraPowerCycle, ASavedAutomaticStartOfZeroHoldsAfterPowerOn) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2F 00 50 00 00 00 00 00     # 0x5000 = 0
    tx 5FF [8] 60 00 50 00 00 00 00 00
    rx 67F [8] 23 10 10 01 73 61 76 65     # "save"
    tx 5FF [8] 60 10 10 01 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 77F [1] 00                          # boot-up, and nothing after it
    wait 1000
    silence
    rx 67F [8] 40 00 50 00 00 00 00 00
    tx 5FF [8] 4F 00 50 00 00 00 00 00     # 0x5000 = 0 kept
  )"),
            "");
  EXPECT_EQ(bus_->node().state(), NmtState::kPreOperational);
}

TEST_F(GraPowerCycle, LoadBringsAStoredNodeIdBackToTheFactoryOne) {
  powerOn();
  EXPECT_EQ(play(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2F 99 59 02 05 00 00 00     # 0x5999:02 = node-id 5 (LSS-PARA)
    tx 5FF [8] 60 99 59 02 00 00 00 00
    rx 67F [8] 23 99 59 03 73 61 76 65     # 0x5999:03 = "save"
    tx 5FF [8] 60 99 59 03 00 00 00 00
    rx 000 [2] 81 7F                       # reset node: the stored node-id
    tx 705 [1] 00
    tx 185 [8] 00 00 00 00 FF FF FF 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 705 [1] 00                          # still node 5 after power-on
    tx 185 [8] 00 00 00 00 FF FF FF 00
    rx 605 [8] 23 11 10 01 6C 6F 61 64     # 0x1011:01 = "load" (line 1248)
    tx 585 [8] 60 11 10 01 00 00 00 00
    rx 605 [8] 40 99 59 02 00 00 00 00
    tx 585 [8] 4F 99 59 02 05 00 00 00     # node-id 5 until the reset
    rx 000 [2] 81 05                       # reset node: the factory node-id (E21)
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    tx 77F [1] 00                          # and after the next power-on
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 40 99 59 02 00 00 00 00
    tx 5FF [8] 4F 99 59 02 7F 00 00 00
  )"),
            "");
}

// "load" to 0x1011:01 restores every group and discards the stored LSS configuration (E21). When
// the EEPROM fails after the groups and before the LSS record is discarded, the answer is
// 0x08000020, not a confirmation: the stored node-id is still there.
TEST_F(GraPowerCycle, ALoadThatCannotDiscardTheLssRecordAnswers08000020) {
  powerOn();
  ASSERT_EQ(play(R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2F 99 59 02 05 00 00 00     # node-id 5, saved
    tx 5FF [8] 60 99 59 02 00 00 00 00
    rx 67F [8] 23 99 59 03 73 61 76 65
    tx 5FF [8] 60 99 59 03 00 00 00 00
    rx 67F [8] 2F 00 50 00 00 00 00 00     # no automatic start, saved
    tx 5FF [8] 60 00 50 00 00 00 00 00
    rx 67F [8] 23 10 10 01 73 61 76 65
    tx 5FF [8] 60 10 10 01 00 00 00 00
  )"),
            "");
  const std::vector<uint8_t> saved(eeprom_.bytes(), eeprom_.bytes() + eeprom_.size());
  // The fewest programmed bytes with which the load succeeds; one fewer leaves the LSS record's
  // last byte unwritten.
  const auto loadWithPowerFor = [&](size_t bytes) {
    std::copy(saved.begin(), saved.end(), eeprom_.bytes());
    eeprom_.restorePower();
    powerOn();
    EXPECT_EQ(play("tx 705 [1] 00\nwait 100\nsilence"), "");  // no automatic start
    eeprom_.cutPowerAfter(bytes);
    return play(R"(
      rx 605 [8] 23 11 10 01 6C 6F 61 64
      tx 585 [8] 60 11 10 01 00 00 00 00
    )");
  };
  size_t enough = 0;
  while (enough < eeprom_.size() && !loadWithPowerFor(enough).empty()) {
    ++enough;
  }
  ASSERT_GT(enough, 0U);
  ASSERT_LT(enough, eeprom_.size());
  EXPECT_NE(loadWithPowerFor(enough - 1U).find("80 11 10 01 20 00 00 08"), std::string::npos);
  eeprom_.restorePower();
  powerOn();
  EXPECT_EQ(play(R"(
    tx 705 [1] 00                          # the stored node-id was not discarded,
    tx 185 [8] 00 00 00 00 FF FF FF 00     # the groups were: automatic start again
  )"),
            "");
}

/// Saves one PARA value, damages its bytes in the file and powers on again.
class GraDamagedParameters : public GraPowerCycle,
                             public ::testing::WithParamInterface<const char*> {};

TEST_P(GraDamagedParameters, AreReportedAsAParameterChecksumError) {
  const std::string which = GetParam();
  const bool application = which == "application";
  powerOn();
  // 0x2101:01 zero point 3531 (0x0DCB, application) or 0x1800:05 event timer 4951 ms (0x1357,
  // communication): byte pairs that occur nowhere else in the file.
  EXPECT_EQ(play(application ? R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2B 01 21 01 CB 0D 00 00
    tx 5FF [8] 60 01 21 01 00 00 00 00
    rx 67F [8] 23 10 10 01 73 61 76 65
    tx 5FF [8] 60 10 10 01 00 00 00 00
  )"
                             : R"(
    tx 77F [1] 00
    tx 1FF [8] 00 00 00 00 FF FF FF 00
    rx 67F [8] 2B 00 18 05 57 13 00 00
    tx 5FF [8] 60 00 18 05 00 00 00 00
    rx 67F [8] 23 10 10 01 73 61 76 65
    tx 5FF [8] 60 10 10 01 00 00 00 00
  )"),
            "");
  bus_.reset();
  ASSERT_TRUE(application ? replaceOnce({0xCB, 0x0D}, {0xCB, 0x0E})
                          : replaceOnce({0x57, 0x13}, {0x57, 0x14}));
  powerOn();
  EXPECT_EQ(play(R"(
    tx 77F [1] 00
    tx 0FF [8] 00 10 00 40 00 FF FF FF     # EMCY: 0x4001 = 0x40 (E52)
    tx 1FF [8] 00 00 00 00 FF FF FF 40     # factory values: zero point 0, 100 ms
    wait 100
    tx 1FF [8] 00 00 00 00 FF FF FF 40
    rx 67F [8] 40 01 40 00 00 00 00 00
    tx 5FF [8] 4F 01 40 00 40 00 00 00
  )"),
            "");
}

INSTANTIATE_TEST_SUITE_P(Groups, GraDamagedParameters,
                         ::testing::Values("application", "communication"));

}  // namespace
}  // namespace costa::test
