#include "costa/port/linux/file_storage.hpp"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <system_error>

namespace costa::port {
namespace {

std::string describe(const std::string& what, const std::string& path) {
  const int code = errno;
  return what + " " + path + ": " + std::system_category().message(code);
}

/// Closes a descriptor on every path out of a scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) {
      ::close(fd_);
    }
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  /// Closes now, reporting the result (close can report a failed write-back).
  bool close() {
    const int fd = fd_;
    fd_ = -1;
    return ::close(fd) == 0;
  }

 private:
  int fd_;
};

bool writeAll(int fd, const uint8_t* data, size_t length) {
  while (length > 0U) {
    const ssize_t done = ::write(fd, data, length);
    if (done < 0) {
      if (errno == EINTR) {
        continue;
      }
      return false;
    }
    data += done;
    length -= static_cast<size_t>(done);
  }
  return true;
}

/// Reads up to `length` bytes; returns how many (fewer at end of file), or -1 on an error.
ssize_t readUpTo(int fd, uint8_t* data, size_t length) {
  size_t total = 0;
  while (total < length) {
    const ssize_t done = ::read(fd, data + total, length - total);
    if (done < 0) {
      if (errno == EINTR) {
        continue;
      }
      return -1;
    }
    if (done == 0) {
      break;
    }
    total += static_cast<size_t>(done);
  }
  return static_cast<ssize_t>(total);
}

std::string directoryOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) {
    return ".";
  }
  return slash == 0U ? "/" : path.substr(0, slash);
}

}  // namespace

bool FileStorage::open(const std::string& path, size_t size, std::string* error) {
  open_ = false;
  image_.assign(size, 0xFFU);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno != ENOENT) {
      *error = describe("cannot open storage file", path);
      return false;
    }
  } else {
    Descriptor file(fd);
    struct stat status {};
    if (::fstat(file.get(), &status) != 0 || !S_ISREG(status.st_mode)) {
      *error = "storage file " + path + " is not a regular file";
      return false;
    }
    if (readUpTo(file.get(), image_.data(), size) < 0) {
      *error = describe("cannot read storage file", path);
      return false;
    }
  }
  path_ = path;
  open_ = true;
  return true;
}

bool FileStorage::read(size_t offset, uint8_t* destination, size_t length) noexcept {
  if (!inRange(offset, length)) {
    return false;
  }
  if (length != 0U) {
    memcpy(destination, image_.data() + offset, length);
  }
  return true;
}

bool FileStorage::write(size_t offset, const uint8_t* source, size_t length) noexcept {
  if (!inRange(offset, length)) {
    return false;
  }
  if (length != 0U) {
    memcpy(image_.data() + offset, source, length);
  }
  return true;
}

bool FileStorage::erase(size_t offset, size_t length) noexcept {
  if (!inRange(offset, length)) {
    return false;
  }
  memset(image_.data() + offset, 0xFF, length);
  return true;
}

bool FileStorage::commit() noexcept {
  if (!open_) {
    lastError_ = "storage is not open";
    return false;
  }
  try {
    std::string error;
    if (!replaceFile(&error)) {
      lastError_ = error;
      return false;
    }
    lastError_.clear();
    return true;
  } catch (...) {  // std::string can throw bad_alloc; commit() must not throw
    return false;
  }
}

bool FileStorage::replaceFile(std::string* error) {
  const std::string temporary = path_ + ".tmp";
  {
    Descriptor file(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (file.get() < 0) {
      *error = describe("cannot create", temporary);
      return false;
    }
    if (!writeAll(file.get(), image_.data(), image_.size()) || ::fsync(file.get()) != 0 ||
        !file.close()) {
      *error = describe("cannot write", temporary);
      ::unlink(temporary.c_str());
      return false;
    }
  }
  if (::rename(temporary.c_str(), path_.c_str()) != 0) {
    *error = describe("cannot rename " + temporary + " to", path_);
    ::unlink(temporary.c_str());
    return false;
  }
  const std::string directory = directoryOf(path_);
  Descriptor folder(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (folder.get() < 0 || ::fsync(folder.get()) != 0) {
    *error = describe("cannot flush directory", directory);
    return false;
  }
  return true;
}

}  // namespace costa::port
