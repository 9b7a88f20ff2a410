#include "allocation_guard.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace costa::test {
namespace {
std::atomic<int> scopeDepth{0};
std::atomic<size_t> violations{0};
std::atomic<size_t> lastSize{0};

void* allocate(size_t size) {
  if (scopeDepth.load() > 0) {
    violations.fetch_add(1);
    lastSize.store(size);
  }
  void* memory = std::malloc(size == 0U ? 1U : size);
  if (memory == nullptr) {
    throw std::bad_alloc();
  }
  return memory;
}

void* allocateAligned(size_t size, std::align_val_t alignment) {
  if (scopeDepth.load() > 0) {
    violations.fetch_add(1);
    lastSize.store(size);
  }
  const auto align = static_cast<size_t>(alignment);
  void* memory = std::aligned_alloc(align, ((size + align - 1U) / align) * align);
  if (memory == nullptr) {
    throw std::bad_alloc();
  }
  return memory;
}
}  // namespace

NoAllocationScope::NoAllocationScope() : violationsAtStart_(violations.load()) {
  scopeDepth.fetch_add(1);
}

NoAllocationScope::~NoAllocationScope() {
  scopeDepth.fetch_sub(1);
  const size_t added = violations.load() - violationsAtStart_;
  if (added != 0U) {
    ADD_FAILURE() << "the stack called global operator new " << added << " time(s) (last size "
                  << lastSize.load() << " bytes)";
  }
}

AllocationAllowedScope::AllocationAllowedScope() : depth_(scopeDepth.exchange(0)) {}

AllocationAllowedScope::~AllocationAllowedScope() {
  scopeDepth.store(depth_);
}

size_t forbiddenAllocations() {
  return violations.load();
}

}  // namespace costa::test

void* operator new(size_t size) {
  return costa::test::allocate(size);
}
void* operator new[](size_t size) {
  return costa::test::allocate(size);
}
void* operator new(size_t size, const std::nothrow_t&) noexcept {
  try {
    return costa::test::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](size_t size, const std::nothrow_t&) noexcept {
  try {
    return costa::test::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(size_t size, std::align_val_t alignment) {
  return costa::test::allocateAligned(size, alignment);
}
void* operator new[](size_t size, std::align_val_t alignment) {
  return costa::test::allocateAligned(size, alignment);
}
void operator delete(void* memory) noexcept {
  std::free(memory);
}
void operator delete[](void* memory) noexcept {
  std::free(memory);
}
void operator delete(void* memory, size_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, size_t) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete(void* memory, size_t, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, size_t, std::align_val_t) noexcept {
  std::free(memory);
}
