// Catches heap use by the stack: tests run every call into the stack inside a
// NoAllocationScope; a global operator new called inside one fails the running test.
#pragma once

#include <stddef.h>

namespace costa::test {

/// While alive, any global operator new (or new[]) is a test failure, reported when the scope
/// ends. Scopes nest.
class NoAllocationScope {
 public:
  NoAllocationScope();
  ~NoAllocationScope();
  NoAllocationScope(const NoAllocationScope&) = delete;
  NoAllocationScope& operator=(const NoAllocationScope&) = delete;

 private:
  size_t violationsAtStart_;
};

/// While alive, inside a NoAllocationScope, allocations are allowed again: for a port the stack
/// calls that is not part of it and may allocate (the Linux FileStorage's commit).
class AllocationAllowedScope {
 public:
  AllocationAllowedScope();
  ~AllocationAllowedScope();
  AllocationAllowedScope(const AllocationAllowedScope&) = delete;
  AllocationAllowedScope& operator=(const AllocationAllowedScope&) = delete;

 private:
  int depth_;
};

/// Allocations made inside a NoAllocationScope since the program started.
size_t forbiddenAllocations();

}  // namespace costa::test
