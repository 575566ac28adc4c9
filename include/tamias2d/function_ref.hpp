/// \file
/// A non-owning reference to something callable: what the World's queries take for their
/// callbacks, so that a query with a callback allocates nothing (std::function may).
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace tamias2d {

template <class Signature> class FunctionRef;

/// Refers to a callable (a lambda, a function, a functor) for the duration of one call: it
/// stores a pointer to it and never copies it, so the callable must outlive the FunctionRef
/// (pass a lambda straight to the call that takes it).
template <class R, class... Args> class FunctionRef<R(Args...)> {
  public:
    /// Refers to `f`, which must be callable with Args... and return something convertible to R.
    template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> &&
             std::is_invocable_r_v<R, F&, Args...>) FunctionRef(F&& f)
    noexcept // NOLINT(google-explicit-constructor): a lambda converts
        : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
          call_([](void* o, Args... args) -> R {
              return (*static_cast<std::remove_reference_t<F>*>(o))(std::forward<Args>(args)...);
          }) {}

    /// Calls the callable.
    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

  private:
    void* object_;
    R (*call_)(void*, Args...);
};

} // namespace tamias2d
