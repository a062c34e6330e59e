//! Whether a window can be opened: on Linux and the other Unix desktops the viewer talks to an X
//! or Wayland server named by the environment; Windows and macOS always have their own display.

/// Whether the environment names no display server to open a window on (`DISPLAY`,
/// `WAYLAND_DISPLAY` and `WAYLAND_SOCKET` all unset or empty). Always `false` on Windows and
/// macOS.
pub fn display_server_missing() -> bool {
    if cfg!(any(windows, target_os = "macos")) {
        return false;
    }
    let set = |name| std::env::var_os(name).is_some_and(|value| !value.is_empty());
    !(set("DISPLAY") || set("WAYLAND_DISPLAY") || set("WAYLAND_SOCKET"))
}
