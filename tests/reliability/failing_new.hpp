// Allocation failure on demand: this test executable replaces the global operator new and
// delete (failing_new.cpp) with versions that throw std::bad_alloc (or, nothrow, return null)
// at the Nth allocation after being armed. Only reliability_oom_tests links it: a replacement
// is global to the executable.
#pragma once

namespace tamias2d::reliability {

/// The next `n` allocations succeed and the one after fails; so do all later ones until
/// stop_failing (a program out of memory stays so while it unwinds), or, with `once`, only it.
void fail_allocation_after(long n, bool once = false);
/// Every allocation succeeds again.
void stop_failing();
/// Whether an allocation has failed since fail_allocation_after.
bool allocation_failed();
/// Allocations asked for so far (failed ones included).
long allocation_count();

} // namespace tamias2d::reliability
