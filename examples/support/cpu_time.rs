//! CPU time of the calling thread, for timing on a shared machine.
//!
//! Wall-clock time counts the time other processes hold the core; on a busy
//! 2-core machine that can double a measurement. The kernel's per-thread
//! run time (`/proc/thread-self/schedstat`, first field, nanoseconds) only
//! grows while this thread runs. It is updated at scheduler ticks (a few
//! milliseconds), so it is only meaningful summed over blocks of work that
//! take much longer than a tick: the examples use it for totals over many
//! steps and report wall-clock medians for single steps.
//!
//! Linux only; elsewhere `thread_cpu_ns` returns `None` and the examples
//! fall back to wall-clock time.

/// Nanoseconds this thread has run on a CPU so far, if the platform says.
pub fn thread_cpu_ns() -> Option<u64> {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}
