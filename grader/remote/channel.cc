#include "channel.hh"

#include <sched.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>

#include "exceptions.hh"

namespace vl::remote {

namespace {

/// Bytes before a frame's body: its length, its kind and its call's number.
constexpr std::size_t header_bytes = sizeof(std::uint32_t) + sizeof(std::uint8_t) + sizeof(std::uint64_t);

/// How long a receive looks for an answer before it sleeps (see wait_briefly).
const int spin_microseconds = [] {
    const char* s = std::getenv("VL_REMOTE_SPIN_US");
    return s != nullptr && *s != '\0' ? std::atoi(s) : 50;
}();

/// An answer usually comes within microseconds, sooner than a sleeping process is woken
/// (tens of microseconds here): so look for it for a while before sleeping. The bytes
/// read, or -1 when none came in time.
ssize_t wait_briefly(int fd, std::vector<char>& into) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(spin_microseconds);
    do {
        for (int k = 0; k < 64; ++k) {
            const ssize_t got = ::recv(fd, into.data(), into.size(), MSG_DONTWAIT);
            if (got >= 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return got < 0 ? 0 : got;
        }
        sched_yield();  // the other end may be waiting for this core
    } while (std::chrono::steady_clock::now() < until);
    return -1;
}

}  // namespace

endpoint::endpoint(int fd, std::vector<handler> handlers, std::string peer)
    : fd_(fd), handlers_(std::move(handlers)), peer_(std::move(peer)) {}

void endpoint::broken(const std::string& why) {
    if (broken_.empty()) broken_ = why;
    throw protocol_error(broken_);
}

void endpoint::send(kind k, std::uint64_t number, const std::vector<char>& body) {
    if (body.size() + header_bytes - sizeof(std::uint32_t) > max_message_bytes)
        throw protocol_error("a message of " + std::to_string(body.size()) + " bytes is too large to send");
    message_writer w;
    w.put(static_cast<std::uint32_t>(body.size() + header_bytes - sizeof(std::uint32_t))).put(k).put(number);
    std::vector<char>& bytes = w.bytes();
    bytes.insert(bytes.end(), body.begin(), body.end());
    std::size_t at = 0;
    while (at < bytes.size()) {
        // send() with MSG_NOSIGNAL: an end that has gone is an error here, never a SIGPIPE.
        const ssize_t n = ::send(fd_, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) broken(peer_ + " closed the connection (" + std::strerror(errno) + ")");
        at += static_cast<std::size_t>(n);
    }
}

void endpoint::read_exactly(char* into, std::size_t n, bool& ended) {
    while (n > 0) {
        if (in_at_ == in_.size()) {
            in_.resize(64 << 10);
            in_at_ = 0;
            ssize_t got = wait_briefly(fd_, in_);
            if (got < 0) {
                do got = ::read(fd_, in_.data(), in_.size());
                while (got < 0 && errno == EINTR);
            }
            in_.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
            if (got <= 0) {
                ended = true;
                return;
            }
        }
        const std::size_t take = std::min(n, in_.size() - in_at_);
        std::memcpy(into, in_.data() + in_at_, take);
        in_at_ += take;
        into += take;
        n -= take;
    }
}

bool endpoint::receive(frame& f) {
    char header[header_bytes];
    bool ended = false;
    read_exactly(header, sizeof header, ended);
    if (ended) return false;
    std::uint32_t length;
    std::memcpy(&length, header, sizeof length);
    if (length > max_message_bytes || length < header_bytes - sizeof length)
        broken(peer_ + " sent a message of " + std::to_string(length) + " bytes (at most " +
               std::to_string(max_message_bytes) + " are read)");
    std::memcpy(&f.k, header + sizeof length, sizeof f.k);
    std::memcpy(&f.number, header + sizeof length + sizeof f.k, sizeof f.number);
    std::vector<char> body(length - (header_bytes - sizeof length));
    read_exactly(body.data(), body.size(), ended);
    if (ended) broken(peer_ + " ended in the middle of a message");
    f.body = message_reader(std::move(body));
    return true;
}

void endpoint::serve_call(frame& f) {
    message_writer result;
    kind answer = kind::result;
    try {
        const auto op = f.body.get<op_id>();
        if (op >= handlers_.size() || !handlers_[op]) throw protocol_error("a call of unknown operation " + std::to_string(op));
        handlers_[op](f.body, result);
    } catch (...) {
        result = message_writer();
        write_exception(std::current_exception(), result);
        answer = kind::thrown;
    }
    send(answer, f.number, result.bytes());
}

message_reader endpoint::call(op_id op, const message_writer& args, const char* what) {
    if (!broken_.empty()) throw protocol_error(broken_);
    const std::uint64_t number = ++next_call_;
    message_writer w;
    w.put(op);
    std::vector<char> body = w.bytes();
    body.insert(body.end(), args.bytes().begin(), args.bytes().end());
    send(kind::call, number, body);
    for (;;) {
        frame f;
        if (!receive(f))
            broken(peer_ + " ended (it crashed or ended itself) while answering " + what);
        switch (f.k) {
            case kind::call: serve_call(f); break;
            case kind::release:
                if (on_release) on_release(f.body.get<handle>());
                break;
            case kind::result:
            case kind::thrown:
                if (f.number != number)
                    broken(peer_ + " answered call " + std::to_string(f.number) + " while call " +
                           std::to_string(number) + " (" + what + ") was waiting: answers out of order");
                if (f.k == kind::thrown) throw_exception(f.body);
                return std::move(f.body);
            default: broken(peer_ + " sent a message of unknown kind " + std::to_string(static_cast<int>(f.k)));
        }
    }
}

void endpoint::release(handle h) noexcept {
    if (!broken_.empty() || h == 0) return;
    try {
        message_writer w;
        w.put(h);
        send(kind::release, 0, w.bytes());
    } catch (...) {
        // A broken connection: the next call says so.
    }
}

void endpoint::serve() {
    for (;;) {
        frame f;
        if (!receive(f)) return;
        switch (f.k) {
            case kind::call: serve_call(f); break;
            case kind::release:
                if (on_release) on_release(f.body.get<handle>());
                break;
            default:
                broken(peer_ + " sent an answer (kind " + std::to_string(static_cast<int>(f.k)) +
                       ") while no call was waiting");
        }
    }
}

}  // namespace vl::remote
