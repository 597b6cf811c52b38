#pragma once
/// \file
/// \brief Exceptions across the connection: the subject writes what its call threw (its
/// kind and message); the judge throws the same kind again, so a test's
/// `CHECK_THROWS_AS(f(), vl::usage_error)` reads as it does in one process.
#include <exception>

#include "wire.hh"

namespace vl::remote {

/// \brief What a call threw that is no std::exception (a student's `throw 42;`).
struct foreign_exception {};

/// Writes the kind and message of the exception `e` (subject side).
void write_exception(std::exception_ptr e, message_writer& out);

/// Throws an exception of the kind and with the message that `in` holds (judge side);
/// throws protocol_error when `in` holds no exception.
[[noreturn]] void throw_exception(message_reader& in);

}  // namespace vl::remote
