#pragma once
/// \file
/// \brief The traps of the oracle probe (oracle_probe.cc): the build links a stage's
/// oracle registration (its register.cc compiled into vl::reference_stageNN) without the
/// reference's pieces, and defines each function the registration takes from them as a
/// trap that throws that function's name. Asking the registration for a piece then names
/// the function, and so the object file, that implements it.
///
/// cmake/grader_oracle_traps.cmake writes one VL_ORACLE_TRAP line per function.
#include <string>

namespace vl::grader {

/// \brief Thrown by a trap: the mangled name of the function the registration called.
struct oracle_trap {
    std::string symbol;
};

}  // namespace vl::grader

/// Defines a trap for `symbol` (a mangled name), which the linker takes for that function.
/// The registration calls it with the function's arguments, which it never reads: it never
/// returns.
#define VL_ORACLE_TRAP(k, symbol)                                  \
    [[noreturn]] void vl_oracle_trap_##k() __asm__(symbol);        \
    [[noreturn]] void vl_oracle_trap_##k() { throw ::vl::grader::oracle_trap{symbol}; }
