#pragma once
/// \file
/// \brief Handing connections across the control connection (descriptor `channel_fd`):
/// the judge opens one connection per thread that calls into the subject (a socket and
/// the memory the two ends share, channel.hh) and sends the subject its end; the subject
/// serves each on a thread of its own.

namespace vl::remote {

/// \brief A connection's two descriptors: its socket and its shared memory (a memfd).
struct connection_fds {
    int socket = -1;
    int memory = -1;
};

/// Sends `c` over the socket `over`; false when the other end is gone.
bool send_connection(int over, connection_fds c);

/// Receives a connection from the socket `over` (close-on-exec); both -1 when the other
/// end closed the control connection or sent no connection.
connection_fds receive_connection(int over);

/// Maps a connection's shared memory (shared_bytes); nullptr when it cannot.
void* map_shared(int memory);

}  // namespace vl::remote
