#include "tamias2d/build_info.hpp"

#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"

namespace tamias2d {

const char* library_version() noexcept {
    return TAMIAS2D_VERSION;
}

const char* solver_instruction_set() noexcept {
    if (const char* clone = WideContactSolver::instruction_set())
        return clone;
#if defined(__x86_64__) || defined(_M_X64)
    return "sse2"; // the x86-64 baseline
#else
    return "generic";
#endif
}

} // namespace tamias2d
