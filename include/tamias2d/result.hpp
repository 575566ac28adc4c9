/// \file
/// Errors as values: tamias2d::Error and tamias2d::Result<T>, which every error-returning call
/// (a `try_` form, such as World::try_create_body) returns instead of throwing. A game built
/// without exceptions (-fno-exceptions) uses these forms only (docs/user-guide.md, "Without
/// exceptions"). This header throws nothing when exceptions are off.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"

namespace tamias2d {

/// What kind of error a call refused with: one per exception the throwing form throws.
enum class ErrorKind : std::uint8_t {
    validation,        ///< ValidationError: field, value, constraint
    invalid_handle,    ///< InvalidHandle: a stale handle, or one never issued
    wrong_world,       ///< WrongWorld: handle, handle_world, world
    wrong_kind,        ///< WrongKind: call, subject, subject_kind
    solver_divergence, ///< SolverDivergence: field
    snapshot,          ///< SnapshotError: offset, field, rule
    recording,         ///< RecordingError: offset, field, rule
    out_of_memory,     ///< std::bad_alloc or std::length_error: an allocation that failed
    /// An exception the game's own function threw (a custom filter, a load function, a
    /// pre-solve callback, a task system), which the throwing form passes on: message is its
    /// what() (or says it was not a std::exception).
    callback_failed,
    allocator_in_use, ///< AllocatorInUse: blocks, bytes (set_allocator, reset_allocator)
};

/// The name of the kind as written in this header, e.g. "invalid_handle".
TAMIAS2D_EXPORT const char* to_string(ErrorKind kind) noexcept;

/// Why a call was refused: its kind and the fields the matching exception carries. A field the
/// kind does not use is empty (strings), NaN (value) or 0. As with the exceptions, a refused
/// call changed nothing: the world is exactly as it was.
struct Error {
    ErrorKind kind = ErrorKind::validation; ///< which exception the throwing form throws
    std::string message; ///< the exception's what(), e.g. "shape.radius = -1: must be > 0 ..."
    std::string field;   ///< validation, solver_divergence, snapshot, recording
    double value = std::numeric_limits<double>::quiet_NaN(); ///< validation: the offending value
    std::string constraint;         ///< validation: the SRS data constraint, e.g. "DCX_shape"
    std::string handle;             ///< wrong_world: the handle, e.g. "BodyId 0:1"
    std::uint32_t handle_world = 0; ///< wrong_world: the tag of the world that issued it
    std::uint32_t world = 0;        ///< wrong_world: the tag of the world it was used with
    std::string call;               ///< wrong_kind: the World member called, e.g. "apply_impulse"
    std::string subject;            ///< wrong_kind: what the handle names, e.g. "body[0 'ground']"
    std::string subject_kind;       ///< wrong_kind: what that is, e.g. "static body"
    std::size_t offset = 0;         ///< snapshot, recording: the byte offset of the field
    std::string rule;               ///< snapshot, recording: the rule the field breaks
    std::size_t blocks = 0;         ///< allocator_in_use: blocks held from the allocator
    std::size_t bytes = 0;          ///< allocator_in_use: their sizes' sum
};

/// What Result::value() throws for an error, and Result::error() for a value, when exceptions
/// are on: a precondition the calling code broke (it did not check has_value()).
struct BadResultAccess : std::exception {
    /// "tamias2d::Result: value() of an error, or error() of a value".
    const char* what() const noexcept override {
        return "tamias2d::Result: value() of an error, or error() of a value";
    }
};

namespace detail {
/// Throws BadResultAccess when exceptions are on; aborts when they are off.
[[noreturn]] inline void bad_result_access() {
#if defined(__cpp_exceptions) || defined(_CPPUNWIND)
    throw BadResultAccess{};
#else
    std::abort();
#endif
}
} // namespace detail

/// A T or the Error that prevented it, as std::expected<T, Error> (C++23) holds them.
/// Check has_value() (or the Result itself, as a bool) before value(), operator* or ->:
/// value() on an error aborts when exceptions are off.
template <class T> class [[nodiscard]] Result {
  public:
    using value_type = T; ///< the value's type
    /// A value.
    Result(T value) : v_(std::in_place_index<0>, std::move(value)) {}
    /// An error.
    Result(Error error) : v_(std::in_place_index<1>, std::move(error)) {}

    /// Whether it holds a value (not an error).
    bool has_value() const noexcept { return v_.index() == 0; }
    /// has_value().
    explicit operator bool() const noexcept { return has_value(); }

    /// The value; for an error, throws BadResultAccess (aborts without exceptions).
    T& value() & {
        if (!has_value())
            detail::bad_result_access();
        return *std::get_if<0>(&v_);
    }
    /// The value; for an error, throws BadResultAccess (aborts without exceptions).
    const T& value() const& {
        if (!has_value())
            detail::bad_result_access();
        return *std::get_if<0>(&v_);
    }
    /// The value, moved out; for an error, throws BadResultAccess (aborts without exceptions).
    T&& value() && { return std::move(value()); }
    /// The value, or `fallback` for an error.
    T value_or(T fallback) const& { return has_value() ? *std::get_if<0>(&v_) : fallback; }

    /// The value, unchecked: only when has_value().
    T& operator*() & noexcept { return *std::get_if<0>(&v_); }
    /// The value, unchecked: only when has_value().
    const T& operator*() const& noexcept { return *std::get_if<0>(&v_); }
    /// The value moved out, unchecked: only when has_value().
    T&& operator*() && noexcept { return std::move(*std::get_if<0>(&v_)); }
    /// The value's members, unchecked: only when has_value().
    T* operator->() noexcept { return std::get_if<0>(&v_); }
    /// The value's members, unchecked: only when has_value().
    const T* operator->() const noexcept { return std::get_if<0>(&v_); }

    /// The error; only when !has_value() (else throws BadResultAccess, or aborts).
    const Error& error() const& {
        if (has_value())
            detail::bad_result_access();
        return *std::get_if<1>(&v_);
    }
    /// The error moved out; only when !has_value() (else throws BadResultAccess, or aborts).
    Error&& error() && {
        if (has_value())
            detail::bad_result_access();
        return std::move(*std::get_if<1>(&v_));
    }

  private:
    std::variant<T, Error> v_;
};

/// Success, or the Error that prevented it.
template <> class [[nodiscard]] Result<void> {
  public:
    using value_type = void; ///< no value
    /// Success.
    Result() noexcept = default;
    /// An error.
    Result(Error error) : error_(std::move(error)) {}

    /// Whether the call succeeded.
    bool has_value() const noexcept { return !error_.has_value(); }
    /// has_value().
    explicit operator bool() const noexcept { return has_value(); }
    /// Nothing on success (as std::expected<void, E>::value()); for an error, throws
    /// BadResultAccess (aborts without exceptions).
    void value() const {
        if (!has_value())
            detail::bad_result_access();
    }
    /// Nothing: there is no value to read.
    void operator*() const noexcept {}

    /// The error; only when !has_value() (else throws BadResultAccess, or aborts).
    const Error& error() const& {
        if (has_value())
            detail::bad_result_access();
        return *error_;
    }
    /// The error moved out; only when !has_value() (else throws BadResultAccess, or aborts).
    Error&& error() && {
        if (has_value())
            detail::bad_result_access();
        return std::move(*error_);
    }

  private:
    std::optional<Error> error_;
};

} // namespace tamias2d
