// A save whose commit fails (the Linux slave's storage file cannot be replaced) changes nothing:
// the master gets 0x08000020, a reset loads what was stored before, and a later save that does
// commit does not make the failed one durable after all. Through the wire, with FileStorage.
#include <stdlib.h>

#include <filesystem>
#include <memory>

#include "costa/port/linux/file_storage.hpp"
#include "example_fixture.hpp"

namespace costa::test {
namespace {

namespace fs = std::filesystem;

/// The Linux FileStorage, whose commit builds path names on the heap: outside the stack, so
/// allowed inside the tests' no-allocation scopes.
class LinuxStorage final : public NvStorage {
 public:
  bool open(const std::string& path, size_t size, std::string* error) {
    return file_.open(path, size, error);
  }
  size_t size() const noexcept override { return file_.size(); }
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override {
    return file_.read(offset, destination, length);
  }
  bool write(size_t offset, const uint8_t* source, size_t length) noexcept override {
    return file_.write(offset, source, length);
  }
  bool erase(size_t offset, size_t length) noexcept override { return file_.erase(offset, length); }
  bool commit() noexcept override {
    const AllocationAllowedScope port;
    return file_.commit();
  }

 private:
  port::FileStorage file_;
};

class StoreFailedCommit : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = ::testing::TempDir() + "costa-failed-commit-XXXXXX";
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
    path_ = directory_ + "/example.bin";
    powerOn();
  }
  void TearDown() override {
    bus_.reset();
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }

  /// A new node over the file as it is on disk, as costa-slave --storage FILE after a restart.
  void powerOn() {
    bus_.reset();
    storage_ = std::make_unique<LinuxStorage>();
    std::string error;
    ASSERT_TRUE(storage_->open(path_, example::ExampleTarget::kStorageBytes, &error)) << error;
    NodeSettings settings = example::ExampleTarget::settings();
    settings.storage = storage_.get();
    bus_ = std::make_unique<InProcessBus>(exampleWith(settings));
    ASSERT_EQ(play("tx 701 [1] 00"), "");
  }
  std::string play(const std::string& text) { return playText(text, *bus_); }

  std::string directory_;
  std::string path_;
  std::unique_ptr<LinuxStorage> storage_;
  std::unique_ptr<InProcessBus> bus_;
};

TEST_F(StoreFailedCommit, AFailedSaveChangesNothingNowOrLater) {
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 00 20 00 20 4E 00 00   # setpoint 20000
    tx 581 [8] 60 00 20 00 00 00 00 00
    rx 601 [8] 23 10 10 03 73 61 76 65   # "save" application: stored
    tx 581 [8] 60 10 10 03 00 00 00 00
    rx 601 [8] 23 00 20 00 30 75 00 00   # 30000
    tx 581 [8] 60 00 20 00 00 00 00 00
  )"),
            "");
  fs::create_directory(path_ + ".tmp");  // the file can no longer be replaced
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 10 10 03 73 61 76 65   # "save" application
    tx 581 [8] 80 10 10 03 20 00 00 08   # 0x08000020: not stored
    rx 000 [2] 81 01                     # reset node: what was stored before
    tx 701 [1] 00
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 20 4E 00 00   # 20000, not 30000
  )"),
            "");
  fs::remove(path_ + ".tmp");
  EXPECT_EQ(play(R"(
    rx 601 [8] 23 05 10 00 90 00 00 00   # SYNC COB-ID 0x090 (communication)
    tx 581 [8] 60 05 10 00 00 00 00 00
    rx 601 [8] 23 10 10 02 73 61 76 65   # "save" communication: the file is replaced
    tx 581 [8] 60 10 10 02 00 00 00 00
  )"),
            "");
  powerOn();
  EXPECT_EQ(play(R"(
    rx 601 [8] 40 00 20 00 00 00 00 00
    tx 581 [8] 43 00 20 00 20 4E 00 00   # still 20000
    rx 601 [8] 40 05 10 00 00 00 00 00
    tx 581 [8] 43 05 10 00 90 00 00 00   # the save that did commit
  )"),
            "");
}

}  // namespace
}  // namespace costa::test
