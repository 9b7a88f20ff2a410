// File-backed storage: a missing file, reopening, atomic replacement on commit, failures that
// leave the previous file intact, and a change of size.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "costa/port/linux/file_storage.hpp"

namespace costa::port {
namespace {

namespace fs = std::filesystem;

class FileStorageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = ::testing::TempDir() + "costa-file-storage-XXXXXX";
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
    path_ = directory_ + "/params.bin";
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }

  static std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>());
  }
  static void writeFile(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  }
  static std::vector<uint8_t> image(FileStorage& storage) {
    std::vector<uint8_t> bytes(storage.size());
    EXPECT_TRUE(storage.read(0, bytes.data(), bytes.size()));
    return bytes;
  }

  std::string directory_;
  std::string path_;
};

TEST_F(FileStorageTest, AMissingFileReadsErasedAndIsCreatedByCommit) {
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 6, &error)) << error;
  EXPECT_TRUE(storage.isOpen());
  EXPECT_EQ(storage.size(), 6U);
  EXPECT_EQ(image(storage), std::vector<uint8_t>(6, 0xFF));
  EXPECT_FALSE(fs::exists(path_));
  const uint8_t data[2] = {0x12, 0x34};
  EXPECT_TRUE(storage.write(1, data, 2));
  EXPECT_FALSE(fs::exists(path_)) << "nothing reaches the file before commit";
  ASSERT_TRUE(storage.commit()) << storage.lastError();
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{0xFF, 0x12, 0x34, 0xFF, 0xFF, 0xFF}));
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
}

TEST_F(FileStorageTest, ReopeningKeepsCommittedDataAndDropsUncommittedData) {
  {
    FileStorage storage;
    std::string error;
    ASSERT_TRUE(storage.open(path_, 4, &error)) << error;
    const uint8_t data[4] = {1, 2, 3, 4};
    EXPECT_TRUE(storage.write(0, data, 4));
    ASSERT_TRUE(storage.commit());
    EXPECT_TRUE(storage.erase(1, 2));
    EXPECT_EQ(image(storage), (std::vector<uint8_t>{1, 0xFF, 0xFF, 4}));
  }
  FileStorage reopened;
  std::string error;
  ASSERT_TRUE(reopened.open(path_, 4, &error)) << error;
  EXPECT_EQ(image(reopened), (std::vector<uint8_t>{1, 2, 3, 4}));
}

TEST_F(FileStorageTest, AnotherSizeIsPaddedWithErasedBytesOrCut) {
  writeFile(path_, {1, 2, 3, 4});
  FileStorage larger;
  std::string error;
  ASSERT_TRUE(larger.open(path_, 6, &error)) << error;
  EXPECT_EQ(image(larger), (std::vector<uint8_t>{1, 2, 3, 4, 0xFF, 0xFF}));
  EXPECT_EQ(fileBytes(path_).size(), 4U) << "the file changes only at commit";

  FileStorage smaller;
  ASSERT_TRUE(smaller.open(path_, 3, &error)) << error;
  EXPECT_EQ(image(smaller), (std::vector<uint8_t>{1, 2, 3}));
  ASSERT_TRUE(smaller.commit());
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{1, 2, 3}));
}

TEST_F(FileStorageTest, ALeftoverTemporaryFileIsIgnoredAndReplaced) {
  writeFile(path_, {7, 7});
  writeFile(path_ + ".tmp", {9, 9, 9, 9, 9});
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 2, &error)) << error;
  EXPECT_EQ(image(storage), (std::vector<uint8_t>{7, 7}));
  ASSERT_TRUE(storage.commit());
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{7, 7}));
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
}

TEST_F(FileStorageTest, ACommitThatCannotCreateTheTemporaryFileKeepsTheGoodFile) {
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 2, &error)) << error;
  const uint8_t first[2] = {1, 1};
  EXPECT_TRUE(storage.write(0, first, 2));
  ASSERT_TRUE(storage.commit());

  fs::create_directory(path_ + ".tmp");  // the temporary file cannot be opened for writing
  const uint8_t second[2] = {2, 2};
  EXPECT_TRUE(storage.write(0, second, 2));
  EXPECT_FALSE(storage.commit());
  EXPECT_NE(storage.lastError().find("cannot create"), std::string::npos) << storage.lastError();
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{1, 1}));

  fs::remove(path_ + ".tmp");
  EXPECT_TRUE(storage.commit()) << storage.lastError();
  EXPECT_EQ(storage.lastError(), "");
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{2, 2}));
}

TEST_F(FileStorageTest, ACommitThatCannotWriteTheTemporaryFileKeepsTheGoodFile) {
  if (!fs::exists("/dev/full")) {
    GTEST_SKIP() << "needs /dev/full";
  }
  writeFile(path_, {5, 5, 5});
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 3, &error)) << error;
  EXPECT_TRUE(storage.erase(0, 3));
  fs::create_symlink("/dev/full", path_ + ".tmp");  // every write fails with ENOSPC
  EXPECT_FALSE(storage.commit());
  EXPECT_NE(storage.lastError().find("cannot write"), std::string::npos) << storage.lastError();
  EXPECT_EQ(fileBytes(path_), (std::vector<uint8_t>{5, 5, 5}));
  EXPECT_FALSE(fs::is_symlink(path_ + ".tmp")) << "the temporary file is removed";
}

TEST_F(FileStorageTest, ACommitThatCannotRenameRemovesTheTemporaryFile) {
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 2, &error)) << error;
  fs::create_directories(path_ + "/occupied");  // a non-empty directory where the file goes
  EXPECT_FALSE(storage.commit());
  EXPECT_NE(storage.lastError().find("cannot rename"), std::string::npos) << storage.lastError();
  EXPECT_FALSE(fs::exists(path_ + ".tmp"));
  EXPECT_TRUE(fs::is_directory(path_ + "/occupied"));
}

TEST_F(FileStorageTest, ACommitIntoARemovedDirectoryFails) {
  const std::string inner = directory_ + "/inner";
  fs::create_directory(inner);
  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(inner + "/params.bin", 2, &error)) << error;
  fs::remove(inner);
  EXPECT_FALSE(storage.commit());
  EXPECT_NE(storage.lastError(), "");
}

TEST_F(FileStorageTest, OpeningADirectoryFailsWithAReason) {
  FileStorage storage;
  std::string error;
  EXPECT_FALSE(storage.open(directory_, 4, &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(storage.isOpen());
}

TEST_F(FileStorageTest, AccessOutsideTheImageOrWhileClosedFails) {
  FileStorage closed;
  uint8_t data[4] = {};
  EXPECT_EQ(closed.size(), 0U);
  EXPECT_FALSE(closed.read(0, data, 1));
  EXPECT_FALSE(closed.write(0, data, 1));
  EXPECT_FALSE(closed.erase(0, 1));
  EXPECT_FALSE(closed.commit());
  EXPECT_EQ(closed.lastError(), "storage is not open");

  FileStorage storage;
  std::string error;
  ASSERT_TRUE(storage.open(path_, 4, &error)) << error;
  EXPECT_FALSE(storage.read(2, data, 3));
  EXPECT_FALSE(storage.write(5, data, 0));
  EXPECT_FALSE(storage.erase(0, SIZE_MAX));
  EXPECT_TRUE(storage.read(4, data, 0));
}

}  // namespace
}  // namespace costa::port
