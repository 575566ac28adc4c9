// The one place where an exception of the library becomes an Error (include/tamias2d/
// result.hpp): every `try_` form runs its throwing form through capture. The library's sources
// use exceptions internally; none leaves a `try_` form.
#pragma once

#include <type_traits>
#include <utility>

#include "tamias2d/result.hpp"

namespace tamias2d::detail {

/// The Error of the exception being handled: called in a catch block only. Each exception type
/// the library throws maps to its ErrorKind with its fields; std::bad_alloc and
/// std::length_error to out_of_memory; anything else (what the game's own functions threw)
/// to callback_failed. Building the Error allocates: if that fails too, std::terminate.
Error current_error() noexcept;

/// Runs `call` (the throwing form) and returns its result, or the Error of what it threw.
template <class F> auto capture(F&& call) noexcept -> Result<std::invoke_result_t<F>> {
    using R = std::invoke_result_t<F>;
    try {
        if constexpr (std::is_void_v<R>) {
            std::forward<F>(call)();
            return Result<void>{};
        } else {
            return Result<R>(std::forward<F>(call)());
        }
    } catch (...) {
        return Result<R>(current_error());
    }
}

} // namespace tamias2d::detail
