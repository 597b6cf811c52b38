#pragma once
/// \file
/// \brief One end of the connection between the judge (the hidden tests, trusted) and the
/// subject (the student's code, in its sandbox): calls that cross it, answers that come
/// back, and calls back the other way.
///
/// A message is a frame: its length (4 bytes, at most max_message_bytes), its kind
/// (call, result, thrown, release), the number of the call it belongs to, then its body.
/// A call carries an operation number and its arguments; the other end answers with
/// a result or with the exception the call threw. While an end waits for its answer it
/// serves the calls the other end makes meanwhile (a composite in the subject asking a
/// child that lives in the judge), so calls nest in both directions.
///
/// The judge trusts nothing that arrives: an answer to another call than the one
/// waiting, a frame too large or malformed, or the end of the connection breaks the
/// endpoint for good, and the call (and every later one) throws protocol_error, saying
/// what happened in the student's terms. That failure is the submission's: the test
/// that made the call fails.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "wire.hh"

namespace vl::remote {

/// The descriptor on which the judge and the subject find their control connection when
/// the grader starts them: the judge hands the subject one connection per thread of its
/// own over it (connections.hh).
inline constexpr int channel_fd = 5;

/// The largest frame either end accepts: an answer that claims more is a flood.
inline constexpr std::uint32_t max_message_bytes = 16u << 20;

/// An operation's number: each stage's calls file (calls_NN.hh) lists its own.
using op_id = std::uint16_t;

/// A handle: the subject's name for an object it made; 0 is no object (nullptr).
using handle = std::uint64_t;

/// Serves one call: reads the arguments, does the work, writes the result. An exception
/// it throws crosses as the call's answer (see exceptions.hh).
using handler = std::function<void(message_reader& args, message_writer& result)>;

/// \brief One end of the connection.
class endpoint {
public:
    /// `fd`: a connected stream socket (the endpoint does not own it). `handlers[op]`
    /// serves the calls the other end makes; `peer` names the other end in messages.
    endpoint(int fd, std::vector<handler> handlers, std::string peer);

    /// Calls `op` at the other end with `args` and returns its result to read. `what`
    /// names the call for a student ("inverse", "the camera's primary_ray"). Rethrows
    /// the exception the call threw there; throws protocol_error when the other end
    /// broke the protocol or ended.
    message_reader call(op_id op, const message_writer& args, const char* what);

    /// Tells the other end that the object `h` is no longer used (no answer is awaited;
    /// never throws: a destructor calls it).
    void release(handle h) noexcept;

    /// Serves calls until the other end closes the connection (returns), or breaks the
    /// protocol (throws protocol_error). The subject's main loop.
    void serve();

    /// Called for each release that arrives.
    std::function<void(handle)> on_release;

private:
    enum class kind : std::uint8_t { call = 1, result = 2, thrown = 3, release = 4 };
    struct frame {
        kind k{};
        std::uint64_t number = 0;
        message_reader body;
    };

    /// The next frame; false at the end of the connection.
    bool receive(frame& f);
    void send(kind k, std::uint64_t number, const std::vector<char>& body);
    void serve_call(frame& f);
    [[noreturn]] void broken(const std::string& why);
    void read_exactly(char* into, std::size_t n, bool& ended);

    int fd_;
    std::vector<handler> handlers_;
    std::string peer_;
    std::uint64_t next_call_ = 0;
    std::string broken_;  ///< why the endpoint is broken, or ""
    std::vector<char> in_;  ///< read ahead
    std::size_t in_at_ = 0;
};

}  // namespace vl::remote
