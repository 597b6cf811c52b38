#pragma once
/// \file
/// \brief The judge's end of the connection to the subject, made on first use, and the
/// base of the judge's stand-ins for the subject's objects.
///
/// The grader starts the subject in its sandbox and hands the judge the connection as
/// descriptor `channel_fd` (environment: VL_SUBJECT_FD). Run by hand or by ctest, the
/// judge starts the subject itself: VL_SUBJECT_PROGRAM names the program (a subject
/// linked with the reference), and every test of the judge runs against that one process.
#include <cstdint>

#include "channel.hh"

namespace vl::remote {

/// The judge's end of the connection (throws protocol_error when there is none).
endpoint& subject();

/// \brief A judge-side stand-in for an object the subject made: it holds the handle, and
/// releases the subject's object when it goes.
class remote_object {
public:
    explicit remote_object(handle h) : handle_(h) {}
    remote_object(const remote_object&) = delete;
    remote_object& operator=(const remote_object&) = delete;
    ~remote_object() { subject().release(handle_); }
    handle id() const { return handle_; }

private:
    handle handle_;
};

}  // namespace vl::remote
