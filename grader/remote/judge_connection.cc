#include "judge_connection.hh"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "connections.hh"
#include "judge_components.hh"

namespace vl::remote {

namespace {

/// Starts `program` with one end of a new control connection as its `channel_fd`;
/// returns the other end.
int start_subject(const char* program) {
    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
        throw protocol_error(std::string("socketpair: ") + std::strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) throw protocol_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
        dup2(ends[1], channel_fd);  // dup2 clears close-on-exec
        char* const argv[] = {const_cast<char*>(program), nullptr};
        execv(program, argv);
        _exit(127);
    }
    close(ends[1]);
    return ends[0];
}

/// The control connection: where each thread's own connection is handed to the subject.
int control_fd() {
    static const int fd = [] {
        if (const char* given = std::getenv("VL_SUBJECT_FD"); given != nullptr && *given != '\0') return std::atoi(given);
        if (const char* program = std::getenv("VL_SUBJECT_PROGRAM"); program != nullptr && *program != '\0')
            return start_subject(program);
        throw protocol_error("the judge has no subject: set VL_SUBJECT_PROGRAM to a subject program "
                             "(the grader hands one over as VL_SUBJECT_FD)");
    }();
    return fd;
}

}  // namespace

namespace {

/// Ends the calling thread's connection when the thread ends, so that the subject's thread
/// serving it ends too (a test that starts threads by the dozen leaves none behind). The
/// endpoint itself stays: nothing of the ended thread calls it again.
struct connection_of_thread {
    endpoint* end = nullptr;
    int socket = -1;
    void* shared = nullptr;
    ~connection_of_thread() {
        if (end != nullptr) end->close();
        if (socket >= 0) shutdown(socket, SHUT_RDWR);
        if (shared != nullptr) munmap(shared, shared_bytes);
    }
};
thread_local connection_of_thread this_thread_connection;

}  // namespace

endpoint& subject() {
    // One connection per thread of the judge, served by a thread of its own in the
    // subject: calls a test makes from several threads run there at once, as they would
    // in one process. Never destroyed: a stand-in held in static storage may release its
    // object after main, and the subject's thread ends when the judge does.
    thread_local endpoint* mine = nullptr;
    if (mine == nullptr) {
        static std::mutex handing_over;
        int ends[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
            throw protocol_error(std::string("socketpair: ") + std::strerror(errno));
        // Sealed at its size before the subject gets it: a subject that could shrink it would
        // make the judge's next read of a box fault (SIGBUS).
        const int memory = memfd_create("vl-connection", MFD_CLOEXEC | MFD_ALLOW_SEALING);
        void* shared = memory >= 0 && ftruncate(memory, static_cast<off_t>(shared_bytes)) == 0 &&
                               fcntl(memory, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_SEAL) == 0
                           ? map_shared(memory)
                           : nullptr;
        if (shared == nullptr) throw protocol_error(std::string("the judge cannot share memory: ") + std::strerror(errno));
        {
            const std::lock_guard<std::mutex> lock(handing_over);
            const bool sent = send_connection(control_fd(), {ends[1], memory});
            close(ends[1]);
            close(memory);
            if (!sent) {
                close(ends[0]);
                throw protocol_error("your code's process is not there to take a connection (it ended, or crashed)");
            }
        }
        // It serves the subject's calls on the judge's lent objects (judge_components.hh).
        mine = new endpoint(ends[0], shared, true, judge_handlers(), "your code's process");
        mine->on_release = released_by_subject;
        this_thread_connection.end = mine;
        this_thread_connection.socket = ends[0];
        this_thread_connection.shared = shared;
        // Kept where a leak checker sees it after the thread has gone.
        static std::vector<const endpoint*>* const every = new std::vector<const endpoint*>();
        const std::lock_guard<std::mutex> lock(handing_over);
        every->push_back(mine);
    }
    return *mine;
}

}  // namespace vl::remote
