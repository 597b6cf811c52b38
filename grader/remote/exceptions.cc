#include "exceptions.hh"

#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>

#include "vl/error.hh"
#include "vl/not_implemented.hh"

namespace vl::remote {

namespace {

/// The kinds that cross, most derived first: the first that matches names the exception.
enum class exception_kind : std::uint8_t {
    not_implemented = 1,
    usage_error,
    file_error,
    invalid_argument,
    domain_error,
    length_error,
    out_of_range,
    logic_error,
    range_error,
    overflow_error,
    underflow_error,
    runtime_error,
    bad_alloc,
    other_std,
    foreign,
};

/// The message, cut to what a report shows (a student's message is no channel for bulk).
std::string cut(const char* what) {
    std::string s = what != nullptr ? what : "";
    if (s.size() > 4000) s = s.substr(0, 4000) + " [...]";
    return s;
}

}  // namespace

void write_exception(std::exception_ptr e, message_writer& out) {
    exception_kind k = exception_kind::foreign;
    std::string what;
    try {
        std::rethrow_exception(e);
    } catch (const not_implemented_error& x) {
        k = exception_kind::not_implemented, what = cut(x.what());
    } catch (const usage_error& x) {
        k = exception_kind::usage_error, what = cut(x.what());
    } catch (const file_error& x) {
        k = exception_kind::file_error, what = cut(x.what());
    } catch (const std::invalid_argument& x) {
        k = exception_kind::invalid_argument, what = cut(x.what());
    } catch (const std::domain_error& x) {
        k = exception_kind::domain_error, what = cut(x.what());
    } catch (const std::length_error& x) {
        k = exception_kind::length_error, what = cut(x.what());
    } catch (const std::out_of_range& x) {
        k = exception_kind::out_of_range, what = cut(x.what());
    } catch (const std::logic_error& x) {
        k = exception_kind::logic_error, what = cut(x.what());
    } catch (const std::range_error& x) {
        k = exception_kind::range_error, what = cut(x.what());
    } catch (const std::overflow_error& x) {
        k = exception_kind::overflow_error, what = cut(x.what());
    } catch (const std::underflow_error& x) {
        k = exception_kind::underflow_error, what = cut(x.what());
    } catch (const std::runtime_error& x) {
        k = exception_kind::runtime_error, what = cut(x.what());
    } catch (const std::bad_alloc& x) {
        k = exception_kind::bad_alloc, what = cut(x.what());
    } catch (const std::exception& x) {
        k = exception_kind::other_std, what = cut(x.what());
    } catch (...) {
        k = exception_kind::foreign;
    }
    out.put(k).put_string(what);
}

void throw_exception(message_reader& in) {
    const auto k = in.get<exception_kind>();
    const std::string what = in.get_string();
    in.finish();
    switch (k) {
        // A stub's "not yet implemented: FUNCTION (FILE:LINE)" keeps its words; its type is
        // made from a source location, so it crosses as the logic_error it derives from.
        case exception_kind::not_implemented: throw std::logic_error(what);
        case exception_kind::usage_error: throw usage_error(what);
        case exception_kind::file_error: throw file_error(what);
        case exception_kind::invalid_argument: throw std::invalid_argument(what);
        case exception_kind::domain_error: throw std::domain_error(what);
        case exception_kind::length_error: throw std::length_error(what);
        case exception_kind::out_of_range: throw std::out_of_range(what);
        case exception_kind::logic_error: throw std::logic_error(what);
        case exception_kind::range_error: throw std::range_error(what);
        case exception_kind::overflow_error: throw std::overflow_error(what);
        case exception_kind::underflow_error: throw std::underflow_error(what);
        case exception_kind::runtime_error: throw std::runtime_error(what);
        case exception_kind::bad_alloc: throw std::bad_alloc();
        case exception_kind::other_std: throw std::runtime_error(what);
        case exception_kind::foreign: throw foreign_exception{};
    }
    throw protocol_error("an exception of no known kind");
}

}  // namespace vl::remote
