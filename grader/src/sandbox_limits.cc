// The resource limits a sandboxed child sets on itself between fork and exec (run_limits,
// sandbox.hh): CPU time, address space, file size, open files, no core dumps. The process
// limit is prlimit's, on bubblewrap's command line (sandbox_bubblewrap.cc).
#include <sys/resource.h>

#include "sandbox_parts.hh"

namespace vl::grader::sandbox_parts {

namespace {

void set_limit(int resource, rlim_t value) {
    const rlimit r{value, value};
    setrlimit(resource, &r);
}

}  // namespace

void set_limits(const run_limits& l, const sandbox_capabilities& caps) {
    const double cpu = l.cpu_seconds > 0 ? l.cpu_seconds : l.wall_seconds + 1;
    set_limit(RLIMIT_CPU, static_cast<rlim_t>(cpu + 0.999));
    if (caps.address_limit && l.memory_bytes > 0) set_limit(RLIMIT_AS, l.memory_bytes);
    set_limit(RLIMIT_FSIZE, l.file_bytes);
    set_limit(RLIMIT_NOFILE, 256);
    set_limit(RLIMIT_CORE, 0);
}

}  // namespace vl::grader::sandbox_parts
