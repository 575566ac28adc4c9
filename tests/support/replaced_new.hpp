// The global operator new and delete replaced by versions that count every call and fail on
// demand (replaced_new.cpp): allocation counts for the tests that a step allocates nothing, and
// std::bad_alloc (or, nothrow, null) at the Nth allocation after being armed for the tests of
// memory exhaustion. A replacement is global to its executable: only the executables that list
// support/replaced_new.cpp among their sources get it.
#pragma once

namespace tamias2d::test {

/// Allocations asked for so far, by any form of operator new (failed ones included).
long allocation_count();
/// Deallocations of a non-null pointer so far, by any form of operator delete.
long deallocation_count();

/// The next `n` allocations succeed and the one after fails; so do all later ones until
/// stop_failing (a program out of memory stays so while it unwinds), or, with `once`, only it.
void fail_allocation_after(long n, bool once = false);
/// Every allocation succeeds again.
void stop_failing();
/// Whether an allocation has failed since fail_allocation_after.
bool allocation_failed();

} // namespace tamias2d::test
