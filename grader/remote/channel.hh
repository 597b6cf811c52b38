#pragma once
/// \file
/// \brief One end of a connection between the judge (the hidden tests, trusted) and the
/// subject (the student's code, in its sandbox): calls that cross it, answers that come
/// back, and calls back the other way.
///
/// A message is a frame: its kind (call, result, thrown, release), the number of the call
/// it belongs to, then its body. A box carries one frame or more, each after its length:
/// a release awaits no answer and goes with the next frame. A call carries an operation number and its arguments;
/// the other end answers with a result or with the exception the call threw. While an
/// end waits for its answer it serves the calls the other end makes meanwhile (a
/// composite in the subject asking a child that lives in the judge), so calls nest in
/// both directions.
///
/// Frames cross through memory the two processes share (a `shared_boxes`: one box each
/// way), because a test may make millions of calls and a round trip through the kernel
/// costs microseconds: an end that waits looks at the box for a while before it sleeps
/// (a futex), and the writer wakes it. A socket beside the boxes carries nothing; its
/// end is how each side learns that the other has gone.
///
/// The judge trusts nothing that arrives: it copies a frame out of the box before it
/// reads it, and an answer to another call than the one waiting, a frame too large or
/// malformed, or the other end's going breaks the endpoint for good: the call (and every
/// later one) throws protocol_error, saying what happened in the student's terms. That
/// failure is the submission's: the test that made the call fails.
#include <atomic>
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

/// The largest frame either end sends or accepts: an answer that claims more is a flood.
inline constexpr std::uint32_t max_message_bytes = 16u << 20;

/// An operation's number: each stage's calls file (calls_NN.hh) lists its own.
using op_id = std::uint16_t;

/// A handle: the subject's name for an object it made; 0 is no object (nullptr).
using handle = std::uint64_t;

/// Serves one call: reads the arguments, does the work, writes the result. An exception
/// it throws crosses as the call's answer (see exceptions.hh).
using handler = std::function<void(message_reader& args, message_writer& result)>;

/// \brief One direction's box in the shared memory: a frame and the count of frames
/// written so far (the futex word the reader sleeps on).
struct alignas(64) shared_box {
    std::atomic<std::uint32_t> written{0};   ///< frames written; changes once per frame
    std::atomic<std::uint32_t> sleeping{0};  ///< the reader sleeps (wake it)
    std::atomic<std::uint32_t> length{0};    ///< the bytes of its frames
    std::atomic<std::uint32_t> taken{0};     ///< frames the reader has copied out
    std::atomic<std::uint32_t> closed{0};    ///< the writer has gone for good
    char pad[44];
    char bytes[max_message_bytes];
};

/// The size of the memory a connection shares: one box each way.
inline constexpr std::size_t shared_bytes = 2 * sizeof(shared_box);

/// \brief One end of a connection.
class endpoint {
public:
    /// `socket`: the connection's socket (the endpoint does not own it); `shared`: its
    /// shared memory (shared_bytes); `judge_side`: which box this end writes.
    /// `handlers[op]` serves the calls the other end makes; `peer` names the other end
    /// in messages.
    endpoint(int socket, void* shared, bool judge_side, std::vector<handler> handlers, std::string peer);

    /// Calls `op` at the other end with `args` and returns its result to read. `what`
    /// names the call for a student ("inverse", "the camera's primary_ray"). Rethrows
    /// the exception the call threw there; throws protocol_error when the other end
    /// broke the protocol or ended.
    message_reader call(op_id op, const message_writer& args, const char* what);

    /// Tells the other end that the object `h` is no longer used (no answer is awaited;
    /// never throws: a destructor calls it).
    void release(handle h) noexcept;

    /// Calls `op` at the other end with `args` and awaits no answer: the frame goes with
    /// the next one sent (as a release does), and the other end serves it before any
    /// frame sent after it. If it throws there, the other end's endpoint breaks for good,
    /// saying what the call was: a post is for calls that cannot fail when the caller
    /// keeps the contract (the subject's make_sphere(), checked here first).
    void post(op_id op, const message_writer& args);

    /// Serves calls until the other end goes (returns), or breaks the protocol (throws
    /// protocol_error). The subject's main loop.
    void serve();

    /// Tells the other end that this end is gone (it wakes if it sleeps); nothing is sent
    /// after. Never throws.
    void close() noexcept;

    /// Called for each release that arrives.
    std::function<void(handle)> on_release;

private:
    enum class kind : std::uint8_t { call = 1, result = 2, thrown = 3, release = 4, post = 5 };
    struct frame {
        kind k{};
        std::uint64_t number = 0;
        message_reader body;
    };

    /// The next frame; false when the other end has gone.
    bool receive(frame& f);
    /// Sends what is queued and this frame, in one box.
    void send(kind k, std::uint64_t number, const std::vector<char>& body);
    /// Queues this frame to go with the next one sent (a box that is full goes first);
    /// throws protocol_error for a frame too large to cross.
    void enqueue(kind k, std::uint64_t number, const std::vector<char>& body);
    /// Adds a frame to what the next send() puts in the box.
    void queue(kind k, std::uint64_t number, const std::vector<char>& body);
    /// Puts what is queued in the box.
    void flush();
    void serve_call(frame& f);
    /// Serves a post: its answer is dropped; its exception breaks the endpoint.
    void serve_post(frame& f);
    [[noreturn]] void broken(const std::string& why);
    /// Waits until the incoming box holds a frame not yet read; false when the other end
    /// has gone.
    bool wait_for_frame();
    /// True while the other end's side of the socket is open.
    bool peer_there();
    /// Waits until the reader has copied out the last frame written to the outgoing box.
    void wait_until_taken();

    int socket_;
    shared_box* out_;
    shared_box* in_;
    std::uint32_t read_ = 0;      ///< boxes read from the incoming side
    std::vector<char> arrived_;   ///< the last box read, copied out: frames, each after its length
    std::size_t arrived_at_ = 0;  ///< how far they have been read
    std::vector<char> queued_;    ///< frames to go with the next one sent
    std::vector<handler> handlers_;
    std::string peer_;
    std::uint64_t next_call_ = 0;
    std::string broken_;  ///< why the endpoint is broken, or ""
};

}  // namespace vl::remote
