// The subject's main(): take each connection the judge hands over on the control
// connection (one per thread of the judge that calls) and serve it on a thread of its
// own, until the judge closes the control connection and every connection has ended.
// Exit 0 then; 3 when the judge's messages made no sense.
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <iostream>
#include <system_error>
#include <thread>
#include <vector>

#include "connections.hh"
#include "subject.hh"

namespace vl::remote {
endpoint*& judge_here() {
    thread_local endpoint* here = nullptr;
    return here;
}
}  // namespace vl::remote

int main() {
    using namespace vl::remote;
    const std::vector<handler> handlers = subject_handlers();
    std::atomic<bool> broken = false;
    std::vector<std::thread> served;
    for (connection_fds c; (c = receive_connection(channel_fd)).socket >= 0;) {
        void* shared = map_shared(c.memory);
        close(c.memory);
        if (shared == nullptr) {
            std::cerr << "subject: cannot map a connection's memory\n";
            return 3;
        }
        try {
            served.emplace_back([c, shared, &handlers, &broken] {
                {
                    endpoint judge(c.socket, shared, false, handlers, "the judge");
                    judge.on_release = release_object;
                    judge_here() = &judge;
                    try {
                        judge.serve();
                    } catch (const protocol_error& e) {
                        std::cerr << "subject: " << e.what() << "\n";
                        broken = true;
                    }
                    judge_here() = nullptr;
                }
                munmap(shared, shared_bytes);
                close(c.socket);
            });
        } catch (const std::system_error& e) {
            // No thread to serve it (the sandbox's limit on threads): the judge's call on
            // this connection finds the subject gone, and its check fails saying so.
            std::cerr << "subject: cannot start a thread to serve a connection: " << e.what() << "\n";
            munmap(shared, shared_bytes);
            close(c.socket);
        }
    }
    for (std::thread& t : served) t.join();
    return broken ? 3 : 0;
}
