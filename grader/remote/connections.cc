#include "connections.hh"

#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "channel.hh"

namespace vl::remote {

bool send_connection(int over, connection_fds c) {
    char byte = 'c';
    iovec io{&byte, 1};
    const int fds[2] = {c.socket, c.memory};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof fds)] = {};
    msghdr m{};
    m.msg_iov = &io;
    m.msg_iovlen = 1;
    m.msg_control = control;
    m.msg_controllen = sizeof control;
    cmsghdr* h = CMSG_FIRSTHDR(&m);
    h->cmsg_level = SOL_SOCKET;
    h->cmsg_type = SCM_RIGHTS;
    h->cmsg_len = CMSG_LEN(sizeof fds);
    std::memcpy(CMSG_DATA(h), fds, sizeof fds);
    ssize_t n;
    do n = sendmsg(over, &m, MSG_NOSIGNAL);
    while (n < 0 && errno == EINTR);
    return n == 1;
}

connection_fds receive_connection(int over) {
    char byte = 0;
    iovec io{&byte, 1};
    int fds[2] = {-1, -1};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof fds)] = {};
    msghdr m{};
    m.msg_iov = &io;
    m.msg_iovlen = 1;
    m.msg_control = control;
    m.msg_controllen = sizeof control;
    ssize_t n;
    do n = recvmsg(over, &m, MSG_CMSG_CLOEXEC);
    while (n < 0 && errno == EINTR);
    const cmsghdr* h = n == 1 ? CMSG_FIRSTHDR(&m) : nullptr;
    if (h == nullptr || h->cmsg_level != SOL_SOCKET || h->cmsg_type != SCM_RIGHTS || h->cmsg_len != CMSG_LEN(sizeof fds))
        return {};
    std::memcpy(fds, CMSG_DATA(h), sizeof fds);
    return {fds[0], fds[1]};
}

void* map_shared(int memory) {
    struct stat st {};
    if (fstat(memory, &st) != 0 || static_cast<std::size_t>(st.st_size) < shared_bytes) return nullptr;
    void* p = mmap(nullptr, shared_bytes, PROT_READ | PROT_WRITE, MAP_SHARED, memory, 0);
    return p == MAP_FAILED ? nullptr : p;
}

}  // namespace vl::remote
