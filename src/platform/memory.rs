//! What the operating system tells about memory (Linux `/proc`): how much the program may still
//! use, and how much it has used at most. Elsewhere (Windows, macOS), or where `/proc` cannot be
//! read, both are unknown and no request is refused for memory beforehand.

/// Bytes the program may still allocate: the smallest of the memory available on the machine
/// (`MemAvailable`) and what the address-space and data-size limits leave (`ulimit -v`,
/// `ulimit -d`). `None` when none of them is known.
pub fn available_memory_bytes() -> Option<u64> {
    if !cfg!(target_os = "linux") {
        return None;
    }
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok();
    let available = meminfo
        .as_deref()
        .and_then(|m| kib_field(m, "MemAvailable:"));
    let limits = std::fs::read_to_string("/proc/self/limits").ok();
    let status = std::fs::read_to_string("/proc/self/status").ok();
    let left = |limit_name: &str, used_field: &str| -> Option<u64> {
        let limit = limits.as_deref().and_then(|l| soft_limit(l, limit_name))?;
        let used = status.as_deref().and_then(|s| kib_field(s, used_field))?;
        Some(limit.saturating_sub(used))
    };
    [
        available,
        left("Max address space", "VmSize:"),
        left("Max data size", "VmData:"),
    ]
    .into_iter()
    .flatten()
    .min()
}

/// The program's peak resident memory so far (`VmHWM`), in bytes.
pub fn peak_memory_bytes() -> Option<u64> {
    if !cfg!(target_os = "linux") {
        return None;
    }
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    kib_field(&status, "VmHWM:")
}

/// A `name:   1234 kB` field, in bytes.
fn kib_field(text: &str, name: &str) -> Option<u64> {
    let line = text.lines().find(|line| line.starts_with(name))?;
    let kib: u64 = line[name.len()..].split_whitespace().next()?.parse().ok()?;
    Some(kib * 1024)
}

/// The soft limit of a `/proc/self/limits` row, in bytes; `None` when unlimited.
fn soft_limit(text: &str, name: &str) -> Option<u64> {
    let line = text.lines().find(|line| line.starts_with(name))?;
    line[name.len()..].split_whitespace().next()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_and_limits_are_read_in_bytes() {
        let status = "Name:\traytracer\nVmHWM:\t   20480 kB\nVmSize:\t  1024 kB\n";
        assert_eq!(kib_field(status, "VmHWM:"), Some(20_971_520));
        assert_eq!(kib_field(status, "VmData:"), None);
        let limits = "Limit                     Soft Limit           Hard Limit           Units\n\
                      Max data size             unlimited            unlimited            bytes\n\
                      Max address space         600000000            600000000            bytes\n";
        assert_eq!(soft_limit(limits, "Max address space"), Some(600_000_000));
        assert_eq!(soft_limit(limits, "Max data size"), None);
    }
}
