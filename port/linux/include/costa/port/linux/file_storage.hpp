// Non-volatile storage of a fixed size kept in a file, replaced atomically on commit.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>
#include <vector>

#include "costa/port/nv_storage.hpp"

namespace costa::port {

/// The medium is an in-memory image of `size` bytes: reads come from it, writes and erases change
/// it, and commit() replaces the file with the whole image. The replacement is atomic: the image
/// is written to `path + ".tmp"`, flushed with fsync(), renamed over `path`, and the directory is
/// flushed, so after a crash the file holds either the previous or the new complete image.
/// Writes that were never committed are lost, as NvStorage allows.
class FileStorage final : public NvStorage {
 public:
  FileStorage() = default;

  /// Loads the image from `path`. A missing file reads as all 0xFF; an existing file of another
  /// length is padded with 0xFF or cut to `size` (in memory: the file changes at the next
  /// commit). On failure (unreadable file, a directory at `path`) returns false, sets `error`
  /// to one line saying why, and leaves the storage closed.
  bool open(const std::string& path, size_t size, std::string* error);
  bool isOpen() const noexcept { return open_; }
  const std::string& path() const noexcept { return path_; }
  /// Why the last commit() failed.
  const std::string& lastError() const noexcept { return lastError_; }

  size_t size() const noexcept override { return image_.size(); }
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override;
  bool write(size_t offset, const uint8_t* source, size_t length) noexcept override;
  bool erase(size_t offset, size_t length) noexcept override;
  bool commit() noexcept override;

 private:
  bool inRange(size_t offset, size_t length) const noexcept {
    return open_ && offset <= image_.size() && length <= image_.size() - offset;
  }
  bool replaceFile(std::string* error);

  std::string path_;
  std::string lastError_;
  std::vector<uint8_t> image_;
  bool open_ = false;
};

}  // namespace costa::port
