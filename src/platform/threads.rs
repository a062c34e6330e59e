//! Lowering the priority of threads that another library started, found by their names (Linux:
//! `/proc/self/task`, and `setpriority` through rustix). Elsewhere threads are not listed by
//! name, and nothing is changed.

/// The largest nice value (the lowest priority).
pub const MAX_NICE: i32 = 19;

/// Raises by `raise` (at most to [`MAX_NICE`]) the nice value of this process's threads whose
/// names start with `prefix`; returns how many were raised. A thread that ends meanwhile, or
/// that the system does not let change, is not counted. Always 0 outside Linux.
#[cfg(target_os = "linux")]
pub fn lower_threads_named(prefix: &str, raise: i32) -> usize {
    use rustix::process::{Pid, getpriority_process, setpriority_process};
    let Ok(tasks) = std::fs::read_dir("/proc/self/task") else {
        return 0;
    };
    let mut lowered = 0;
    for task in tasks.flatten() {
        let is_named = std::fs::read_to_string(task.path().join("comm"))
            .is_ok_and(|name| name.starts_with(prefix));
        let thread = task
            .file_name()
            .to_str()
            .and_then(|id| id.parse().ok())
            .and_then(Pid::from_raw);
        let (true, Some(thread)) = (is_named, thread) else {
            continue;
        };
        // On Linux the nice value belongs to the thread the id names.
        let Ok(nice) = getpriority_process(Some(thread)) else {
            continue;
        };
        if setpriority_process(Some(thread), (nice + raise).min(MAX_NICE)).is_ok() {
            lowered += 1;
        }
    }
    lowered
}

/// Elsewhere threads are not known by name: none is changed.
#[cfg(not(target_os = "linux"))]
pub fn lower_threads_named(_prefix: &str, _raise: i32) -> usize {
    0
}
