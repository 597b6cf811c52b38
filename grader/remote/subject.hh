#pragma once
/// \file
/// \brief The subject: the program that holds the student's code and serves the judge's
/// calls, and nothing else (no test, no expected value, no verdict). Each stage's
/// subject_NN.cc defines the two functions below; subject_main.cc is its main().
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "channel.hh"

namespace vl::remote {

/// The handlers of the stage's calls (calls_NN.hh), indexed by operation.
std::vector<handler> subject_handlers();

/// Drops the object `h`, whatever its kind (the judge's stand-in for it has gone).
void release_object(handle h);

/// The judge's end of the connection this thread serves: where a lent object's calls
/// go back (calls_components.hh). nullptr on a thread that serves none (one the student's
/// code started).
endpoint*& judge_here();

/// The next handle: unique among every kind of object, never 0.
inline handle next_handle() {
    static std::atomic<handle> last = 0;
    return ++last;
}

/// \brief The objects of one kind that the student's code made, by handle. The judge's
/// threads reach them through threads of their own here, so the table has a lock; the
/// objects themselves are used as the contract says (at once where it allows).
template <class T>
class objects {
public:
    /// Keeps `object` and returns its handle; nullptr is handle 0.
    template <class U>
    handle add(std::unique_ptr<U> object) {
        if (!object) return 0;
        const handle h = next_handle();
        const std::lock_guard<std::mutex> lock(mutex_);
        by_handle_.emplace(h, std::move(object));
        return h;
    }
    /// The object `h`; throws protocol_error for a handle of no object of this kind.
    T& at(handle h) const {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto it = by_handle_.find(h);
        if (it == by_handle_.end()) throw protocol_error("no object has the handle " + std::to_string(h));
        return *it->second;
    }
    void erase(handle h) {
        std::unique_ptr<T> gone;  // destroyed outside the lock: its destructor is the student's
        const std::lock_guard<std::mutex> lock(mutex_);
        if (const auto it = by_handle_.find(h); it != by_handle_.end()) {
            gone = std::move(it->second);
            by_handle_.erase(it);
        }
    }

private:
    mutable std::mutex mutex_;
    std::map<handle, std::unique_ptr<T>> by_handle_;
};

}  // namespace vl::remote
