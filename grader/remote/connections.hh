#pragma once
/// \file
/// \brief Handing a connection across the control connection (descriptor `channel_fd`):
/// the judge opens one connection per thread that calls into the subject, and sends the
/// subject its end; the subject serves each on a thread of its own.

namespace vl::remote {

/// Sends the descriptor `fd` over the socket `over`; false when the other end is gone.
bool send_descriptor(int over, int fd);

/// Receives a descriptor from the socket `over` (close-on-exec); -1 when the other end
/// closed the connection or sent no descriptor.
int receive_descriptor(int over);

}  // namespace vl::remote
