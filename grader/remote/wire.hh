#pragma once
/// \file
/// \brief What crosses between the judge and the subject: a message is a run of values,
/// written in order by a `message_writer` and read back in the same order by a
/// `message_reader`.
///
/// Values are written as their bytes (both ends are the same program build on the same
/// machine), so a double or a matrix crosses bit for bit. The reader trusts nothing it
/// reads: every value is bounds-checked against the message, every length against a
/// limit, and a message that is too short, too long or malformed throws protocol_error.
/// Only trivially copyable types made of numbers cross as bytes: any bit pattern is a
/// valid value of them (a NaN, a huge number), never a pointer.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vl::remote {

/// \brief The other end broke the protocol: it sent a message that is not an answer to
/// the call made, is malformed, or ended the connection.
class protocol_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The largest string that crosses (an exception's message, a name).
inline constexpr std::size_t max_string_bytes = 64 << 10;

/// \brief Builds one message.
class message_writer {
public:
    template <class T>
    message_writer& put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
        append(&value, sizeof(T));
        return *this;
    }
    message_writer& put_string(std::string_view s) {
        put(static_cast<std::uint32_t>(s.size()));
        append(s.data(), s.size());
        return *this;
    }
    template <class T>
    message_writer& put_vector(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
        put(static_cast<std::uint32_t>(v.size()));
        append(v.data(), v.size() * sizeof(T));
        return *this;
    }
    /// Appends `n` bytes from `from`.
    void append(const void* from, std::size_t n) {
        if (n == 0) return;
        const std::size_t at = bytes_.size();
        bytes_.resize(at + n);
        std::memcpy(bytes_.data() + at, from, n);
    }
    const std::vector<char>& bytes() const { return bytes_; }
    std::vector<char>& bytes() { return bytes_; }

private:
    std::vector<char> bytes_;
};

/// \brief Reads one message, checking every step.
class message_reader {
public:
    message_reader() = default;
    explicit message_reader(std::vector<char> bytes) : bytes_(std::move(bytes)) {}

    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    std::string get_string(std::size_t max_bytes = max_string_bytes) {
        const std::size_t n = get<std::uint32_t>();
        if (n > max_bytes) throw protocol_error("a string of " + std::to_string(n) + " bytes, more than the " +
                                                std::to_string(max_bytes) + " allowed");
        need(n);
        std::string s(bytes_.data() + at_, n);
        at_ += n;
        return s;
    }
    template <class T>
    std::vector<T> get_vector(std::size_t max_count) {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values cross as bytes");
        const std::size_t n = get<std::uint32_t>();
        if (n > max_count) throw protocol_error("a list of " + std::to_string(n) + " values, more than the " +
                                                std::to_string(max_count) + " expected");
        need(n * sizeof(T));
        std::vector<T> v(n);
        if (n != 0) std::memcpy(v.data(), bytes_.data() + at_, n * sizeof(T));
        at_ += n * sizeof(T);
        return v;
    }
    /// Throws unless every byte was read: a message with more in it than its kind holds is
    /// as malformed as one with less.
    void finish() const {
        if (at_ != bytes_.size())
            throw protocol_error("a message " + std::to_string(bytes_.size() - at_) + " bytes longer than its kind");
    }

private:
    void need(std::size_t n) const {
        if (n > bytes_.size() - at_) throw protocol_error("a message shorter than its kind");
    }
    std::vector<char> bytes_;
    std::size_t at_ = 0;
};

}  // namespace vl::remote
