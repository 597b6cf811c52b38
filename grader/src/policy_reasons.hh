#pragma once
/// \file
/// \brief Why the policy (policy.hh) refuses something: the words a policy_finding's
/// reason gives, shared by its symbol checks (policy_symbols.cc) and its source checks
/// (policy.cc), so one kind of deed is always named the same.

namespace vl::grader::policy_reasons {

inline constexpr const char* files = "opens or writes files";
inline constexpr const char* ends = "ends the process";
inline constexpr const char* spawns = "starts processes";
inline constexpr const char* signals = "sends signals";
inline constexpr const char* network = "uses the network";
inline constexpr const char* loads = "loads code at run time";
inline constexpr const char* maps = "maps memory";
inline constexpr const char* syscalls = "makes raw system calls";
inline constexpr const char* assembly = "uses inline assembly";
inline constexpr const char* early = "runs code before main";
inline constexpr const char* counters = "tampers with the intersection counters";
inline constexpr const char* harness = "reaches into the test framework";
inline constexpr const char* replaces = "replaces a symbol of the framework or the runtime";
inline constexpr const char* environment = "reads or changes the environment";
inline constexpr const char* reference = "calls the reference solution";

}  // namespace vl::grader::policy_reasons
